// RuleLibrary: the contract names, closure and order of emitted code, guards, errors, parsing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include "emitted_glsl.hpp"
#include "rules/rule_library.hpp"

namespace doublet::rules {
namespace {

using test::split_functions;
using test::trim;

const RuleLibrary& lib() { return RuleLibrary::builtin(); }

EmitResult emit_one(const std::string& name, int width, GuardStyle g = GuardStyle::Uniform, int es = 320,
                    bool integer_eft = false) {
  EmitRequest req;
  req.integer_eft = integer_eft;
  req.used = {{name, width}};
  req.guard = g;
  req.es_version = es;
  return lib().emit(req);
}

// The names the compiler core calls, with their widths (the contract of rule_library.hpp).
const std::map<std::string, std::vector<int>>& contract() {
  static const std::map<std::string, std::vector<int>> c = {
      {"df_add", {1, 2, 3, 4}},       {"df_sub", {1, 2, 3, 4}},        {"df_mul", {1, 2, 3, 4}},
      {"df_div", {1, 2, 3, 4}},       {"df_neg", {1, 2, 3, 4}},        {"df_sqrt", {1, 2, 3, 4}},
      {"df_abs", {1, 2, 3, 4}},       {"df_min", {1, 2, 3, 4}},        {"df_max", {1, 2, 3, 4}},
      {"df_lt", {1}},                 {"df_le", {1}},                  {"df_gt", {1}},
      {"df_ge", {1}},                 {"df_equal", {1, 2, 3, 4}},      {"df_not_equal", {1, 2, 3, 4}},
      {"df_dot", {1, 2, 3, 4}},       {"df_length", {1, 2, 3, 4}},     {"df_from_float", {1, 2, 3, 4}},
      {"df_to_float", {1, 2, 3, 4}},  {"df_from_int", {1, 2, 3, 4}},   {"df_to_int", {1, 2, 3, 4}},
      {"df_from_uint", {1, 2, 3, 4}}, {"df_to_uint", {1, 2, 3, 4}},    {"df_from_bool", {1, 2, 3, 4}},
      {"df_to_bool", {1, 2, 3, 4}},
  };
  return c;
}

std::string df(int w) { return w == 1 ? "df_double" : "df_dvec" + std::to_string(w); }
std::string vec(const char* s, const char* v, int w) { return w == 1 ? s : std::string(v) + std::to_string(w); }

TEST(RuleLibrary, BuiltinParses) {
  EmitResult r = emit_one("df_add", 1);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_GE(lib().all().size(), 90u);
}

TEST(RuleLibrary, ContractNamesWidthsAndSignatures) {
  for (const auto& [name, widths] : contract()) {
    for (int w = 1; w <= 4; ++w) {
      const bool want = std::find(widths.begin(), widths.end(), w) != widths.end();
      EXPECT_EQ(lib().has({name, w}), want) << name << " width " << w;
      if (!want) continue;
      EmitResult r = emit_one(name, w);
      ASSERT_TRUE(r.ok) << name << " " << w << ": " << r.error;
      auto fns = split_functions(r.text);
      ASSERT_FALSE(fns.empty());
      const auto& f = fns.back();  // the requested function comes last
      EXPECT_EQ(f.name, name);
      // Return types of the contract.
      std::string ret = df(w);
      if (name == "df_lt" || name == "df_le" || name == "df_gt" || name == "df_ge" || name == "df_equal" ||
          name == "df_not_equal")
        ret = "bool";
      else if (name == "df_dot" || name == "df_length")
        ret = "df_double";
      else if (name == "df_to_float")
        ret = vec("float", "vec", w);
      else if (name == "df_to_int")
        ret = vec("int", "ivec", w);
      else if (name == "df_to_uint")
        ret = vec("uint", "uvec", w);
      else if (name == "df_to_bool")
        ret = vec("bool", "bvec", w);
      EXPECT_EQ(f.ret, ret) << f.signature;
      // Parameter types of the conversions.
      std::string p0 = df(w);
      if (name == "df_from_float") p0 = vec("float", "vec", w);
      if (name == "df_from_int") p0 = vec("int", "ivec", w);
      if (name == "df_from_uint") p0 = vec("uint", "uvec", w);
      if (name == "df_from_bool") p0 = vec("bool", "bvec", w);
      ASSERT_FALSE(f.params.empty()) << f.signature;
      EXPECT_EQ(f.params[0].first, p0) << f.signature;
    }
  }
}

// Every instance alone: only its transitive closure, each function once, callees first.
TEST(RuleLibrary, EmitsClosureInDependencyOrder) {
  std::set<std::string> all_names;
  for (const auto& r : lib().all()) all_names.insert(r.name);
  for (const auto& ref : lib().all()) {
    SCOPED_TRACE(ref.name + " width " + std::to_string(ref.width));
    EmitResult r = emit_one(ref.name, ref.width);
    ASSERT_TRUE(r.ok) << r.error;
    auto fns = split_functions(r.text);
    ASSERT_FALSE(fns.empty());
    EXPECT_EQ(fns.back().name, ref.name);
    std::set<std::string> signatures;
    std::set<std::string> defined;
    std::map<std::string, int> called_later;  // name -> number of later functions calling it
    for (size_t i = 0; i < fns.size(); ++i) {
      EXPECT_TRUE(signatures.insert(fns[i].signature).second) << "defined twice: " << fns[i].signature;
      // Every rule called here is already defined above.
      std::regex call("\\b((?:df|ex)_[a-z0-9_]+)\\s*\\(");  // ex_: rules/exact.glsl
      for (std::sregex_iterator it(fns[i].body.begin(), fns[i].body.end(), call), end; it != end; ++it) {
        const std::string callee = (*it)[1];
        if (callee.rfind("df_dvec", 0) == 0 || callee == "df_double") continue;  // constructors
        EXPECT_TRUE(all_names.count(callee)) << callee;
        EXPECT_TRUE(defined.count(callee)) << fns[i].name << " calls " << callee << " before its definition";
        called_later[callee]++;
      }
      defined.insert(fns[i].name);
    }
    // Nothing unused: every function but the requested one is called by a later one.
    for (size_t i = 0; i + 1 < fns.size(); ++i)
      EXPECT_GT(called_later[fns[i].name], 0) << fns[i].signature << " is emitted but unused";
    // Struct types: exactly those used.
    for (int w = 1; w <= 4; ++w) {
      const bool declared = r.text.find("struct " + df(w) + " ") != std::string::npos;
      std::string rest = r.text;
      size_t decl = rest.find("struct " + df(w) + " ");
      if (decl != std::string::npos) rest.erase(decl, 7 + df(w).size());
      const bool used = std::regex_search(rest, std::regex("\\b" + df(w) + "\\b"));
      EXPECT_EQ(declared, used) << df(w);
      if (declared) EXPECT_LT(decl, fns.front().offset) << "struct after functions";
    }
  }
}

TEST(RuleLibrary, SmallClosureExample) {
  EmitResult r = emit_one("df_add", 3);
  ASSERT_TRUE(r.ok) << r.error;
  auto fns = split_functions(r.text);
  std::vector<std::string> names;
  for (const auto& f : fns) names.push_back(f.name);
  // df_finish is @per-component: its width-3 instance calls the width-1 one (on df_double).
  EXPECT_EQ(names, (std::vector<std::string>{"df_two_sum", "df_fast_two_sum", "df_finish", "df_finish", "df_add"}));
  EXPECT_NE(r.text.find("struct df_dvec3 { vec3 hi; vec3 lo; };"), std::string::npos);
  EXPECT_NE(r.text.find("struct df_double { float hi; float lo; };"), std::string::npos);
  EXPECT_EQ(r.text.find("df_mul"), std::string::npos);
}

TEST(RuleLibrary, SharedDependenciesEmittedOnce) {
  EmitRequest req;
  req.used = {{"df_div", 2}, {"df_mul", 2}, {"df_add", 2}, {"df_sqrt", 2}, {"df_length", 3}, {"df_add", 2}};
  EmitResult r = lib().emit(req);
  ASSERT_TRUE(r.ok) << r.error;
  auto fns = split_functions(r.text);
  std::set<std::string> sigs;
  for (const auto& f : fns) EXPECT_TRUE(sigs.insert(f.signature).second) << f.signature;
  auto pos = [&](const std::string& sig) {
    for (const auto& f : fns)
      if (f.signature == sig) return static_cast<long>(f.offset);
    return -1L;
  };
  EXPECT_LT(pos("df_dvec2 df_split(vec2 a)"), pos("df_dvec2 df_two_prod(vec2 a, vec2 b)"));
  EXPECT_LT(pos("df_dvec2 df_two_prod(vec2 a, vec2 b)"), pos("df_dvec2 df_mul(df_dvec2 a, df_dvec2 b)"));
  EXPECT_LT(pos("df_dvec2 df_mul_f(df_dvec2 a, vec2 b)"), pos("df_dvec2 df_div(df_dvec2 a, df_dvec2 b)"));
  EXPECT_LT(pos("df_double df_sqrt(df_double a)"), pos("df_double df_length(df_dvec3 a)"));
  EXPECT_LT(pos("df_double df_dot(df_dvec3 a, df_dvec3 b)"), pos("df_double df_length(df_dvec3 a)"));
  EXPECT_GE(pos("df_double df_add(df_double a, df_double b)"), 0);  // df_dot width 3 sums in width 1
  EXPECT_EQ(r.text.find("struct df_dvec4"), std::string::npos);
}

TEST(RuleLibrary, EmptyRequestIsEmpty) {
  EmitResult r = lib().emit(EmitRequest{});
  EXPECT_TRUE(r.ok);
  EXPECT_TRUE(r.text.empty());
}

TEST(RuleLibrary, GuardStyles) {
  EmitRequest req;
  req.used = {{"df_mul", 1}};
  req.guard = GuardStyle::Uniform;
  req.guard_uniform = "my_zero";
  EmitResult u = lib().emit(req);
  ASSERT_TRUE(u.ok) << u.error;
  EXPECT_NE(u.text.find("uniform highp float my_zero;"), std::string::npos);
  EXPECT_NE(u.text.find("((a * b) - my_zero)"), std::string::npos) << u.text;
  EXPECT_EQ(u.text.find("precise"), std::string::npos);
  EXPECT_EQ(u.text.find("df_guard"), std::string::npos);

  req.guard = GuardStyle::Precise;
  EmitResult p = lib().emit(req);
  ASSERT_TRUE(p.ok) << p.error;
  EXPECT_NE(p.text.find("precise float p = (a * b);"), std::string::npos) << p.text;
  EXPECT_EQ(p.text.find("uniform"), std::string::npos);

  req.guard = GuardStyle::None;
  EmitResult n = lib().emit(req);
  ASSERT_TRUE(n.ok) << n.error;
  EXPECT_NE(n.text.find("float p = (a * b);"), std::string::npos);
  EXPECT_EQ(n.text.find("precise"), std::string::npos);
  EXPECT_EQ(n.text.find("uniform"), std::string::npos);
  EXPECT_EQ(n.text.find('$'), std::string::npos);

  req.guard = GuardStyle::Uniform;
  req.guard_uniform = "not an identifier";
  EmitResult bad = lib().emit(req);
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.error.find("not a GLSL identifier"), std::string::npos);
}

bool has_arithmetic(const std::string& expr) {
  for (size_t i = 0; i < expr.size(); ++i) {
    const char c = expr[i];
    if (c != '+' && c != '-' && c != '*' && c != '/') continue;
    size_t p = i;
    while (p > 0 && expr[p - 1] == ' ') --p;
    const char prev = p > 0 ? expr[p - 1] : '(';
    // Exponent sign of a literal such as 1.0e-30.
    if ((c == '-' || c == '+') && (prev == 'e' || prev == 'E') && p >= 2 &&
        (std::isdigit(static_cast<unsigned char>(expr[p - 2])) || expr[p - 2] == '.'))
      continue;
    // Sign of a literal: -1.0 after '(' or ',' or at the start.
    if ((c == '-' || c == '+') && (prev == '(' || prev == ',') && i + 1 < expr.size() &&
        (std::isdigit(static_cast<unsigned char>(expr[i + 1])) || expr[i + 1] == '.'))
      continue;
    return true;
  }
  return false;
}

// Calls f(file name, line) for every line of every rules/*.glsl source.
template <typename F>
void for_each_rule_source_line(F&& f) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(DOUBLET_SOURCE_DIR) + "/rules")) {
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) f(entry.path().filename().string(), line);
  }
}

