#include "verify/sabotage.hpp"

#include "frontend/demote.hpp"

#include <string>
#include <utility>

namespace doublet::verify {

std::string_view to_string(Sabotage s) {
  switch (s) {
    case Sabotage::DropLo: return "drop-lo";
    case Sabotage::DropGuard: return "drop-guard";
    case Sabotage::TiesAway: return "ties-away";
    default: return "none";
  }
}

std::optional<Sabotage> parse_sabotage(std::string_view s) {
  if (s == "none") return Sabotage::None;
  if (s == "drop-lo") return Sabotage::DropLo;
  if (s == "drop-guard") return Sabotage::DropGuard;
  if (s == "ties-away") return Sabotage::TiesAway;
  return std::nullopt;
}

void apply_sabotage(Sabotage s, std::string* source, Options* options) {
  if (s == Sabotage::DropLo) *source = frontend::demote_doubles(*source);
  if (s == Sabotage::DropGuard) options->guard = GuardKind::None;
}

bool apply_output_sabotage(Sabotage s, std::string* lowered) {
  if (s != Sabotage::TiesAway) return true;
  // rules/exact.glsl's round-and-pack: on an exact tie the mask clears the last kept bit (to
  // even); the sabotage keeps every bit (ties away from zero).
  const std::pair<std::string, std::string> edits[] = {
      {"uint tie = roundBits == 0x200u ? 0xFFFFFFFEu : 0xFFFFFFFFu;", "uint tie = 0xFFFFFFFFu;"},
      // The same line as the WGSL printer spells it (target wgsl, verify --backend webgpu).
      {"var tie: u32 = select(4294967295u, 4294967294u, (roundBits == 512u));", "var tie: u32 = 4294967295u;"}};
  for (const auto& [from, to] : edits) {
    const size_t at = lowered->find(from);
    if (at == std::string::npos) continue;
    lowered->replace(at, from.size(), to);
    return true;
  }
  return false;
}

}  // namespace doublet::verify
