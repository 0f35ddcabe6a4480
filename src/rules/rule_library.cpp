// RuleLibrary: parses the rules/*.glsl chunk format (docs/rules-format.md), instantiates chunks
// per width and guard style, and emits the transitive closure of what a shader uses.
#include "rules/rule_library.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string_view>
#include <utility>

#include "embedded_rules.hpp"

namespace doublet::rules {

namespace {

constexpr int kMaxWidth = 4;
constexpr const char* kComponents[] = {"x", "y", "z", "w"};

struct Param {
  std::string type;  // template text, e.g. "$DF" or "float"
  std::string name;
};

// The "@variant" kinds, most specific first: where a request selects several, the first one that
// has a chunk of the wanted name and width replaces the plain chunk (docs/rules-format.md).
constexpr const char* kVariantKinds[] = {"int", "integer-functions", "bit-casts"};
constexpr size_t kVariantKindCount = std::size(kVariantKinds);

// Which "@variant" kinds a request selects, indexed as kVariantKinds (from EmitRequest's
// integer_eft, integer_functions and bit_casts flags).
using Variants = std::array<bool, kVariantKindCount>;

int variant_kind(const std::string& name) {
  for (size_t k = 0; k < kVariantKindCount; ++k)
    if (name == kVariantKinds[k]) return static_cast<int>(k);
  return -1;
}

struct Chunk {
  std::string name;
  std::string file;
  int line = 0;
  std::vector<std::string> comment;  // header lines ("// ..."), annotations removed
  std::string definition;            // template text of the function definition
  std::string ret_type;              // template text
  std::vector<Param> params;
  std::vector<int> widths;
  int min_es = 100;
  bool per_component = false;
  int variant_kind = -1;  // its index in kVariantKinds; -1 for a plain chunk
  std::vector<std::pair<std::string, std::vector<std::string>>> uses;  // callee -> widths ("2", "W")
  std::vector<std::string> callees;  // chunk names referenced by the definition, first use order
  std::map<std::string, std::string> fields;  // Algorithm, Source, Bound, Flops
};

// Modes exact and rte-exact: the rules of these files work on binary64 words (df_* structs of uints);
// any other rule they call (a transcendental bridge's callee) keeps float words, as ff_* types.
bool holds_binary64_words(const Chunk& c) { return c.file == "exact.glsl" || c.file == "rte_exact.glsl"; }

std::string trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return std::string(s.substr(b, e - b));
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

bool is_identifier(std::string_view s) {
  if (s.empty() || !is_ident_start(s[0])) return false;
  return std::all_of(s.begin(), s.end(), is_ident_char);
}

std::vector<std::string> split_ws(std::string_view s) {
  std::vector<std::string> out;
  std::istringstream in{std::string(s)};
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

// Identifiers of `text` outside comments, in order of first appearance.
std::vector<std::string> identifiers(std::string_view text) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (size_t i = 0; i < text.size();) {
    if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
      continue;
    }
    if (text[i] == '$') {  // placeholder name: skip
      ++i;
      while (i < text.size() && std::isupper(static_cast<unsigned char>(text[i]))) ++i;
      continue;
    }
    if (is_ident_start(text[i]) && (i == 0 || !is_ident_char(text[i - 1]))) {
      size_t j = i;
      while (j < text.size() && is_ident_char(text[j])) ++j;
      std::string id(text.substr(i, j - i));
      if (seen.insert(id).second) out.push_back(id);
      i = j;
      continue;
    }
    ++i;
  }
  return out;
}

std::string es_name(int es) {
  std::ostringstream o;
  o << "ES " << es / 100 << '.' << (es % 100 < 10 ? "0" : "") << es % 100;
  return o.str();
}

std::string df_type(int w) { return w == 1 ? "df_double" : "df_dvec" + std::to_string(w); }
std::string vec_type(const char* scalar, const char* vec, int w) {
  return w == 1 ? std::string(scalar) : std::string(vec) + std::to_string(w);
}

// Mode exact's name for the float-float types: there df_double holds binary64 words, and the
// float-float rules that rules/exact.glsl bridges to (the transcendentals) keep their float pairs
// under this name.
std::string ff_type(int w) { return w == 1 ? "ff_double" : "ff_dvec" + std::to_string(w); }

// `text` with every identifier df_double/df_dvecN renamed to ff_double/ff_dvecN.
std::string rename_to_ff_types(std::string_view text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (is_ident_start(text[i]) && (i == 0 || !is_ident_char(text[i - 1]))) {
      size_t j = i;
      while (j < text.size() && is_ident_char(text[j])) ++j;
      std::string id(text.substr(i, j - i));
      for (int w = 1; w <= 4; ++w)
        if (id == df_type(w)) id = ff_type(w);
      out += id;
      i = j;
      continue;
    }
    out += text[i++];
  }
  return out;
}

