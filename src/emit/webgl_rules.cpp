// WebGL 2.0 rules checked on printed GLSL. Sources of the rules: the WebGL 2.0 specification
// ("Differences with OpenGL ES 3.0": reserved webgl_/_webgl_ identifiers, GLSL ES 3.00 only with
// the extensions the context enables) and what ANGLE's translator (the compiler Chromium runs)
// reports: "Float overflow" for a literal above FLT_MAX, no `precise` in ESSL 3.00.
#include "emit/webgl_rules.hpp"

#include "target/target.hpp"

#include <cfloat>
#include <cstdlib>

namespace doublet::emit {
namespace {

bool identifier_start(char c) { return c == '_' || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool identifier_char(char c) { return identifier_start(c) || (c >= '0' && c <= '9'); }
bool digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::vector<WebglViolation> webgl_violations(std::string_view text) {
  std::vector<WebglViolation> out;
  int line = 1;
  bool line_start = true;  // only whitespace so far on this line
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = true;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      const std::size_t stop = end == std::string_view::npos ? text.size() : end + 2;
      for (; i < stop; ++i)
        if (text[i] == '\n') ++line;
      continue;
    }
    const bool directive = line_start && c == '#';
    line_start = false;
    if (directive) {
      std::size_t end = text.find('\n', i);
      if (end == std::string_view::npos) end = text.size();
      std::string_view d = text.substr(i, end - i);
      if (d.find("extension") != std::string_view::npos)
        out.push_back({line, "'" + std::string(d) + "': WebGL enables extensions from JavaScript, and doublet "
                                                     "prints none for webgl2"});
      i = end;
      continue;
    }
    if (identifier_start(c)) {
      std::size_t end = i;
      while (end < text.size() && identifier_char(text[end])) ++end;
      const std::string_view name = text.substr(i, end - i);
      if (name == "precise")
        out.push_back({line, "'precise' is not a WebGL 2.0 (GLSL ES 3.00) keyword"});
      else if (name.rfind("webgl_", 0) == 0 || name.rfind("_webgl_", 0) == 0)
        out.push_back({line, "'" + std::string(name) + "': WebGL reserves identifiers beginning with webgl_ and _webgl_"});
      else if (name.size() > target::facts(Target::Webgl2).max_identifier_length)
        out.push_back({line, "an identifier of " + std::to_string(name.size()) + " characters: WebGL 2.0 allows " +
                                 std::to_string(target::facts(Target::Webgl2).max_identifier_length)});
      i = end;
      continue;
    }
    if (digit(c) || (c == '.' && i + 1 < text.size() && digit(text[i + 1]))) {
      std::size_t end = i;
      bool is_float = false;
      while (end < text.size()) {
        const char d = text[end];
        if (digit(d) || d == '.') {
          is_float = is_float || d == '.';
        } else if ((d == 'e' || d == 'E') && !(text.compare(i, 2, "0x") == 0 || text.compare(i, 2, "0X") == 0)) {
          is_float = true;
          if (end + 1 < text.size() && (text[end + 1] == '+' || text[end + 1] == '-')) ++end;
        } else if (identifier_char(d)) {
          // suffix (u, f) or hex digits
        } else {
          break;
        }
        ++end;
      }
      if (is_float) {
        const std::string literal(text.substr(i, end - i));
        const double value = std::strtod(literal.c_str(), nullptr);
        if (value > FLT_MAX)
          out.push_back({line, "the literal " + literal + " is above FLT_MAX as written: ANGLE warns 'Float overflow'"});
      }
      i = end;
      continue;
    }
    ++i;
  }
  return out;
}

std::string spell_float_max_for_webgl(std::string runtime) {
  static constexpr std::string_view kOverflowing = "3.40282347e38", kExact = "3.4028234663852886e38";
  for (std::size_t at = runtime.find(kOverflowing); at != std::string::npos;
       at = runtime.find(kOverflowing, at + kExact.size()))
    runtime.replace(at, kOverflowing.size(), kExact);
  return runtime;
}

}  // namespace doublet::emit
