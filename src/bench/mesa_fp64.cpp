#include "bench/mesa_fp64.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>

namespace doublet::bench {

namespace {

// Typed stand-ins for what Mesa gets from GL_ARB_gpu_shader_int64 (see the header). The mix
// overloads keep GLSL's own mix for the types the file already used it with; the uvec2 one selects
// both words, as mix on a uint64_t does.
const char* const kPrelude = R"(// Mesa's float64.glsl (soft-fp64, after Berkeley SoftFloat 3e), adapted by doublet bench for
// GLSL ES: uint64_t spelled uvec2 (lo, hi); the arithmetic below is Mesa's, unchanged.
#define uint64_t uvec2
#define packUint2x32(v) (v)
#define unpackUint2x32(v) (v)
uint mesa_mix(uint x, uint y, bool a) { return mix(x, y, a); }
int mesa_mix(int x, int y, bool a) { return mix(x, y, a); }
bool mesa_mix(bool x, bool y, bool a) { return mix(x, y, a); }
float mesa_mix(float x, float y, bool a) { return mix(x, y, a); }
uvec2 mesa_mix(uvec2 x, uvec2 y, bool a) { return mix(x, y, bvec2(a)); }
uvec2 mesa_mix(uvec2 x, uvec2 y, bvec2 a) { return mix(x, y, a); }
#define mix(x, y, a) mesa_mix(x, y, a)
)";

// Written here after Mesa 22.3's src/compiler/nir/nir_lower_double_ops.c (lower_rcp,
// fix_inv_result, set_exponent, get_exponent), read, not copied: what a driver without fp64 runs
// for a double division once NIR has lowered it (fdiv -> a * rcp(b); the fp64 ops of rcp then
// become float64.glsl calls: ffma -> __ffma64, which is __fadd64 of __fmul64, not fused).
const char* const kMesaDivision = R"(
// mesa_div: a / b = a * rcp(b). rcp: b with exponent 1023, a float reciprocal of it, the
// exponent moved back; two Newton-Raphson steps x + x * (1 - x * b); then 0 where the exponent
// underflows or b is Inf/NaN, and Inf with b's sign for b = +-0 (fix_inv_result).
uvec2 mesa_set_exponent(uvec2 v, int e) { return uvec2(v.x, bitfieldInsert(v.y, uint(e), 20, 11)); }
int mesa_get_exponent(uvec2 v) { return int(bitfieldExtract(v.y, 20, 11)); }
uvec2 mesa_rcp(uvec2 b) {
  uvec2 minusOne = uvec2(0u, 0xBFF00000u);
  uvec2 estimate = __fp32_to_fp64(1.0 / __fp64_to_fp32(mesa_set_exponent(b, 1023)));
  int e = mesa_get_exponent(estimate) - (mesa_get_exponent(b) - 1023);
  uvec2 x = mesa_set_exponent(estimate, e);
  x = __ffma64(__fneg64(x), __ffma64(x, b, minusOne), x);
  x = __ffma64(__fneg64(x), __ffma64(x, b, minusOne), x);
  if (0 >= e || __feq64(__fabs64(b), uvec2(0u, 0x7FF00000u))) x = uvec2(0u);
  if (!__fneu64(b, uvec2(0u))) x = uvec2(0u, (b.y & 0x80000000u) | 0x7FF00000u);
  return x;
}
uvec2 mesa_div(uvec2 a, uvec2 b) { return __fmul64(a, mesa_rcp(b)); }
)";