struct Subst {
  int width = 1;
  GuardStyle guard = GuardStyle::None;
  std::string guard_uniform = "df_guard";
  bool indexed_guard = false;  // EmitRequest::indexed_guard
  bool exact_words = false;  // EmitRequest::exact_words: uint words in the df_* structs
  int es_version = 300;      // EmitRequest::es_version: $SEL is mix() from ES 3.00 on
};

// The guard's value as a guarded step reads it. Indexed: element 0 of a two-element array at an
// index read from element 1 (both 0), an offset no driver may take for a constant, so a uniform
// inliner that specialises the shader on uniforms cannot replace the guard (docs/accuracy.md,
// "A uniform inliner cannot reach an indexed guard").
std::string guard_read(const Subst& s) {
  return s.indexed_guard ? s.guard_uniform + "[int(" + s.guard_uniform + "[1])]" : s.guard_uniform;
}

// The arguments of a placeholder call whose '(' is at in[open]: split at the commas of depth 1.
// Returns the index of the closing ')' (npos when unbalanced).
size_t placeholder_arguments(std::string_view in, size_t open, std::vector<std::string_view>& args) {
  int depth = 0;
  size_t start = open + 1;
  for (size_t k = open; k < in.size(); ++k) {
    if (in[k] == '(') ++depth;
    if (in[k] == ',' && depth == 1) {
      args.push_back(in.substr(start, k - start));
      start = k + 1;
    }
    if (in[k] == ')' && --depth == 0) {
      args.push_back(in.substr(start, k - start));
      return k;
    }
  }
  return std::string_view::npos;
}

// Replaces the placeholders of docs/rules-format.md. Returns false (and sets *error) on an
// unknown placeholder or an unbalanced $G( or $SAFE(.
bool substitute(std::string_view in, const Subst& s, std::string& out, std::string* error) {
  for (size_t i = 0; i < in.size(); ++i) {
    if (in[i] != '$') {
      out += in[i];
      continue;
    }
    size_t j = i + 1;
    while (j < in.size() && std::isupper(static_cast<unsigned char>(in[j]))) ++j;
    std::string key(in.substr(i + 1, j - i - 1));
    if (key == "SEL") {
      // $SEL(c, a, b): c ? a : b without a branch (docs/rules-format.md): mix(b, a, c) where GLSL
      // has mix on a boolean selector (ES 3.00, GLSL 1.30; WGSL prints select), a ternary on ES 1.00.
      std::vector<std::string_view> args;
      const size_t k = j < in.size() && in[j] == '(' ? placeholder_arguments(in, j, args) : std::string_view::npos;
      if (k == std::string_view::npos || args.size() != 3) {
        *error = "$SEL must be followed by (condition, if_true, if_false)";
        return false;
      }
      std::string c, a, b;
      if (!substitute(args[0], s, c, error) || !substitute(args[1], s, a, error) || !substitute(args[2], s, b, error))
        return false;
      auto trim = [](std::string& t) {
        t.erase(0, t.find_first_not_of(' '));
        t.erase(t.find_last_not_of(' ') + 1);
      };
      trim(c), trim(a), trim(b);
      out += s.es_version >= 300 ? "mix(" + b + ", " + a + ", " + c + ")" : "(" + c + " ? " + a + " : " + b + ")";
      i = k;
      continue;
    }
    if (key == "G" || key == "SAFE") {
      std::vector<std::string_view> args;
      const size_t k = j < in.size() && in[j] == '(' ? placeholder_arguments(in, j, args) : std::string_view::npos;
      if (j >= in.size() || in[j] != '(') {
        *error = "$" + key + " must be followed by '('";
        return false;
      }
      if (k == std::string_view::npos) {
        *error = "unbalanced parentheses in $" + key + "(...)";
        return false;
      }
      std::string inner;
      if (!substitute(in.substr(j + 1, k - j - 1), s, inner, error)) return false;
      // $SAFE(e): a step no later step of the rule cancels against (docs/rules.md, "The
      // optimizer guard"): `precise` where the target has it, no uniform subtraction.
      if (s.guard == GuardStyle::Uniform && key == "G")
        // Subtract the +0 guard: x - 0 == x for every x including -0 (x + 0 turns -0 into +0).
        out += "((" + inner + ") - " + guard_read(s) + ")";
      else
        out += "(" + inner + ")";
      i = k;
      continue;
    }
    const int w = s.width;
    if (key == "DF") out += df_type(w);
    else if (key == "F") out += vec_type("float", "vec", w);
    else if (key == "B") out += vec_type("bool", "bvec", w);
    else if (key == "I") out += vec_type("int", "ivec", w);
    else if (key == "U") out += vec_type("uint", "uvec", w);
    else if (key == "W") out += std::to_string(w);
    else if (key == "PRECISE") {
      // "$PRECISE $F x" -> "precise float x" or "float x".
      if (s.guard == GuardStyle::Precise) out += "precise";
      else if (j < in.size() && in[j] == ' ') ++j;
    }
    else {
      *error = "unknown placeholder $" + key;
      return false;
    }
    i = j - 1;
  }
  return true;
}