// Per rule function, the float temporaries its source declares $SAFE(...) (steps no later step
// cancels against, which need no Uniform guard; docs/rules.md, "The optimizer guard").
std::map<std::string, std::set<std::string>> safe_temporaries() {
  std::map<std::string, std::set<std::string>> safe;
  const std::regex function(R"(^\S+ (\w+)\(.*\) \{$)");
  const std::regex safe_decl(R"(\$PRECISE (?:\$F|float|vec[234]) (\w+) = \$SAFE\()");
  std::string current;
  for_each_rule_source_line([&](const std::string&, const std::string& line) {
    std::smatch m;
    if (std::regex_match(line, m, function)) current = m[1];
    else if (std::regex_search(line, m, safe_decl)) safe[current].insert(m[1]);
  });
  return safe;
}

TEST(RuleLibrary, EveryFloatTemporaryIsGuardedOrDeclaredSafe) {
  const std::regex temporary(R"(\$PRECISE \$F \w+ = (\$\w+\()?)");
  int safe_count = 0, guarded_count = 0;
  for_each_rule_source_line([&](const std::string& file, const std::string& line) {
    std::smatch m;
    if (!std::regex_search(line, m, temporary)) return;
    SCOPED_TRACE(file + ": " + line);
    EXPECT_TRUE(m[1] == "$G(" || m[1] == "$SAFE(") << "a float temporary must be $G(...) or $SAFE(...)";
    (m[1] == "$SAFE(" ? safe_count : guarded_count)++;
  });
  // The first steps of every error-free transformation stay guarded: this test fails if a
  // sweeping edit marks everything safe.
  EXPECT_GT(guarded_count, 0);
  EXPECT_GT(safe_count, 0);
  const auto safe = safe_temporaries();
  for (const auto& [fn, steps] : std::map<std::string, std::vector<std::string>>{
           {"df_two_sum", {"s", "bb"}}, {"df_fast_two_sum", {"s", "z"}}, {"df_split", {"g", "d"}},
           {"df_two_prod", {"p"}}}) {
    for (const auto& step : steps) EXPECT_EQ(safe.count(fn) ? safe.at(fn).count(step) : 0u, 0u) << fn << "." << step;
  }
}

