#include "verify/sabotage.hpp"

#include "frontend/demote.hpp"

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
  // rules/exact.glsl's round-and-pack: on an exact tie the last kept bit is cleared (to even).
  const std::string tie = "if (roundBits == 0x200u) sig.x &= 0xFFFFFFFEu;";
  const size_t at = lowered->find(tie);
  if (at == std::string::npos) {
    // The same line as the WGSL printer spells it (target wgsl, verify --backend webgpu).
    const std::string wgsl_tie = "if ((roundBits == 512u)) {\n    sig_v[0i] &= 4294967294u;\n  }";
    const size_t w = lowered->find(wgsl_tie);
    if (w == std::string::npos) return false;
    lowered->erase(w, wgsl_tie.size());
    return true;
  }
  lowered->erase(at, tie.size());
  return true;
}

}  // namespace doublet::verify