std::string subst_or_empty(std::string_view in, const Subst& s) {
  std::string out, err;
  if (!substitute(in, s, out, &err)) return {};
  return out;
}

bool is_width_placeholder(const std::string& t) {
  return t == "$DF" || t == "$F" || t == "$B" || t == "$I" || t == "$U";
}

// "out $I" → "$I" (an out parameter of a @per-component rule); anything else → "".
std::string_view out_param_type(std::string_view t) {
  constexpr std::string_view kOut = "out ";
  return t.substr(0, kOut.size()) == kOut ? t.substr(kOut.size()) : std::string_view();
}

}  // namespace

struct RuleLibrary::Impl {
  std::vector<Chunk> chunks;
  std::map<std::pair<std::string, int>, size_t> index;  // (name, width) -> chunk
  // Per kind of kVariantKinds: (name, width) -> that "@variant" chunk.
  std::array<std::map<std::pair<std::string, int>, size_t>, kVariantKindCount> variant_index;
  std::set<std::string> names;
  std::string init_error;  // builtin() only: the embedded rules failed to parse

  // The "@variant" chunk of that name and width the request selects, most specific first
  // (kVariantKinds' order), else the plain one.
  const Chunk* find(const std::string& name, int width, const Variants& v = {}) const {
    for (size_t k = 0; k < kVariantKindCount; ++k) {
      if (!v[k]) continue;
      auto it = variant_index[k].find({name, width});
      if (it != variant_index[k].end()) return &chunks[it->second];
    }
    auto it = index.find({name, width});
    return it == index.end() ? nullptr : &chunks[it->second];
  }

  // Direct dependencies of one instance.
  bool deps(const Chunk& c, int width, std::vector<RuleRef>& out, std::string* error, const Variants& v = {}) const {
    if (c.per_component && width > 1) {
      out.push_back({c.name, 1});
      return true;
    }
    for (const auto& callee : c.callees) {
      auto u = std::find_if(c.uses.begin(), c.uses.end(), [&](const auto& p) { return p.first == callee; });
      if (u != c.uses.end()) {
        for (const auto& spec : u->second) out.push_back({callee, spec == "W" ? width : std::stoi(spec)});
      } else if (find(callee, width, v)) {
        out.push_back({callee, width});
      } else {
        *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + " (width " + std::to_string(width) +
                 ") calls " + callee + ", which has no width " + std::to_string(width) +
                 "; name the width with @uses " + callee + ":N";
        return false;
      }
    }
    for (const auto& [callee, specs] : c.uses) {
      if (std::find(c.callees.begin(), c.callees.end(), callee) != c.callees.end()) continue;
      for (const auto& spec : specs) out.push_back({callee, spec == "W" ? width : std::stoi(spec)});
    }
    return true;
  }

  // The function text of one instance, header comment included.
  bool instantiate(const Chunk& c, int width, const Subst& s, std::string& out, std::string* error) const {
    {
      Subst sw = s;
      sw.width = width;
      for (const auto& line : c.comment)
        if (!substitute(line, sw, out, error)) {
          *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + " header: " + *error;
          return false;
        } else {
          out += "\n";
        }
    }
    if (!(c.per_component && width > 1)) {
      Subst sw = s;
      sw.width = width;
      if (!substitute(c.definition, sw, out, error)) {
        *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + ": " + *error;
        return false;
      }
      out += "\n";
      return true;
    }
    // @per-component: the width-1 rule applied to each component.
    Subst sw = s, s1 = s;
    sw.width = width;
    s1.width = 1;
    const std::string ret_w = subst_or_empty(c.ret_type, sw), ret_1 = subst_or_empty(c.ret_type, s1);
    std::string signature = ret_w + " " + c.name + "(";
    for (size_t i = 0; i < c.params.size(); ++i)
      signature += (i ? ", " : "") + subst_or_empty(c.params[i].type, sw) + " " + c.params[i].name;
    signature += ") {\n";
    if (s.exact_words) {
      per_component_loop(c, width, signature, ret_w, ret_1, s1, out);
      return true;
    }
    out += "// (width " + std::to_string(width) + ": the width-1 " + c.name + " applied to each component)\n";
    out += signature;
    // An `out $I e` parameter: one width-1 local per component, gathered into e at the end.
    std::string gather;
    for (const auto& p : c.params) {
      const std::string_view type = out_param_type(p.type);
      if (type.empty()) continue;
      std::string parts;
      for (int k = 0; k < width; ++k) {
        const std::string local = p.name + "_" + std::to_string(k);
        out += "  " + subst_or_empty(std::string(type), s1) + " " + local + ";\n";
        parts += (k ? ", " : "") + local;
      }
      gather += "  " + p.name + " = " + subst_or_empty(std::string(type), sw) + "(" + parts + ");\n";
    }
    for (int k = 0; k < width; ++k) {
      out += "  " + ret_1 + " r" + std::to_string(k) + " = " + c.name + "(";
      for (size_t i = 0; i < c.params.size(); ++i) {
        const auto& p = c.params[i];
        out += i ? ", " : "";
        if (!out_param_type(p.type).empty())
          out += p.name + "_" + std::to_string(k);
        else
          out += component_argument(p, std::string(".") + kComponents[k]);
      }
      out += ");\n";
    }
    out += gather;
    auto list = [&](const std::string& suffix) {
      std::string l;
      for (int k = 0; k < width; ++k) l += (k ? ", r" : "r") + std::to_string(k) + suffix;
      return l;
    };
    if (c.ret_type == "$DF") {
      const std::string v = s.exact_words ? vec_type("uint", "uvec", width) : vec_type("float", "vec", width);
      out += "  return " + ret_w + "(" + v + "(" + list(".hi") + "), " + v + "(" + list(".lo") + "));\n";
    } else {
      out += "  return " + ret_w + "(" + list("") + ");\n";
    }
    out += "}\n";
    return true;
  }

