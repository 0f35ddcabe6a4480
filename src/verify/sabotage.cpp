#include "verify/sabotage.hpp"

#include "frontend/demote.hpp"

namespace doublet::verify {

std::string_view to_string(Sabotage s) {
  switch (s) {
    case Sabotage::DropLo: return "drop-lo";
    case Sabotage::DropGuard: return "drop-guard";
    default: return "none";
  }
}

std::optional<Sabotage> parse_sabotage(std::string_view s) {
  if (s == "none") return Sabotage::None;
  if (s == "drop-lo") return Sabotage::DropLo;
  if (s == "drop-guard") return Sabotage::DropGuard;
  return std::nullopt;
}

void apply_sabotage(Sabotage s, std::string* source, Options* options) {
  if (s == Sabotage::DropLo) *source = frontend::demote_doubles(*source);
  if (s == Sabotage::DropGuard) options->guard = GuardKind::None;
}

}  // namespace doublet::verify