// Comments removed, line breaks kept (so the text stays readable and line counts stay).
std::string strip_comments(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      const size_t end = s.find("*/", i + 2);
      const size_t stop = end == std::string::npos ? s.size() : end + 2;
      for (; i < stop; ++i)
        if (s[i] == '\n') out += '\n';
    } else {
      out += s[i++];
    }
  }
  return out;
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::set<std::string> identifiers(const std::string& s) {
  std::set<std::string> out;
  for (size_t i = 0; i < s.size();) {
    if (is_ident_start(s[i]) && (i == 0 || !is_ident_char(s[i - 1]))) {
      size_t j = i;
      while (j < s.size() && is_ident_char(s[j])) ++j;
      out.insert(s.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
  return out;
}

struct Definition {
  std::string name;  // function name; empty for a declaration that is not a function
  std::string text;
};

// The file's top level: #define/#undef lines (kept, in order), function definitions and other
// declarations. #version/#extension/#pragma are dropped; #if at the top level is refused (the
// slice could not honour it).
bool split_top_level(const std::string& s, std::string* defines, std::vector<Definition>* defs, std::string* error) {
  int depth = 0, line = 1;
  std::string current;
  bool line_start = true;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (depth == 0 && line_start && c == '#') {
      std::string directive;
      while (i < s.size() && (s[i] != '\n' || (!directive.empty() && directive.back() == '\\'))) {
        if (s[i] == '\n') ++line;
        directive += s[i++];
      }
      ++line;
      size_t k = 1;
      while (k < directive.size() && std::isspace(static_cast<unsigned char>(directive[k]))) ++k;
      const std::string word = directive.substr(k, directive.find_first_of(" \t(", k) - k);
      if (word == "define" || word == "undef") *defines += directive + "\n";
      else if (word != "version" && word != "extension" && word != "pragma") {
        *error = "line " + std::to_string(line - 1) + ": #" + word + " around definitions is not supported";
        return false;
      }
      line_start = true;
      continue;
    }
    if (c == '\n') ++line, line_start = true;
    else if (!std::isspace(static_cast<unsigned char>(c))) line_start = false;
    current += c;
    if (c == '{') ++depth;
    if (c == '}' && --depth < 0) {
      *error = "line " + std::to_string(line) + ": unbalanced '}'";
      return false;
    }
    if (depth == 0 && (c == '}' || c == ';')) {
      Definition d;
      const size_t paren = current.find('(');
      if (c == '}' && paren != std::string::npos) {
        size_t end = paren;
        while (end > 0 && std::isspace(static_cast<unsigned char>(current[end - 1]))) --end;
        size_t begin = end;
        while (begin > 0 && is_ident_char(current[begin - 1])) --begin;
        d.name = current.substr(begin, end - begin);
      }
      const size_t first = current.find_first_not_of(" \t\n");
      d.text = first == std::string::npos ? "" : current.substr(first) + "\n";
      if (!d.text.empty()) defs->push_back(std::move(d));
      current.clear();
    }
  }
  if (depth != 0) {
    *error = "unbalanced '{' at the end of the file";
    return false;
  }
  return true;
}

// 64-bit integer literals (suffix ul/UL, or l/L) as uvec2(lo, hi). A signed one must not be negated
// (two's complement across two words is not what unary minus on a uvec2 gives): refused.
bool convert_literals(std::string* text, std::string* error) {
  std::string& s = *text;
  std::string out;
  for (size_t i = 0; i < s.size();) {
    const bool starts_number = std::isdigit(static_cast<unsigned char>(s[i])) &&
                               (i == 0 || (!is_ident_char(s[i - 1]) && s[i - 1] != '.'));
    if (!starts_number) {
      out += s[i++];
      continue;
    }
    size_t j = i;
    const bool hex = s.compare(i, 2, "0x") == 0 || s.compare(i, 2, "0X") == 0;
    if (hex) j += 2;
    while (j < s.size() && (hex ? std::isxdigit(static_cast<unsigned char>(s[j])) : std::isdigit(static_cast<unsigned char>(s[j])))) ++j;
    size_t k = j;
    while (k < s.size() && is_ident_char(s[k])) ++k;
    std::string suffix = s.substr(j, k - j);
    for (char& ch : suffix) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (suffix == "ul" || suffix == "lu" || suffix == "l") {
      if (suffix == "l" && i > 0 && s.find_last_not_of(" \t", i - 1) != std::string::npos &&
          s[s.find_last_not_of(" \t", i - 1)] == '-') {
        *error = "negative 64-bit literal " + s.substr(i, k - i) + " cannot be spelled as uvec2";
        return false;
      }
      const uint64_t v = std::stoull(s.substr(i, j - i), nullptr, hex ? 16 : 10);
      char buf[64];
      std::snprintf(buf, sizeof buf, "uvec2(0x%08Xu, 0x%08Xu)", static_cast<unsigned>(v & 0xFFFFFFFFu),
                    static_cast<unsigned>(v >> 32));
      out += buf;
    } else {
      out += s.substr(i, k - i);
    }
    i = k;
  }
  s = std::move(out);
  return true;
}

// Desktop GLSL converts an int literal to uint implicitly; ES does not. These are the places the
// file relies on it (Mesa 22.3.6, in __fadd64 and __normalizeFloat64Subnormal), given the u the
// value already has. A file with others fails to compile, and the bench says where.
void spell_uint_literals(std::string* s) {
  static const std::pair<const char*, const char*> kSpellings[] = {
      {"uint sign_of_difference = 0;", "uint sign_of_difference = 0u;"},
      {"sign_of_difference = 0x80000000;", "sign_of_difference = 0x80000000u;"},
      {"aFrac0 == 0)", "aFrac0 == 0u)"},
  };
  for (const auto& [from, to] : kSpellings)
    for (size_t p = s->find(from); p != std::string::npos; p = s->find(from, p + std::string(to).size()))
      s->replace(p, std::string(from).size(), to);
}

}  // namespace

const std::vector<std::string>& mesa_fp64_roots() {
  static const std::vector<std::string> roots{"__fadd64", "__fneg64", "__fmul64", "__ffma64", "__fsqrt64", "__fabs64",
                                              "__feq64",  "__fneu64", "__fp32_to_fp64", "__fp64_to_fp32"};
  return roots;
}

bool adapt_mesa_fp64(const std::string& file_text, std::string* library, std::string* error) {
  std::string defines;
  std::vector<Definition> defs;
  if (!split_top_level(strip_comments(file_text), &defines, &defs, error)) return false;
  std::map<std::string, std::vector<size_t>> by_name;
  for (size_t i = 0; i < defs.size(); ++i)
    if (!defs[i].name.empty()) by_name[defs[i].name].push_back(i);
  // Reachable from the roots through calls (an identifier naming another definition).
  std::set<size_t> keep;
  std::vector<std::string> todo;
  for (const std::string& root : mesa_fp64_roots()) {
    if (!by_name.count(root)) {
      *error = "no function " + root + " in the file (is it Mesa's src/compiler/glsl/float64.glsl?)";
      return false;
    }
    todo.push_back(root);
  }
  while (!todo.empty()) {
    const std::string name = todo.back();
    todo.pop_back();
    for (size_t i : by_name[name]) {
      if (!keep.insert(i).second) continue;
      for (const std::string& id : identifiers(defs[i].text))
        if (id != name && by_name.count(id)) todo.push_back(id);
    }
  }
  std::string body;
  for (size_t i : keep) body += defs[i].text + "\n";  // file order: std::set<size_t> is sorted
  if (!convert_literals(&body, error)) return false;
  spell_uint_literals(&body);
  *library = std::string(kPrelude) + defines + "\n" + body + kMesaDivision;
  return true;
}

std::string mesa_op_expression(const std::string& op, const std::string& a, const std::string& b) {
  if (op == "add") return "__fadd64(" + a + ", " + b + ")";
  if (op == "sub") return "__fadd64(" + a + ", __fneg64(" + b + "))";
  if (op == "mul") return "__fmul64(" + a + ", " + b + ")";
  if (op == "div") return "mesa_div(" + a + ", " + b + ")";
  if (op == "sqrt") return "__fsqrt64(" + a + ")";
  return "";
}

}  // namespace doublet::bench