  // The argument passing one component of parameter p to the width-1 rule; `selector` picks the
  // component (".x", "[per_i]"). Parameters of a fixed type pass whole.
  static std::string component_argument(const Param& p, const std::string& selector) {
    if (p.type == "$DF") return "df_double(" + p.name + ".hi" + selector + ", " + p.name + ".lo" + selector + ")";
    return is_width_placeholder(p.type) ? p.name + selector : p.name;
  }

  // Mode exact's @per-component instance: one call of the width-1 rule in a loop over the
  // components, so drivers compile one copy of an operation of a few hundred integer instructions
  // instead of `width` (docs/performance.md, "Mode exact: vector and matrix operations as loops").
  // The index is computed from the counter (width - 1 - per_k), as everywhere in mode exact's loops:
  // Mesa's GLSL compiler unrolls, whatever the body's size, a loop whose counter indexes an array
  // with as many elements as the loop has iterations (for vector components no difference was
  // measured). The names carry a per_ prefix so that no rule's parameter name is shadowed.
  static void per_component_loop(const Chunk& c, int width, const std::string& signature, const std::string& ret_w,
                                 const std::string& ret_1, const Subst& s1, std::string& out) {
    const std::string last = std::to_string(width - 1);
    out += "// (width " + std::to_string(width) + ": the width-1 " + c.name + " applied to each component, in a loop)\n";
    out += signature + "  " + ret_w + " per_r;\n";
    out += "  for (int per_k = 0; per_k < " + std::to_string(width) + "; ++per_k) {\n    int per_i = " + last + " - per_k;\n";
    std::string call = c.name + "(", stores;
    for (size_t i = 0; i < c.params.size(); ++i) {
      const auto& p = c.params[i];
      call += i ? ", " : "";
      if (const std::string_view type = out_param_type(p.type); !type.empty()) {
        out += "    " + subst_or_empty(std::string(type), s1) + " " + p.name + "_per;\n";
        call += p.name + "_per";
        stores += "    " + p.name + "[per_i] = " + p.name + "_per;\n";
      } else {
        call += component_argument(p, "[per_i]");
      }
    }
    out += "    " + ret_1 + " per_c = " + call + ");\n" + stores;
    out += c.ret_type == "$DF" ? "    per_r.hi[per_i] = per_c.hi;\n    per_r.lo[per_i] = per_c.lo;\n" : "    per_r[per_i] = per_c;\n";
    out += "  }\n  return per_r;\n}\n";
  }
};