// The optimizer guard: every float temporary that computes anything is $PRECISE and wrapped in
// $G(...) or, where its source says $SAFE(...), carries no Uniform guard; no arithmetic anywhere
// else (returns, arguments, conditions). Integer statements are exempt (integer arithmetic is
// exact and cannot be rewritten inexactly).
TEST(RuleLibrary, EveryFloatOperationIsGuarded) {
  const auto safe = safe_temporaries();
  const std::regex function_name(R"(^\S+ (\w+)\()");
  const std::regex decl(R"(^(precise\s+)?(\w+)\s+(\w+)\s*=\s*([\s\S]*)$)");
  const std::regex int_type(R"(^(int|uint|bool|[iub]vec[234])$)");
  const std::regex float_type(R"(^(float|vec[234])$)");
  for (GuardStyle g : {GuardStyle::Uniform, GuardStyle::Precise}) {
    for (const auto& ref : lib().all())
      for (bool integer_eft : {false, true}) {  // df64-int's rules/int.glsl too
      EmitResult r = emit_one(ref.name, ref.width, g, 320, integer_eft);
      ASSERT_TRUE(r.ok) << r.error;
      for (const auto& f : split_functions(r.text)) {
        // rules/exact.glsl is integer arithmetic only: no float operation for an optimizer to rewrite.
        if (f.name.rfind("ex_", 0) == 0) continue;
        std::string stmt;
        for (char c : f.body + ";") {
          if (c != ';' && c != '{' && c != '}') {
            stmt += c;
            continue;
          }
          std::string s = trim(stmt);
          stmt.clear();
          if (s.empty() || s.rfind("//", 0) == 0) continue;
          SCOPED_TRACE(f.signature + ": " + s);
          std::smatch m;
          if (std::regex_match(s, m, decl)) {
            const std::string type = m[2], rhs = trim(m[4]);
            if (std::regex_match(type, int_type)) continue;
            if (std::regex_match(type, float_type)) {
              std::smatch fn;
              const bool declared_safe = std::regex_search(f.signature, fn, function_name) &&
                                         safe.count(fn[1].str()) && safe.at(fn[1].str()).count(m[3].str());
              if (g == GuardStyle::Uniform && !declared_safe) {
                EXPECT_TRUE(rhs.rfind("((", 0) == 0 && rhs.size() > 13 &&
                            rhs.compare(rhs.size() - 13, 13, ") - df_guard)") == 0)
                    << "float temporary neither wrapped in $G(...) nor declared $SAFE(...)";
              } else if (g == GuardStyle::Uniform) {
                EXPECT_EQ(rhs.find("df_guard"), std::string::npos) << "a $SAFE step carries the guard";
              } else {
                EXPECT_TRUE(m[1].matched) << "float temporary not declared $PRECISE";
              }
              continue;
            }
            EXPECT_FALSE(has_arithmetic(rhs)) << "arithmetic outside a guarded float temporary";
            continue;
          }
          EXPECT_FALSE(has_arithmetic(s)) << "arithmetic outside a guarded float temporary";
        }
      }
    }
  }
}

