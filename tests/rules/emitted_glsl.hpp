// Helpers for the rule tests: split emitted GLSL into functions, build a tiny caller shader.
#pragma once

#include <string>
#include <vector>

namespace doublet::rules::test {

struct EmittedFunction {
  std::string header;     // the comment lines directly above the definition
  std::string signature;  // "ret name(params)"
  std::string ret;
  std::string name;
  std::vector<std::pair<std::string, std::string>> params;  // (type, name)
  std::string body;       // between the outer braces
  size_t offset = 0;      // position in the emitted text
};

inline std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// Function definitions of `text` in order: a definition starts at column 0 with a line that is
// not a comment, struct or uniform and contains '(' and '{', and ends at a line "}".
inline std::vector<EmittedFunction> split_functions(const std::string& text) {
  std::vector<EmittedFunction> out;
  std::vector<std::string> lines;
  std::vector<size_t> offsets;
  for (size_t pos = 0; pos <= text.size();) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    lines.push_back(text.substr(pos, nl - pos));
    offsets.push_back(pos);
    pos = nl + 1;
  }
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    if (l.empty() || l[0] == ' ' || l[0] == '/' || l.rfind("struct", 0) == 0 || l.rfind("uniform", 0) == 0 ||
        l.find('(') == std::string::npos || l.find('{') == std::string::npos)
      continue;
    EmittedFunction f;
    f.offset = offsets[i];
    f.signature = trim(l.substr(0, l.find('{')));
    const size_t open = f.signature.find('('), close = f.signature.rfind(')');
    const std::string head = trim(f.signature.substr(0, open));
    f.name = head.substr(head.rfind(' ') + 1);
    f.ret = trim(head.substr(0, head.rfind(' ')));
    std::string plist = f.signature.substr(open + 1, close - open - 1) + ",";
    std::string cur;
    for (char c : plist) {
      if (c == ',') {
        cur = trim(cur);
        if (!cur.empty()) f.params.push_back({trim(cur.substr(0, cur.rfind(' '))), cur.substr(cur.rfind(' ') + 1)});
        cur.clear();
      } else {
        cur += c;
      }
    }
    for (size_t k = i; k > 0 && lines[k - 1].rfind("//", 0) == 0; --k) f.header = lines[k - 1] + "\n" + f.header;
    size_t j = i + 1;
    for (; j < lines.size() && lines[j] != "}"; ++j) f.body += lines[j] + "\n";
    out.push_back(f);
    i = j;
  }
  return out;
}

// A GLSL expression of `type` (float/int/uint/bool vectors or df_* structs).
// exact_words: mode exact's df_* structs hold uint words (1.5 = 0x3FF80000 00000000).
inline std::string sample_value(const std::string& type, bool exact_words = false) {
  auto width = [&](const std::string& prefix) { return type.substr(prefix.size()); };
  if (type == "float") return "1.5";
  if (type == "int") return "7";
  if (type == "uint") return "7u";
  if (type == "bool") return "true";
  if (type.rfind("vec", 0) == 0) return type + "(1.5)";
  if (type.rfind("ivec", 0) == 0) return type + "(7)";
  if (type.rfind("uvec", 0) == 0) return type + "(7u)";
  if (type.rfind("bvec", 0) == 0) return type + "(true)";
  if (type == "df_double") return exact_words ? "df_double(0x3FF80000u, 0u)" : "df_double(1.5, 0.0)";
  if (type == "ff_double") return "ff_double(1.5, 0.0)";  // mode exact's float-float pair (transcendental bridges)
  if (type.rfind("df_dvec", 0) == 0) {
    const std::string v = "vec" + width("df_dvec");
    if (exact_words) return type + "(u" + v + "(0x3FF80000u), u" + v + "(0u))";
    return type + "(" + v + "(1.5), " + v + "(0.0))";
  }
  return "<unknown type " + type + ">";
}

}  // namespace doublet::rules::test