namespace {

// Splits one rule file into chunks.
bool parse_file(const std::string& file, const std::string& text, std::vector<Chunk>& out, std::string* error) {
  std::vector<std::string> lines;
  {
    std::string cur;
    for (char ch : text) {
      if (ch == '\n') {
        lines.push_back(cur);
        cur.clear();
      } else if (ch != '\r') {
        cur += ch;
      }
    }
    if (!cur.empty()) lines.push_back(cur);
  }
  auto fail = [&](size_t line, const std::string& msg) {
    *error = file + ":" + std::to_string(line + 1) + ": " + msg;
    return false;
  };
  std::vector<std::string> pending;
  for (size_t i = 0; i < lines.size();) {
    const std::string t = trim(lines[i]);
    if (t.empty()) {
      pending.clear();
      ++i;
      continue;
    }
    if (t.rfind("//", 0) == 0) {
      pending.push_back(t);
      ++i;
      continue;
    }
    if (t.rfind("/*", 0) == 0) return fail(i, "block comments are not supported in rule files; use //");
    if (t[0] == '#') return fail(i, "preprocessor lines are not supported in rule files");
    // A definition: up to the brace that closes the first '{'.
    const size_t start = i;
    std::string def;
    int depth = 0;
    bool opened = false;
    for (; i < lines.size(); ++i) {
      std::string code = lines[i];
      if (auto c = code.find("//"); c != std::string::npos) code.resize(c);
      if (code.find("/*") != std::string::npos) return fail(i, "block comments are not supported in rule files");
      def += lines[i] + "\n";
      if (!opened && code.find(';') != std::string::npos)
        return fail(i, "only function definitions may appear at top level");
      for (char ch : code) {
        if (ch == '{') {
          ++depth;
          opened = true;
        } else if (ch == '}') {
          if (--depth < 0) return fail(i, "unbalanced '}'");
        }
      }
      if (opened && depth == 0) {
        ++i;
        break;
      }
    }
    if (!opened || depth != 0) return fail(start, "definition is not closed (missing '}')");
    while (!def.empty() && (def.back() == '\n' || def.back() == ' ')) def.pop_back();

    Chunk c;
    c.file = file;
    c.line = static_cast<int>(start + 1);
    c.definition = def;
    // Signature: <return type> <name>(<params>) {
    const std::string sig = def.substr(0, def.find('{'));
    const size_t open = sig.find('('), close = sig.rfind(')');
    if (open == std::string::npos || close == std::string::npos || close < open)
      return fail(start, "only function definitions may appear at top level");
    auto head = split_ws(sig.substr(0, open));
    if (head.size() < 2) return fail(start, "expected '<return type> <name>(...)'");
    c.name = head.back();
    head.pop_back();
    for (size_t k = 0; k < head.size(); ++k) c.ret_type += (k ? " " : "") + head[k];
    if (!is_identifier(c.name)) return fail(start, "bad function name '" + c.name + "'");
    const std::string plist = trim(sig.substr(open + 1, close - open - 1));
    if (!plist.empty() && plist != "void") {
      std::string cur;
      std::vector<std::string> parts;
      for (char ch : plist) {
        if (ch == ',') {
          parts.push_back(cur);
          cur.clear();
        } else {
          cur += ch;
        }
      }
      parts.push_back(cur);
      for (const auto& p : parts) {
        auto w = split_ws(p);
        if (w.size() < 2) return fail(start, c.name + ": bad parameter '" + trim(p) + "'");
        Param prm;
        prm.name = w.back();
        w.pop_back();
        for (size_t k = 0; k < w.size(); ++k) prm.type += (k ? " " : "") + w[k];
        c.params.push_back(prm);
      }
    }
    if (pending.empty()) return fail(start, c.name + " has no header comment (see docs/rules-format.md)");
    bool widths_given = false;
    for (const auto& raw : pending) {
      const std::string body = trim(std::string_view(raw).substr(2));
      if (!body.empty() && body[0] == '@') {
        auto w = split_ws(body);
        const std::string key = w[0];
        w.erase(w.begin());
        if (key == "@widths") {
          widths_given = true;
          for (const auto& v : w) {
            if (v.size() != 1 || v[0] < '1' || v[0] > '4') return fail(start, c.name + ": @widths takes 1..4, got '" + v + "'");
            c.widths.push_back(v[0] - '0');
          }
          if (c.widths.empty()) return fail(start, c.name + ": @widths is empty");
        } else if (key == "@min-es") {
          if (w.size() != 1 || (w[0] != "100" && w[0] != "300" && w[0] != "310" && w[0] != "320"))
            return fail(start, c.name + ": @min-es takes one of 100 300 310 320");
          c.min_es = std::stoi(w[0]);
        } else if (key == "@variant") {
          if (w.size() != 1 || variant_kind(w[0]) < 0) {
            std::string kinds;
            for (size_t k = 0; k < kVariantKindCount; ++k)
              kinds += std::string(k == 0 ? "'" : k + 1 == kVariantKindCount ? " or '" : ", '") + kVariantKinds[k] + "'";
            return fail(start, c.name + ": @variant takes " + kinds);
          }
          c.variant_kind = variant_kind(w[0]);
        } else if (key == "@per-component") {
          if (!w.empty()) return fail(start, c.name + ": @per-component takes no value");
          c.per_component = true;
        } else if (key == "@uses") {
          for (const auto& v : w) {
            const auto colon = v.find(':');
            if (colon == std::string::npos || colon == 0) return fail(start, c.name + ": @uses wants NAME:WIDTH[,WIDTH], got '" + v + "'");
            std::vector<std::string> specs;
            std::string spec;
            for (char ch : v.substr(colon + 1) + ",") {
              if (ch == ',') {
                if (spec != "W" && !(spec.size() == 1 && spec[0] >= '1' && spec[0] <= '4'))
                  return fail(start, c.name + ": @uses width must be 1..4 or W, got '" + spec + "'");
                specs.push_back(spec);
                spec.clear();
              } else {
                spec += ch;
              }
            }
            c.uses.push_back({v.substr(0, colon), specs});
          }
        } else {
          return fail(start, c.name + ": unknown annotation " + key);
        }
        continue;
      }
      for (const char* f : {"Algorithm", "Source", "Bound", "Flops"}) {
        const std::string key = std::string(f) + ":";
        if (body.rfind(key, 0) == 0) c.fields[f] = trim(body.substr(key.size()));
      }
      c.comment.push_back(raw);
    }
    if (!widths_given) c.widths = {1};
    for (const char* f : {"Algorithm", "Source", "Bound", "Flops"})
      if (c.fields[f].empty()) return fail(start, c.name + ": header lacks a non-empty '" + std::string(f) + ":' line");
    if (c.per_component) {
      if (!is_width_placeholder(c.ret_type))
        return fail(start, c.name + ": @per-component needs a $DF/$F/$B/$I/$U return type");
      for (const auto& p : c.params)
        if (p.type.find('$') != std::string::npos && !is_width_placeholder(p.type) &&
            !(is_width_placeholder(std::string(out_param_type(p.type))) && out_param_type(p.type) != "$DF"))
          return fail(start, c.name + ": @per-component parameter type '" + p.type + "' is not supported");
    }
    out.push_back(std::move(c));
    pending.clear();
  }
  return true;
}

}  // namespace