TEST(RuleLibrary, UnknownRulesAndWidths) {
  EmitResult r = emit_one("df_frobnicate", 1);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("unknown rule df_frobnicate"), std::string::npos) << r.error;
  EXPECT_TRUE(r.text.empty());
  r = emit_one("df_lt", 3);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("df_lt has no width 3"), std::string::npos) << r.error;
}

TEST(RuleLibrary, MinEsIsEnforced) {
  for (const char* name : {"df_from_uint", "df_to_uint"}) {
    for (int w = 1; w <= 4; ++w) {
      EmitResult r = emit_one(name, w, GuardStyle::Uniform, 100);
      EXPECT_FALSE(r.ok);
      EXPECT_EQ(r.error, std::string(name) + " is not available on ES 1.00 (it needs ES 3.00 or later)");
      EXPECT_TRUE(r.text.empty());
      EXPECT_TRUE(emit_one(name, w, GuardStyle::Uniform, 300).ok);
    }
  }
  // Everything else is ES 1.00 unless its header says @min-es (and then it is refused below that).
  std::map<std::string, int> min_es;
  for (const auto& info : lib().info())  // df64-int replacements are not emitted without integer_eft
    if (info.variant.empty()) min_es[info.name] = std::max(min_es[info.name], info.min_es);
  for (const auto& ref : lib().all()) {
    if (ref.name == "df_from_uint" || ref.name == "df_to_uint") continue;
    EXPECT_EQ(emit_one(ref.name, ref.width, GuardStyle::Uniform, 100).ok, min_es[ref.name] == 100) << ref.name;
    EXPECT_TRUE(emit_one(ref.name, ref.width, GuardStyle::Uniform, 300).ok) << ref.name;
  }
}

