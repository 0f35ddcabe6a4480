#include "verify/sabotage.hpp"

#include <regex>

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

std::string demote_doubles(std::string_view source) {
  // Comments keep their text; everything else is rewritten. Good enough for a sabotage: a shader
  // whose demotion does not compile is reported like any other lowering failure.
  static const std::regex token(R"((//[^\n]*|/\*[\s\S]*?\*/)|\bdouble\b|\bdvec([234])\b|([0-9.][0-9.eE+\-]*)(lf|LF)\b)");
  std::string out;
  std::string s(source);
  auto last = s.cbegin();
  for (std::sregex_iterator it(s.begin(), s.end(), token), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(last, m[0].first);
    if (m[1].matched) out += m[1].str();
    else if (m[2].matched) out += "vec" + m[2].str();
    else if (m[3].matched) out += m[3].str();
    else out += "float";
    last = m[0].second;
  }
  out.append(last, s.cend());
  return out;
}

void apply_sabotage(Sabotage s, std::string* source, Options* options) {
  if (s == Sabotage::DropLo) *source = demote_doubles(*source);
  if (s == Sabotage::DropGuard) options->guard = GuardKind::None;
}

}  // namespace doublet::verify