RuleLibrary::RuleLibrary() : impl_(std::make_unique<Impl>()) {}
RuleLibrary::~RuleLibrary() = default;
RuleLibrary::RuleLibrary(RuleLibrary&&) noexcept = default;
RuleLibrary& RuleLibrary::operator=(RuleLibrary&&) noexcept = default;

std::optional<RuleLibrary> RuleLibrary::parse(const std::vector<std::pair<std::string, std::string>>& files,
                                              std::string* error) {
  std::string local_error;
  if (!error) error = &local_error;
  try {
    RuleLibrary lib;
    Impl& im = *lib.impl_;
    for (const auto& [name, text] : files)
      if (!parse_file(name, text, im.chunks, error)) return std::nullopt;
    for (size_t i = 0; i < im.chunks.size(); ++i) {
      const Chunk& c = im.chunks[i];
      im.names.insert(c.name);
      for (int w : c.widths) {
        auto& index = c.variant_kind < 0 ? im.index : im.variant_index[c.variant_kind];
        if (!index.emplace(std::make_pair(c.name, w), i).second) {
          *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + " width " + std::to_string(w) +
                   " is defined twice";
          return std::nullopt;
        }
      }
    }
    for (auto& c : im.chunks) {
      for (const auto& id : identifiers(c.definition))
        if (id != c.name && im.names.count(id)) c.callees.push_back(id);
      for (const auto& [callee, specs] : c.uses) {
        if (!im.names.count(callee)) {
          *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + ": @uses names unknown rule " + callee;
          return std::nullopt;
        }
        if (callee == c.name && std::find(specs.begin(), specs.end(), "W") != specs.end()) {
          *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + " @uses itself at its own width";
          return std::nullopt;
        }
      }
      if (c.per_component && std::find(c.widths.begin(), c.widths.end(), 1) == c.widths.end()) {
        *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + ": @per-component needs width 1";
        return std::nullopt;
      }
    }
    // Every instance: dependencies exist, placeholders substitute, no cycles.
    for (const auto& variants : im.variant_index)
      for (const auto& [key, idx] : variants)
        if (!im.index.count(key)) {
          const Chunk& c = im.chunks[idx];
          *error = c.file + ":" + std::to_string(c.line) + ": " + c.name + " width " + std::to_string(key.second) +
                   ": @variant " + kVariantKinds[c.variant_kind] + " replaces nothing (no plain chunk of that name and width)";
          return std::nullopt;
        }
    Variants selected{};
    std::map<std::pair<std::string, int>, int> state;  // 1 visiting, 2 done
    std::vector<RuleRef> stack;
    std::function<bool(const RuleRef&)> visit = [&](const RuleRef& r) -> bool {
      auto key = std::make_pair(r.name, r.width);
      if (state[key] == 2) return true;
      const Chunk* c = im.find(r.name, r.width, selected);
      if (!c) {
        *error = "rule " + r.name + " has no width " + std::to_string(r.width);
        return false;
      }
      if (state[key] == 1) {
        *error = c->file + ":" + std::to_string(c->line) + ": dependency cycle through " + r.name + " (width " +
                 std::to_string(r.width) + ")";
        return false;
      }
      state[key] = 1;
      std::vector<RuleRef> ds;
      if (!im.deps(*c, r.width, ds, error, selected)) return false;
      for (const auto& d : ds)
        if (!visit(d)) return false;
      for (GuardStyle g : {GuardStyle::Precise, GuardStyle::Uniform, GuardStyle::None}) {
        std::string text;
        if (!im.instantiate(*c, r.width, Subst{r.width, g, "df_guard"}, text, error)) return false;
      }
      state[key] = 2;
      return true;
    };
    // No variant, each kind alone, and all of them (df64-int on a target with integer functions).
    for (size_t choice = 0; choice <= kVariantKindCount + 1; ++choice) {
      for (size_t k = 0; k < kVariantKindCount; ++k)
        selected[k] = choice == k + 1 || choice == kVariantKindCount + 1;
      state.clear();
      for (const auto& [key, idx] : im.index)
        if (!visit({key.first, key.second})) return std::nullopt;
    }
    return lib;
  } catch (const std::exception& e) {
    *error = std::string("rule library: ") + e.what();
  } catch (...) {
    *error = "rule library: unknown error";
  }
  return std::nullopt;
}