TEST(RuleLibrary, ThreadSafeBuiltin) {
  std::vector<std::thread> threads;
  std::vector<std::string> texts(8);
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([t, &texts] {
      EmitRequest req;
      req.used = {{"df_div", 1 + t % 4}, {"df_sqrt", 1 + t % 4}};
      texts[t] = RuleLibrary::builtin().emit(req).text;
    });
  for (auto& th : threads) th.join();
  for (int t = 4; t < 8; ++t) EXPECT_EQ(texts[t], texts[t - 4]);
  EXPECT_FALSE(texts[0].empty());
}

// ---- the format, on small hand-written libraries ----

const char* kHeader =
    "// Algorithm: a\n// Source: s 2017\n// Bound: exact\n// Flops: 1\n";

std::optional<RuleLibrary> parse_one(const std::string& text, std::string* error) {
  return RuleLibrary::parse({{"t.glsl", text}}, error);
}

TEST(RuleFormat, PlaceholdersAndWidths) {
  std::string err;
  auto l = parse_one(std::string("// file header\n\n") + kHeader +
                         "// @widths 1 3\n$DF f($F x, $B b, $I i, $U u) {\n"
                         "  $PRECISE $F y = $G(x * $F($W));\n  return $DF(y, $F(0.0));\n}\n",
                     &err);
  ASSERT_TRUE(l) << err;
  EXPECT_TRUE(l->has({"f", 1}));
  EXPECT_FALSE(l->has({"f", 2}));
  EXPECT_TRUE(l->has({"f", 3}));
  EmitRequest req;
  req.used = {{"f", 3}};
  req.guard = GuardStyle::Uniform;
  req.guard_uniform = "g0";
  EmitResult r = l->emit(req);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(r.text.find("df_dvec3 f(vec3 x, bvec3 b, ivec3 i, uvec3 u) {"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("  vec3 y = ((x * vec3(3)) - g0);"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("uniform highp float g0;"), std::string::npos);
  EXPECT_EQ(r.text.find("@widths"), std::string::npos) << "annotations are not emitted";
  EXPECT_NE(r.text.find("// Bound: exact"), std::string::npos);
  EXPECT_EQ(r.text.find("file header"), std::string::npos);
}

TEST(RuleFormat, UsesAndPerComponent) {
  std::string err;
  auto l = parse_one(std::string(kHeader) +
                         "// @widths 1 2 3 4\n// @per-component\n$DF pick($DF a, $F k, float s) {\n"
                         "  if (a.hi < k) {\n    return a;\n  }\n  return $DF(k, s);\n}\n\n" +
                         kHeader + "// @widths 2\n// @uses pick:1,W\ndf_double both($DF a) {\n"
                         "  df_double x = df_double(a.hi.x, a.lo.x);\n  df_double y = pick(x, 1.0, 0.0);\n"
                         "  $DF z = pick(a, $F(1.0), 0.0);\n  return y;\n}\n",
                     &err);
  ASSERT_TRUE(l) << err;
  EmitRequest req;
  req.used = {{"both", 2}};
  req.guard = GuardStyle::None;
  EmitResult r = l->emit(req);
  ASSERT_TRUE(r.ok) << r.error;
  auto fns = split_functions(r.text);
  ASSERT_EQ(fns.size(), 3u) << r.text;
  EXPECT_EQ(fns[0].signature, "df_double pick(df_double a, float k, float s)");
  EXPECT_EQ(fns[1].signature, "df_dvec2 pick(df_dvec2 a, vec2 k, float s)");
  EXPECT_NE(fns[1].body.find("df_double r1 = pick(df_double(a.hi.y, a.lo.y), k.y, s);"), std::string::npos)
      << fns[1].body;
  EXPECT_NE(fns[1].body.find("return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));"), std::string::npos)
      << fns[1].body;
  EXPECT_EQ(fns[2].name, "both");
}

// `@variant integer-functions` replaces the plain chunk (here a dependency) only when the request
// says the target has the integer functions; it must replace something and name a known kind.
TEST(RuleFormat, IntegerFunctionsVariant) {
  std::string err;
  const std::string h = kHeader;
  auto l = parse_one(h + "uint lead(uint x) {\n  return x >> 1u;\n}\n\n" + h +
                         "// @min-es 310\n// @variant integer-functions\nuint lead(uint x) {\n  return uint(findMSB(x));\n}\n\n" +
                         h + "uint top(uint x) {\n  return lead(x);\n}\n",
                     &err);
  ASSERT_TRUE(l) << err;
  EmitRequest req;
  req.used = {{"top", 1}};
  req.guard = GuardStyle::None;
  req.es_version = 310;
  EmitResult plain = l->emit(req);
  ASSERT_TRUE(plain.ok) << plain.error;
  EXPECT_NE(plain.text.find("x >> 1u"), std::string::npos) << plain.text;
  EXPECT_EQ(plain.text.find("findMSB"), std::string::npos) << plain.text;
  req.integer_functions = true;
  EmitResult variant = l->emit(req);
  ASSERT_TRUE(variant.ok) << variant.error;
  EXPECT_NE(variant.text.find("findMSB"), std::string::npos) << variant.text;
  EXPECT_EQ(variant.text.find("x >> 1u"), std::string::npos) << variant.text;
  EXPECT_FALSE(parse_one(h + "// @variant integer-functions\nuint lone(uint x) {\n  return x;\n}\n", &err));
  EXPECT_NE(err.find("@variant integer-functions replaces nothing"), std::string::npos) << err;
  EXPECT_FALSE(parse_one(h + "// @variant fast\nuint lead(uint x) {\n  return x;\n}\n", &err));
  EXPECT_NE(err.find("@variant takes 'int', 'integer-functions' or 'bit-casts'"), std::string::npos) << err;
}

// "@variant bit-casts" (TwoProd's split by bits) replaces the plain chunk where the target has bit
// casts, and yields to the df64-int chunk of the same name when both apply.
TEST(RuleFormat, BitCastsVariantYieldsToTheIntegerEfts) {
  std::string err;
  const std::string h = kHeader;
  auto l = parse_one(h + "float cut(float x) {\n  return x * 4097.0;\n}\n\n" + h +
                         "// @min-es 300\n// @variant bit-casts\nfloat cut(float x) {\n  return uintBitsToFloat(floatBitsToUint(x) & 4294963200u);\n}\n\n" +
                         h + "// @min-es 300\n// @variant int\nfloat cut(float x) {\n  return float(floatBitsToInt(x) >> 12);\n}\n\n" +
                         h + "float top(float x) {\n  return cut(x);\n}\n",
                     &err);
  ASSERT_TRUE(l) << err;
  EmitRequest req;
  req.used = {{"top", 1}};
  req.guard = GuardStyle::None;
  req.es_version = 300;
  auto emitted = [&](bool bit_casts, bool integer_eft) {
    req.bit_casts = bit_casts;
    req.integer_eft = integer_eft;
    EmitResult r = l->emit(req);
    EXPECT_TRUE(r.ok) << r.error;
    return r.text;
  };
  EXPECT_NE(emitted(false, false).find("4097.0"), std::string::npos);
  const std::string casts = emitted(true, false);
  EXPECT_NE(casts.find("& 4294963200u"), std::string::npos) << casts;
  EXPECT_EQ(casts.find("4097.0"), std::string::npos) << casts;
  const std::string both = emitted(true, true);
  EXPECT_NE(both.find(">> 12"), std::string::npos) << both;
  EXPECT_EQ(both.find("4294963200u"), std::string::npos) << both;
}

TEST(RuleFormat, Errors) {
  struct Case {
    std::string text;
    std::string message;
  };
  const std::string h = kHeader;
  const std::vector<Case> cases = {
      {"float f(float x) {\n  return x;\n}\n", "has no header comment"},
      {"// Algorithm: a\n// Source: s\n// Flops: 1\nfloat f(float x) {\n  return x;\n}\n", "'Bound:'"},
      {h + "float f(float x) {\n  return $Q;\n}\n", "unknown placeholder $Q"},
      {h + "float f(float x) {\n  return $G(x;\n}\n", "unbalanced"},
      {h + "// @widths 5\nfloat f(float x) {\n  return x;\n}\n", "@widths takes 1..4"},
      {h + "// @frob\nfloat f(float x) {\n  return x;\n}\n", "unknown annotation @frob"},
      {h + "float f(float x) {\n  return x;\n}\n\n" + h + "float f(float x) {\n  return x;\n}\n",
       "defined twice"},
      {h + "float f(float x) {\n  return g(x);\n}\n\n" + h + "float g(float x) {\n  return f(x);\n}\n",
       "dependency cycle"},
      {h + "// @widths 2\n$F f($F x) {\n  return g(x);\n}\n\n" + h + "float g(float x) {\n  return x;\n}\n",
       "has no width 2"},
      {h + "float f(float x) {\n  return x;\n", "not closed"},
      {"#define X 1\n", "preprocessor"},
      {h + "const float k = 1.0;\n", "only function definitions"},
  };
  for (const auto& c : cases) {
    std::string err;
    EXPECT_FALSE(parse_one(c.text, &err)) << c.text;
    EXPECT_NE(err.find(c.message), std::string::npos) << "got: " << err << "\nfor:\n" << c.text;
    EXPECT_NE(err.find("t.glsl"), std::string::npos) << err;
  }
}

}  // namespace
}  // namespace doublet::rules