const RuleLibrary& RuleLibrary::builtin() {
  static const RuleLibrary lib = [] {
    std::vector<std::pair<std::string, std::string>> files;
    for (std::size_t i = 0; i < detail::kEmbeddedRuleFileCount; ++i)
      files.emplace_back(detail::kEmbeddedRuleFiles[i].name, detail::kEmbeddedRuleFiles[i].text);
    std::string error;
    auto parsed = parse(files, &error);
    if (parsed) return std::move(*parsed);
    RuleLibrary empty;
    empty.impl_->init_error = "the built-in rules failed to parse: " + error;
    return empty;
  }();
  return lib;
}

bool RuleLibrary::has(const RuleRef& ref) const { return impl_ && impl_->find(ref.name, ref.width) != nullptr; }

std::vector<std::string> RuleLibrary::parameter_qualifiers(const std::string& name) const {
  std::vector<std::string> qualifiers;
  if (!impl_) return qualifiers;
  // The rule's narrowest width (every width declares the same qualifiers): a lookup, not a scan, as
  // the WGSL passes ask for every runtime call they meet.
  const auto it = impl_->index.lower_bound({name, std::numeric_limits<int>::min()});
  if (it == impl_->index.end() || it->first.first != name) return qualifiers;
  for (const auto& p : impl_->chunks[it->second].params)
    qualifiers.push_back(p.type.rfind("out ", 0) == 0 ? "out" : p.type.rfind("inout ", 0) == 0 ? "inout" : "");
  return qualifiers;
}

std::vector<RuleRef> RuleLibrary::all() const {
  // Names in order of first appearance in the files, each name's widths ascending.
  std::vector<RuleRef> out;
  if (!impl_) return out;
  std::set<std::string> done;
  for (const auto& c : impl_->chunks) {
    if (!done.insert(c.name).second) continue;
    for (int w = 1; w <= kMaxWidth; ++w)
      if (impl_->find(c.name, w)) out.push_back({c.name, w});
  }
  return out;
}

std::vector<RuleInfo> RuleLibrary::info() const {
  std::vector<RuleInfo> out;
  if (!impl_) return out;
  for (const auto& c : impl_->chunks) {
    RuleInfo r;
    r.name = c.name;
    r.widths = c.widths;
    r.min_es = c.min_es;
    r.per_component = c.per_component;
    r.variant = c.variant_kind < 0 ? "" : kVariantKinds[c.variant_kind];
    r.file = c.file;
    r.algorithm = c.fields.at("Algorithm");
    r.source = c.fields.at("Source");
    r.bound = c.fields.at("Bound");
    r.flops = c.fields.at("Flops");
    for (const auto& l : c.comment) r.header += l + "\n";
    out.push_back(std::move(r));
  }
  return out;
}

EmitResult RuleLibrary::emit(const EmitRequest& request) const {
  EmitResult result;
  try {
    if (!impl_) {
      result.error = "rule library is empty (moved-from)";
      return result;
    }
    const Impl& im = *impl_;
    if (!im.init_error.empty()) {
      result.error = im.init_error;
      return result;
    }
    if (request.guard == GuardStyle::Uniform && !is_identifier(request.guard_uniform)) {
      result.error = "guard uniform name '" + request.guard_uniform + "' is not a GLSL identifier";
      return result;
    }
    for (const auto& r : request.used) {
      if (!im.names.count(r.name)) {
        result.error = "unknown rule " + r.name;
        return result;
      }
      if (!im.find(r.name, r.width)) {
        std::string ws;
        for (const auto& c : im.chunks)
          if (c.name == r.name)
            for (int w : c.widths) ws += (ws.empty() ? "" : " ") + std::to_string(w);
        result.error = "rule " + r.name + " has no width " + std::to_string(r.width) + " (widths: " + ws + ")";
        return result;
      }
    }
    // Mode exact has no optimizer guard: the float-float rules its bridges call (rules/exact.glsl,
    // transcendentals) take the integer error-free transformations of df64-int, which need none.
    const Variants selected = {request.integer_eft || request.exact_words, request.integer_functions,
                               request.bit_casts};  // kVariantKinds' order
    // Post-order DFS: callees before callers, each instance once.
    std::vector<RuleRef> order;
    std::map<std::pair<std::string, int>, int> state;
    std::map<std::pair<std::string, int>, RuleRef> parent;
    std::string error;
    std::function<bool(const RuleRef&)> visit = [&](const RuleRef& r) -> bool {
      auto key = std::make_pair(r.name, r.width);
      if (state[key] == 2) return true;
      if (state[key] == 1) {
        error = "dependency cycle through " + r.name;
        return false;
      }
      state[key] = 1;
      const Chunk* c = im.find(r.name, r.width, selected);
      std::vector<RuleRef> ds;
      if (!c || !im.deps(*c, r.width, ds, &error, selected)) {
        if (error.empty()) error = "rule " + r.name + " has no width " + std::to_string(r.width);
        return false;
      }
      for (const auto& d : ds) {
        parent.emplace(std::make_pair(d.name, d.width), r);
        if (!visit(d)) return false;
      }
      state[key] = 2;
      order.push_back(r);
      return true;
    };
    for (const auto& r : request.used)
      if (!visit(r)) {
        result.error = error;
        return result;
      }
    for (const auto& r : order) {
      const Chunk* c = im.find(r.name, r.width, selected);
      if (c->min_es > request.es_version) {
        std::string msg = r.name + " is not available on " + es_name(request.es_version) + " (it needs " +
                          es_name(c->min_es) + " or later)";
        // Name the rule the shader asked for when this one is only a dependency.
        RuleRef root = r;
        for (auto it = parent.find({root.name, root.width}); it != parent.end();
             it = parent.find({root.name, root.width}))
          root = it->second;
        if (!(root == r)) msg += ", needed by " + root.name;
        result.error = msg;
        result.error_rule = root.name;
        return result;
      }
    }
    Subst s;
    s.guard = request.guard;
    s.guard_uniform = request.guard_uniform;
    s.indexed_guard = request.indexed_guard;
    s.exact_words = request.exact_words;
    s.es_version = request.es_version;
    std::vector<std::string> functions;
    std::set<int> struct_widths, ff_struct_widths;
    for (const auto& r : order) {
      const Chunk& c = *im.find(r.name, r.width, selected);
      // Mode exact: a float-float rule (a bridge's callee) keeps float words, as ff_* types.
      const bool float_float = request.exact_words && !holds_binary64_words(c);
      Subst sc = s;
      if (float_float) sc.exact_words = false;
      std::string text;
      if (!im.instantiate(c, r.width, sc, text, &error)) {
        result.error = error;
        return result;
      }
      if (float_float) text = rename_to_ff_types(text);
      for (const auto& id : identifiers(text))
        for (int w = 1; w <= kMaxWidth; ++w) {
          if (id == df_type(w)) struct_widths.insert(w);
          if (id == ff_type(w)) ff_struct_widths.insert(w);
        }
      functions.push_back(std::move(text));
    }
    std::string out;
    if (!order.empty()) {
      if (request.exact_words) {
        const size_t bridged = size_t(std::count_if(order.begin(), order.end(), [&](const RuleRef& r) {
          return !holds_binary64_words(*im.find(r.name, r.width, selected));
        }));
        out += "// doublet exact binary64 runtime (mode exact): " + std::to_string(order.size() - bridged) +
               " functions from rules/exact.glsl and rules/rte_exact.glsl, integer arithmetic (no optimizer guard needed)";
        if (bridged)
          out += "; " + std::to_string(bridged) + " float-float functions (on ff_* types) its transcendentals bridge to, with "
                 "integer error-free transformations (df64-int)";
      } else {
        out += "// doublet float-float runtime: " + std::to_string(order.size()) + " functions from rules/*.glsl, guard: ";
        out += request.guard == GuardStyle::Precise   ? "precise"
               : request.guard == GuardStyle::Uniform ? "uniform " + request.guard_uniform
                                                      : "none (unprotected)";
        if (request.integer_eft) out += ", error-free transformations: integer (df64-int)";
      }
      out += "\n";
      for (int w : struct_widths) {
        const std::string f = request.exact_words ? vec_type("uint", "uvec", w) : vec_type("float", "vec", w);
        out += pair_struct_definition(df_type(w), f + " hi", f + " lo", true);
      }
      for (int w : ff_struct_widths) {
        const std::string f = vec_type("float", "vec", w);
        out += pair_struct_definition(ff_type(w), f + " hi", f + " lo", true);
      }
      result.types_end = out.size();
      if (request.guard == GuardStyle::Uniform)
        out += "uniform highp float " + request.guard_uniform + (request.indexed_guard ? "[" + std::to_string(kIndexedGuardElements) + "]" : "") +
               ";  // never set: GL zero-fills it at link\n";
      for (const auto& f : functions) out += "\n" + f;
    }
    result.text = std::move(out);
    result.ok = true;
  } catch (const std::exception& e) {
    result.ok = false;
    result.text.clear();
    result.error = std::string("rule library: ") + e.what();
  } catch (...) {
    result.ok = false;
    result.text.clear();
    result.error = "rule library: unknown error";
  }
  return result;
}

std::string pair_struct_definition(const std::string& name, const std::string& hi, const std::string& lo, bool one_line) {
  return one_line ? "struct " + name + " { " + hi + "; " + lo + "; };\n"
                  : "struct " + name + " {\n  " + hi + ";\n  " + lo + ";\n};\n";
}

}  // namespace doublet::rules
