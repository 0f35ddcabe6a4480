// Special values and range extremes against native fp64 (docs/extremes.md, one test per row).
//
// Each row is a double expression in x and y. The same shader runs natively in fp64 on lavapipe
// and, lowered by doublet, on lavapipe and on Mesa GLES (llvmpipe), in compute and in the vertex
// and fragment stages; the interface is float only (x = hi + lo in, float(r) and the rest out),
// so both see the same inputs and the same driver. The lowered result must have native's class
// (NaN, +-Inf, +-0 with its sign, finite with its sign) and, where finite, native's value to
// 2^-44 (the rules' bounds). Rows where float-float cannot match native say how it differs
// (Expect::Saturates, Expect::Tiny) and the test checks that documented behaviour instead.
//
// Sabotage: the same rows run with the previous rule text (tests/extremes/baseline_rules/, the
// rules before special values were handled) spliced into the lowered shader, and with the
// Uniform guard adding its zero instead of subtracting it; the rows that those fixed must fail.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "doublet/split.hpp"
#include "rules/rule_library.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;
using doublet::runner::GraphicsStage;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class Expect {
  Match,      // same class and sign; finite values within 2^-44 relative
  Saturates,  // native is finite beyond float range; float-float gives +-Inf of native's sign
  Tiny,       // below ~2^-102: lo subnormal (compute: absolute error <= 2^-146) or flushed
              // (vertex/fragment: float precision, 2^-126 absolute)
  TinyOperand,  // an operand below ~2^-114: compute matches (2^-44); vertex/fragment flush the
                // split's low half, so the product keeps only ~12 bits (2^-11 relative)
  ZeroWithSignOfX,  // GLSL's rule over Mesa's: a zero with the sign of the input x (modf of
                    // +-0: "the same sign as x"; native fp64 gives +0 for -0)
};

// BaselineRules: the rules of commit 16ff2c0 (before special values, issue 7);
// RulesBeforeIssue13: those of commit 86dc5f7 (before the fixes of issue 13).
enum class Sabotage { None, BaselineRules, RulesBeforeIssue13, AddGuard };

struct Row {
  const char* name;
  const char* expr;  // a double expression in x and y
  std::vector<std::pair<double, double>> inputs;
  Expect expect = Expect::Match;
  // Which sabotage must turn the row red (where it did not already fail before the fix).
  bool red_with_baseline = false;
  bool red_with_add_guard = false;
  // Statements before `double r = expr;` (for built-ins with out parameters: frexp, modf).
  const char* prelude = "";
  // Where native fp64 is not IEEE on every CPU (rounding to an integer, docs/extremes.md), the
  // host's IEEE 754 result of the row's expression is the reference instead of native's.
  double (*ieee)(double x, double y) = nullptr;
};

const std::vector<Row>& rows() {
  static const std::vector<Row> r = {
      {"add_inf", "x + y", {{1.5, kInf}, {-2.5, kInf}, {1e30, -kInf}, {kInf, 3.0}, {-kInf, -7.0}}, Expect::Match, true},
      {"add_inf_minus_inf", "x + y", {{kInf, -kInf}, {-kInf, kInf}}},
      {"sub_inf_inf", "x - y", {{kInf, kInf}, {-kInf, -kInf}, {kInf, -kInf}}, Expect::Match, true},
      {"add_nan", "x + y", {{kNaN, 1.0}, {1.0, kNaN}, {kNaN, kInf}}},
      {"mul_overflow", "x * y", {{1e20, 1e20}, {-1e20, 1e20}, {3e38, 2.0}, {1e30, -1e10}}, Expect::Match, true},
      {"mul_zero_inf", "x * y", {{0.0, kInf}, {-0.0, kInf}, {kInf, 0.0}}},
      {"mul_inf", "x * y", {{kInf, 2.5}, {-3.0, kInf}, {kInf, -kInf}}, Expect::Match, true},
      {"mul_nan", "x * y", {{kNaN, 2.0}, {2.0, kNaN}}},
      {"div_by_zero", "x / y", {{1.0, 0.0}, {1.0, -0.0}, {-2.5, 0.0}, {1e-30, -0.0}, {kInf, 0.0}}, Expect::Match, true},
      {"div_zero_zero", "x / y", {{0.0, 0.0}, {-0.0, 0.0}, {kInf, kInf}, {kNaN, 0.0}}},
      {"div_overflow", "x / y", {{1e30, 1e-30}, {-3e38, 0.5}}, Expect::Match, true},
      {"div_by_inf", "x / y", {{1.0, kInf}, {-1.0, kInf}, {1.0, -kInf}}, Expect::Match, true},
      {"div_nan", "x / y", {{kNaN, 1.0}, {1.0, kNaN}}},
      {"sqrt_negative", "sqrt(x)", {{-1.0, 0}, {-1e-30, 0}, {-kInf, 0}, {kNaN, 0}}},
      {"sqrt_zero", "sqrt(x)", {{0.0, 0}, {-0.0, 0}}, Expect::Match, true},
      {"sqrt_inf", "sqrt(x)", {{kInf, 0}}, Expect::Match, true},
      {"mul_near_max", "x * y",
       {{1.2345678901234e36, 0.25}, {3.0000000001e38, 1.0000001e-3}, {1.1e35, 1.3e-30}, {-2.9e38, 1.1}, {9e34, -3.3}},
       Expect::Match, true},
      // Operands whose 12-bit rounding would carry past FLT_MAX (|x| >= 0x7F7FF800, 3.4024e38): the
      // split by bits truncates them instead (rules/core.glsl); rounded, hi is Inf and the low word is lost.
      {"mul_at_max", "x * y",
       {{3.4027e38, 0.75}, {-3.40281e38, 0.3}, {0.6, 3.40275e38}, {1.0000001, -3.40269e38}, {3.4028e38, 1.0 / 3.0}}},
      {"square_near_max", "x * x", {{1.8e19, 0}, {-1.3e19, 0}, {1.0e35, 0}}, Expect::Match, true},
      {"div_near_max", "x / y", {{3.0000000001e38, 7.0}, {1.0, 1.0000003e36}, {1e36, 3.3e-2}, {2e38, 1.7e36}}, Expect::Match, true},
      {"sqrt_near_max", "sqrt(x)", {{3.0000000001e38, 0}, {1.0000000007e36, 0}}},
      {"add_near_max", "x + y", {{3e38, 3e37}, {3.4e38, -1e38}, {-3e38, -3e37}, {3.4028234e38, 1e30}}},
      {"add_beyond_max", "(x + y) * 0.5lf", {{3e38, 3e38}, {-3e38, -2e38}}, Expect::Saturates},
      {"mul_beyond_max", "(x * y) / y", {{1e30, 1e20}, {-1e25, 1e25}}, Expect::Saturates},
      {"tiny_lo_subnormal", "x * y", {{1.2345678e-20, 1e-15}, {3e-16, 3.3e-17}, {1.3e-19, 1.01e-13}}, Expect::Tiny},
      {"product_tiny_operand", "x * y", {{1.1e35, 1.3e-35}, {3.3e-36, 7.7e30}}, Expect::TinyOperand},
      {"below_float_min", "x * y", {{1e-20, 1e-20}, {-3e-21, 2e-19}}, Expect::Tiny},
      {"neg_signed_zero", "-x", {{0.0, 0}, {-0.0, 0}}, Expect::Match, false, true},
      {"add_signed_zero", "x + y", {{-0.0, -0.0}, {-0.0, 0.0}, {0.0, -0.0}, {1.5, -1.5}}, Expect::Match, true, true},
      {"sub_signed_zero", "x - y", {{-0.0, 0.0}, {0.0, 0.0}, {1.5, 1.5}, {0.0, -0.0}}, Expect::Match, true, true},
      {"mul_signed_zero", "x * y", {{-0.0, 5.0}, {-3.0, 0.0}, {-0.0, -2.0}, {1e-30, -1e-30}}, Expect::Match, true, true},
      {"div_signed_zero", "x / y", {{-0.0, 3.0}, {0.0, -3.0}}, Expect::Match, true, true},
      {"to_float_saturates", "double(float(x * y))", {{1e20, 1e20}, {-1e20, 1e20}, {3.4e38, 1.0000001}}, Expect::Match, true},
      {"to_float_rounds", "double(float(x + y))",
       {{1.0, 0x1p-24 + 0x1p-40}, {1.0, 0x1p-24}, {1.0, -0x1p-25 - 0x1p-45}, {3.4028234663852886e38, 1e30}}},
      {"to_float_signed_zero", "double(float(x))", {{-0.0, 0}, {0.0, 0}}, Expect::Match, true, true},
      // x / y with y = 0 gives an infinity whose lo word is 0 (df_finish), an input Inf a NaN lo.
      // fract_inf and floor_ceil_signed_zero failed with the rules of commit 35e5576, before
      // df_floor/df_ceil/df_fract ended in df_finish (the 16ff2c0 baseline gives NaN for x / 0,
      // so fract_inf cannot be one of its flagged rows).
      {"floor_inf", "floor(x / y)", {{1.0, 0.0}, {-1.0, 0.0}, {kInf, 1.0}, {kNaN, 1.0}}},
      {"ceil_inf", "ceil(x / y)", {{1.0, 0.0}, {-1.0, 0.0}, {-kInf, 1.0}}},
      {"trunc_round_inf", "trunc(x / y) + round(x / y)", {{1.0, 0.0}, {-1.0, 0.0}}},
      {"round_even_inf", "roundEven(x / y)", {{1.0, 0.0}, {-1.0, 0.0}}},
      {"fract_inf", "fract(x / y)", {{1.0, 0.0}, {-1.0, 0.0}, {kInf, 1.0}, {2.0, 1.0}, {-3.0, 1.0}}},
      {"floor_ceil_signed_zero", "floor(x) * ceil(y)", {{-0.0, 2.0}, {2.0, -0.0}, {0.0, -0.5}, {-0.0, -0.0}, {0.0, -0x1.fffffff8p-1}},
       Expect::Match, true},
      {"compare_nan", "(x < y ? 1.0lf : 0.0lf) + (x == y ? 2.0lf : 0.0lf) + (x != y ? 4.0lf : 0.0lf) + (x >= y ? 8.0lf : 0.0lf)",
       {{kNaN, 1.0}, {1.0, kNaN}, {kNaN, kNaN}, {1.0, 1.0}}},
      {"compare_self_nan", "(x != x ? 1.0lf : 0.0lf) + (x == x ? 2.0lf : 0.0lf)", {{kNaN, 0}, {1.0, 0}}},
      {"isnan_isinf", "(isnan(x) ? 1.0lf : 0.0lf) + (isinf(x) ? 2.0lf : 0.0lf)", {{kNaN, 0}, {kInf, 0}, {-kInf, 0}, {1.0, 0}}},
      // Issue 13. ldexp beyond float range: (Inf, 0), never (Inf, -Inf) (whose words add to NaN,
      // and which compares unequal to an infinity); exponents beyond +-254 are not clamped.
      {"ldexp_overflow_is_inf", "ldexp(x, int(y)) == ldexp(sign(x), int(y)) ? 1.0lf : 0.0lf",
       {{1.0 - 0x1p-30, 1100}, {-1.0 + 0x1p-30, 1100}, {0x1.8p0 - 0x1p-40, 1030}}},
      {"ldexp_overflow", "ldexp(x, int(y))", {{1.0 - 0x1p-30, 1100}, {-1.0 + 0x1p-30, 1100}, {0x1p-100, 250}, {3e38, 1}}},
      {"ldexp_underflow", "ldexp(x, int(y))",
       {{0x1p120, -280}, {-0x1p120, -280}, {0x1.8p-100, -40}, {0x1.8p0 + 0x1p-30, -135}, {1.0, -160}}, Expect::Tiny},
      {"ldexp_from_subnormal", "ldexp(x, int(y))", {{0x1p-140, 270}, {-0x1.8p-140, 100}}},
      // round/roundEven/trunc/ceil of x in (-1, 0) and modf's fraction of a negative integer are -0.
      // (No halves in round's inputs: GLSL leaves their direction to the implementation.)
      {.name = "round_signed_zero", .expr = "round(x)",
       .inputs = {{-0.3, 0}, {-0.0, 0}, {0.3, 0}, {-0.7, 0}, {-1e-30, 0}, {-2.75, 0}},
       .ieee = [](double x, double) { return std::round(x); }},
      {.name = "round_even_signed_zero", .expr = "roundEven(x)",
       .inputs = {{-0.3, 0}, {-0.5, 0}, {-0.0, 0}, {0.5, 0}, {-1.5, 0}, {-1e-30, 0}},
       .ieee = [](double x, double) { return std::nearbyint(x); }},  // default rounding: ties to even
      {.name = "trunc_signed_zero", .expr = "trunc(x) + ceil(y)",
       .inputs = {{-0.3, -0.7}, {-0.0, -0.0}, {0.3, -0.2}, {-1e-30, -0.5}, {-2.5, 0.5}},
       .ieee = [](double x, double y) { return std::trunc(x) + std::ceil(y); }},
      {.name = "modf_fraction_signed_zero", .expr = "f",
       .inputs = {{-3.0, 0}, {3.0, 0}, {0.0, 0}, {-2.5, 0}, {-0.25, 0}, {-0x1p30 - 0x1p-10, 0}, {-0x1p40, 0}},
       .prelude = "double ip; double f = modf(x, ip);"},
      {.name = "modf_whole_signed_zero", .expr = "ip",
       .inputs = {{-3.0, 0}, {-0.25, 0}, {0.25, 0}, {-0x1p30 - 0x1p-10, 0}},
       .prelude = "double ip; double f = modf(x, ip);"},
      {.name = "modf_of_zero", .expr = "f * 2.0lf + ip", .inputs = {{-0.0, 0}, {0.0, 0}}, .expect = Expect::ZeroWithSignOfX,
       .prelude = "double ip; double f = modf(x, ip);"},
      // frexp: mantissa in [0.5, 1) and the exponent for tiny values; 0, -0, Inf, NaN as native.
      {.name = "frexp_mantissa", .expr = "m",
       .inputs = {{0x1p-120 - 0x1p-147, 0}, {-0x1.8p-126, 0}, {0.0, 0}, {-0.0, 0}, {3.0, 0}, {-0x1p-126, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      {.name = "frexp_exponent", .expr = "double(e)",
       .inputs = {{0x1p-120 - 0x1p-147, 0}, {-0x1.8p-126, 0}, {0.0, 0}, {-0.0, 0}, {3.0, 0}, {-0x1p-126, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      {.name = "frexp_subnormal_mantissa", .expr = "m", .inputs = {{1e-40, 0}, {-3e-42, 0}, {0x1p-149, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      {.name = "frexp_subnormal_exponent", .expr = "double(e)", .inputs = {{1e-40, 0}, {-3e-42, 0}, {0x1p-149, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      {.name = "frexp_special_mantissa", .expr = "m", .inputs = {{kInf, 0}, {-kInf, 0}, {kNaN, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      {.name = "frexp_special_exponent", .expr = "double(e)", .inputs = {{kInf, 0}, {-kInf, 0}, {kNaN, 0}},
       .prelude = "int e; double m = frexp(x, e);"},
      // length/normalize/distance across float's exponent range: the squares would leave it.
      {"length_large", "length(dvec3(x, y, x))", {{3e19, 4e19}, {-1e30, 2e30}, {1.5e38, 1e38}, {2e38, 3e38}, {1.0, 2.0}}},
      {"length_small", "length(dvec2(x, y))", {{3e-25, -4e-25}, {1e-30, 2e-30}, {1e-20, 1e-19}, {-1e-19, 0.0}, {0.0, 0.0}}},
      {"normalize_extremes", "normalize(dvec3(x, y, x)).y", {{3e19, -4e19}, {1e30, 2e30}, {3e-25, 4e-25}, {1e-35, -2e-35}, {1.0, 2.0}}},
      {"distance_extremes", "distance(dvec2(x, y), dvec2(y, x))", {{3e19, -4e19}, {1e-30, 3e-30}, {1e37, -1e37}}},
  };
  return r;
}

// ---- configurations ---------------------------------------------------------------------------

struct Config {
  const char* name;
  bool compute;
  GraphicsStage stage;  // when !compute
  Backend backend;
  doublet::Target target;
};

const std::vector<Config>& configs() {
  static const std::vector<Config> c = {
      {"compute_lavapipe_es310", true, GraphicsStage::Vertex, Backend::Vulkan, doublet::Target::Es310},
      {"compute_lavapipe_es320", true, GraphicsStage::Vertex, Backend::Vulkan, doublet::Target::Es320},
      {"compute_gles_es310", true, GraphicsStage::Vertex, Backend::Gles, doublet::Target::Es310},
      {"compute_gles_es320", true, GraphicsStage::Vertex, Backend::Gles, doublet::Target::Es320},
      {"fragment_lavapipe_es310", false, GraphicsStage::Fragment, Backend::Vulkan, doublet::Target::Es310},
      {"vertex_lavapipe_glsl450", false, GraphicsStage::Vertex, Backend::Vulkan, doublet::Target::Glsl450},
      {"fragment_gles_es320", false, GraphicsStage::Fragment, Backend::Gles, doublet::Target::Es320},
      {"vertex_gles_es310", false, GraphicsStage::Vertex, Backend::Gles, doublet::Target::Es310},
  };
  return c;
}

std::string shader(const Row& row, bool compute, GraphicsStage stage) {
  std::string s = "#version 450\n";
  std::string in = "v", out;
  if (compute) {
    s += "layout(local_size_x = 1) in;\n"
         "layout(std430, binding = 0) readonly buffer In { vec4 inputs[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Out { vec4 outputs[]; };\n";
    in = "inputs[gl_GlobalInvocationID.x]";
    out = "outputs[gl_GlobalInvocationID.x]";
  } else if (stage == GraphicsStage::Fragment) {
    s += "flat in vec4 v;\nlayout(location = 0) out vec4 o;\n";
    out = "o";
  } else {
    s += "in vec4 v;\nlayout(location = 0) out vec4 o;\n";
    out = "o";
  }
  s += "void main() {\n  vec4 w = " + in + ";\n";
  s += "  double x = double(w.x) + double(w.y);\n  double y = double(w.z) + double(w.w);\n";
  s += std::string("  ") + row.prelude + "\n";
  s += "  double r = " + std::string(row.expr) + ";\n";
  s += "  float hi = float(r);\n";
  s += "  " + out + " = vec4(hi, float(r - double(hi)), 0.0, 0.0);\n";
  if (!compute && stage == GraphicsStage::Vertex) s += "  gl_Position = vec4(0.0);\n";
  return s + "}\n";
}

// x as the float pair the shaders add up: a zero keeps its sign in both words (-0 + -0 = -0).
std::pair<float, float> pair_of(double x) {
  doublet::FloatPair p = doublet::split(x);
  if (p.lo == 0.0f) p.lo = std::copysign(0.0f, p.hi);
  return {p.hi, p.lo};
}

std::vector<float> packed_inputs(const Row& row) {
  std::vector<float> v;
  for (auto [x, y] : row.inputs) {
    auto a = pair_of(x), b = pair_of(y);
    v.insert(v.end(), {a.first, a.second, b.first, b.second});
  }
  return v;
}

// ---- sabotage: the previous rule text ----------------------------------------------------------

// The rule library of the .glsl files in `dir`, each file `dir` lacks taken from rules/ as it is
// (so a snapshot keeps only the files that changed); parsed once per directory.
const doublet::rules::RuleLibrary& library_in(const std::string& dir) {
  static std::map<std::string, doublet::rules::RuleLibrary> cache;
  auto it = cache.find(dir);
  if (it != cache.end()) return it->second;
  std::map<std::string, std::filesystem::path> sources;
  for (const std::string& from : {std::string(DOUBLET_RULES_DIR), dir})  // dir's files win
    for (const auto& e : std::filesystem::directory_iterator(from))
      if (e.path().extension() == ".glsl") sources[e.path().filename().string()] = e.path();
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& [name, path] : sources) {
    std::ifstream f(path);
    std::stringstream ss;
    ss << f.rdbuf();
    files.emplace_back(name, ss.str());
  }
  std::string error;
  auto parsed = doublet::rules::RuleLibrary::parse(files, &error);
  if (!parsed) {
    std::fprintf(stderr, "rules in %s do not parse: %s\n", dir.c_str(), error.c_str());
    std::abort();
  }
  return cache.emplace(dir, std::move(*parsed)).first->second;
}

// Replaces the emitted runtime (from its "// doublet float-float runtime" line to the last rule
// function) with `rules`' emission of the same user-called functions, at every width they have
// (the shader's vectors are dvec2 or dvec3; unused instances are harmless).
std::string splice_rules(const std::string& lowered, const doublet::rules::RuleLibrary& rules, bool precise,
                         std::string* error) {
  const size_t begin = lowered.find("// doublet float-float runtime");
  if (begin == std::string::npos) {
    *error = "no runtime in the lowered shader";
    return {};
  }
  // The runtime is a run of paragraphs (blank-line separated) of comments, struct and guard
  // lines and df_ functions. Functions that are no rule (the lowering's generated helpers, e.g.
  // df_make_dvec2_1_1) are kept, after the replacement runtime.
  size_t end = begin;
  const std::regex function(R"(^(\w+) (df_\w+)\()");
  std::string kept;
  auto is_rule = [](const std::string& name) {
    for (int width = 1; width <= 4; ++width)
      if (doublet::rules::RuleLibrary::builtin().has({name, width})) return true;
    return false;
  };
  while (end < lowered.size()) {
    size_t next = lowered.find("\n\n", end);
    if (next == std::string::npos) next = lowered.size();
    std::string para = lowered.substr(end, next - end);
    while (!para.empty() && para.front() == '\n') para.erase(0, 1);
    bool ok = para.rfind("// doublet float-float runtime", 0) == 0;
    if (!ok) {
      std::istringstream in(para);
      for (std::string line; std::getline(in, line);) {
        if (line.rfind("//", 0) == 0) continue;
        std::smatch m;
        ok = std::regex_search(line, m, function);
        if (ok && !is_rule(m[2])) kept += para + "\n\n";
        break;
      }
    }
    if (!ok) break;
    end = next == lowered.size() ? next : next + 1;
  }
  std::string before = lowered.substr(0, begin), after = lowered.substr(end);
  std::set<std::string> called;
  const std::regex call(R"(\b(df_\w+)\()");
  for (const std::string* part : {&before, &kept, &after})
    for (std::sregex_iterator it(part->begin(), part->end(), call), e; it != e; ++it) called.insert((*it)[1]);
  doublet::rules::EmitRequest req;
  for (const auto& name : called)
    for (int width = 1; width <= 4; ++width)
      if (rules.has({name, width})) req.used.push_back({name, width});
  req.guard = precise ? doublet::rules::GuardStyle::Precise : doublet::rules::GuardStyle::Uniform;
  // The guard as the lowered text declares it: the shader's constants read it too (guard-constants).
  req.indexed_guard = !precise && lowered.find("uniform highp float df_guard[2];") != std::string::npos;
  req.es_version = 320;
  auto emitted = rules.emit(req);
  if (!emitted.ok) {
    *error = emitted.error;
    return {};
  }
  std::string text = emitted.text;
  // Struct types already declared before the runtime stay declared once.
  for (const char* s : {"struct df_double { float hi; float lo; };\n"})
    if (before.find(s) != std::string::npos) {
      size_t at = text.find(s);
      if (at != std::string::npos) text.erase(at, std::strlen(s));
    }
  return before + text + "\n" + kept + after;
}

std::string add_guard(std::string text) {
  static const std::regex minus(R"(\) - (df_guard(\[int\(df_guard\[1\]\)\])?)\))");
  return std::regex_replace(text, minus, ") + $1)");
}

// ---- running --------------------------------------------------------------------------------

struct Outcome {
  std::string error;
  std::vector<std::pair<float, float>> results;  // (float(r), float(r - float(r))) per input
};

Outcome run(const Row& row, const Config& c, bool native, Sabotage sabotage, doublet::Mode mode) {
  Outcome o;
  const std::string source = shader(row, c.compute, c.stage);
  std::string glsl = source;
  Backend backend = native ? Backend::Vulkan : c.backend;
  if (!native) {
    doublet::Options opt;
    opt.stage = c.compute ? doublet::Stage::Compute
                          : (c.stage == GraphicsStage::Vertex ? doublet::Stage::Vertex : doublet::Stage::Fragment);
    opt.target = c.target;
    opt.file_name = std::string(row.name) + ".glsl";
    opt.mode = mode;
    // The previous rules predate the whole-shader optimizer's substitutes (rules/opt.glsl).
    if (sabotage == Sabotage::BaselineRules || sabotage == Sabotage::RulesBeforeIssue13) opt.optimize = false;
    auto lowered = doublet::lower(source, opt);
    if (!lowered.ok) {
      for (const auto& d : lowered.diagnostics) o.error += doublet::format_diagnostic(d) + "\n";
      return o;
    }
    glsl = lowered.output;
    const bool precise = lowered.manifest.guard.kind == "precise";
    if (sabotage == Sabotage::BaselineRules)
      glsl = splice_rules(glsl, library_in(DOUBLET_EXTREMES_BASELINE_DIR), precise, &o.error);
    if (sabotage == Sabotage::RulesBeforeIssue13)
      glsl = splice_rules(glsl, library_in(DOUBLET_EXTREMES_BEFORE_ISSUE13_DIR), precise, &o.error);
    if (sabotage == Sabotage::AddGuard) glsl = add_guard(glsl);
    if (!o.error.empty()) return o;
  }
  const std::vector<float> in = packed_inputs(row);
  const uint32_t n = static_cast<uint32_t>(row.inputs.size());
  if (c.compute) {
    doublet::runner::ComputeJob job;
    job.glsl = glsl;
    job.buffers.resize(2);
    job.buffers[0].resize(in.size() * sizeof(float));
    std::memcpy(job.buffers[0].data(), in.data(), job.buffers[0].size());
    job.buffers[1].assign(n * 4 * sizeof(float), 0);
    job.groups_x = n;
    auto r = doublet::runner::run_compute(backend, job);
    if (!r.ok) {
      o.error = r.error + "\n--- shader ---\n" + glsl;
      return o;
    }
    std::vector<float> out(n * 4);
    std::memcpy(out.data(), r.buffers[1].data(), out.size() * sizeof(float));
    for (uint32_t i = 0; i < n; ++i) o.results.push_back({out[i * 4], out[i * 4 + 1]});
  } else {
    doublet::runner::GraphicsJob job;
    job.stage = c.stage;
    job.glsl = glsl;
    job.count = n;
    job.inputs["v"] = std::vector<double>(in.begin(), in.end());
    auto r = doublet::runner::run_graphics(backend, job);
    if (!r.ok) {
      o.error = r.error + "\n--- shader ---\n" + glsl;
      return o;
    }
    const auto& out = r.outputs["o"];
    for (uint32_t i = 0; i < n; ++i)
      o.results.push_back({static_cast<float>(out[i * 4]), static_cast<float>(out[i * 4 + 1])});
  }
  return o;
}

std::string describe(float hi, float lo) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%a, %a)", static_cast<double>(hi), static_cast<double>(lo));
  return buf;
}

// Empty when the lowered result `got` is what `want` (native) implies for this row.
std::string judge(Expect expect, bool compute, double x, std::pair<float, float> want, std::pair<float, float> got) {
  const float wh = want.first, gh = got.first;
  // The value: hi alone when it is not finite (r - Inf is NaN), else hi + lo.
  auto value = [](std::pair<float, float> p) {
    return std::isfinite(p.first) ? double(p.first) + double(p.second) : double(p.first);
  };
  const double w = value(want), g = value(got);
  const std::string seen = "native " + describe(want.first, want.second) + ", lowered " + describe(got.first, got.second);
  if (expect == Expect::ZeroWithSignOfX)
    return g == 0 && std::signbit(gh) == std::signbit(x) ? "" : "expected a zero with the sign of x: " + seen;
  if (std::isnan(wh)) return std::isnan(gh) ? "" : "expected NaN: " + seen;
  if (std::isinf(wh)) return gh == wh ? "" : "expected the same infinity: " + seen;
  if (expect == Expect::Saturates) {
    // Native keeps a finite value that float-float cannot hold: it must saturate to Inf.
    return std::isinf(gh) && std::signbit(gh) == std::signbit(wh) ? "" : "expected +-Inf (beyond float range): " + seen;
  }
  if (std::isnan(gh) || std::isinf(gh)) return "expected a finite value: " + seen;
  if (w == 0) {
    if (expect == Expect::Tiny && !compute && std::fabs(g) <= 0x1p-126) return "";
    return g == 0 && std::signbit(gh) == std::signbit(wh) ? "" : "expected a zero of the same sign: " + seen;
  }
  double tolerance = std::fabs(w) * 0x1p-44;
  if (expect == Expect::Tiny) tolerance = compute ? std::fabs(w) * 0x1p-44 + 0x1p-146 : std::fabs(w) * 0x1p-23 + 0x1p-126;
  if (expect == Expect::TinyOperand && !compute) tolerance = std::fabs(w) * 0x1p-11;
  if (std::signbit(gh) != std::signbit(wh) && g != 0) return "sign differs: " + seen;
  return std::fabs(g - w) <= tolerance ? "" : "value differs beyond tolerance: " + seen;
}

// Failures of one row in one configuration ("" when it matches).
std::string check(const Row& row, const Config& c, Sabotage sabotage, doublet::Mode mode = doublet::Mode::Df64) {
  static std::map<std::string, Outcome> native_cache;
  const std::string key = std::string(row.name) + (c.compute ? "/comp" : c.stage == GraphicsStage::Vertex ? "/vert" : "/frag");
  auto it = native_cache.find(key);
  const bool first_native_run = it == native_cache.end();  // native's disagreements are told once
  if (first_native_run) it = native_cache.emplace(key, run(row, c, true, Sabotage::None, doublet::Mode::Df64)).first;
  const Outcome& native = it->second;
  if (!native.error.empty()) return "native fp64 run failed: " + native.error;
  Outcome lowered = run(row, c, false, sabotage, mode);
  if (!lowered.error.empty()) return "lowered run failed: " + lowered.error;
  std::string failures;
  for (size_t i = 0; i < row.inputs.size(); ++i) {
    std::pair<float, float> want = native.results[i];
    if (row.ieee) {
      const auto [x, y] = row.inputs[i];
      const auto xs = pair_of(x), ys = pair_of(y);  // the inputs as the shader receives them
      want = pair_of(row.ieee(double(xs.first) + xs.second, double(ys.first) + ys.second));
      if (first_native_run && !judge(Expect::Match, c.compute, x, want, native.results[i]).empty())
        std::printf("[ extremes ] %s x=%a y=%a: native fp64 gives %s, IEEE 754 %s (the reference here)\n", row.name,
                    x, y, describe(native.results[i].first, native.results[i].second).c_str(),
                    describe(want.first, want.second).c_str());
    }
    std::string f = judge(row.expect, c.compute, row.inputs[i].first, want, lowered.results[i]);
    if (!f.empty() && row.ieee) f += " (\"native\" here is the host's IEEE 754 result)";
    if (!f.empty()) {
      char in[96];
      std::snprintf(in, sizeof in, "x=%a y=%a: ", row.inputs[i].first, row.inputs[i].second);
      failures += std::string("  ") + c.name + " " + in + f + "\n";
    }
  }
  return failures;
}

class Extremes : public ::testing::TestWithParam<Row> {};

// One row of docs/extremes.md: every configuration (compute and vertex/fragment, lavapipe and
// GLES, uniform guard and precise) behaves as the row says, against native fp64.
TEST_P(Extremes, BehavesLikeNativeFp64) {
  for (Backend b : {Backend::Vulkan, Backend::Gles})
    ASSERT_EQ(doublet::runner::backend_unavailable_reason(b), "") << doublet::runner::backend_name(b);
  std::string failures;
  for (const auto& c : configs()) failures += check(GetParam(), c, Sabotage::None);
  EXPECT_EQ(failures, "") << GetParam().expr;
}

// The same row under --mode df64-int (integer error terms, no guard; docs/modes.md): every
// configuration, as df64.
TEST_P(Extremes, Df64IntBehavesLikeNativeFp64) {
  std::string failures;
  for (const auto& c : configs()) failures += check(GetParam(), c, Sabotage::None, doublet::Mode::Df64Int);
  EXPECT_EQ(failures, "") << GetParam().expr;
}

INSTANTIATE_TEST_SUITE_P(Rows, Extremes, ::testing::ValuesIn(rows()),
                         [](const auto& info) { return std::string(info.param.name); });

// The rows the special-value handling fixed fail with the previous rule text: the tests can fail.
TEST(ExtremesSabotage, PreviousRulesTurnTheFixedRowsRed) {
  int red = 0, flagged = 0;
  std::string still_green;
  for (const auto& row : rows()) {
    if (!row.red_with_baseline) continue;
    ++flagged;
    std::string failures;
    for (const auto& c : configs()) failures += check(row, c, Sabotage::BaselineRules);
    if (failures.find("lowered run failed") != std::string::npos) ADD_FAILURE() << failures;
    if (!failures.empty()) {
      ++red;
      std::printf("%s with the previous rules: %s", row.name, failures.substr(0, failures.find('\n') + 1).c_str());
    } else {
      still_green += std::string(row.name) + " ";
    }
  }
  std::printf("previous rules: %d of %d flagged rows red\n", red, flagged);
  EXPECT_EQ(still_green, "") << "rows that should fail with the previous rules but pass";
}

// The rows issue 13 fixed fail with the rules before it (tests/extremes/rules_before_issue13/).
TEST(ExtremesSabotage, RulesBeforeIssue13TurnItsRowsRed) {
  const std::set<std::string> fixed = {
      "ldexp_overflow_is_inf", "ldexp_underflow", "ldexp_from_subnormal", "round_signed_zero",
      "round_even_signed_zero", "modf_fraction_signed_zero", "modf_of_zero", "frexp_mantissa",
      "frexp_subnormal_mantissa", "frexp_subnormal_exponent", "frexp_special_exponent",
      "length_large", "length_small", "normalize_extremes", "distance_extremes"};
  int red = 0;
  std::string still_green;
  for (const auto& row : rows()) {
    if (!fixed.count(row.name)) continue;
    std::string failures;
    for (const auto& c : configs()) failures += check(row, c, Sabotage::RulesBeforeIssue13);
    if (failures.find("lowered run failed") != std::string::npos) ADD_FAILURE() << failures;
    if (!failures.empty()) {
      ++red;
      std::printf("%s with the rules before issue 13: %s", row.name, failures.substr(0, failures.find('\n') + 1).c_str());
    } else {
      still_green += std::string(row.name) + " ";
    }
  }
  std::printf("rules before issue 13: %d of %zu rows red\n", red, fixed.size());
  EXPECT_EQ(still_green, "") << "rows that should fail with the rules before issue 13 but pass";
}

// Adding the uniform guard's zero (x + 0) instead of subtracting it loses the sign of -0.
TEST(ExtremesSabotage, AddingTheGuardZeroTurnsSignedZeroRowsRed) {
  int red = 0, flagged = 0;
  std::string still_green;
  for (const auto& row : rows()) {
    if (!row.red_with_add_guard) continue;
    ++flagged;
    std::string failures;
    for (const auto& c : configs())
      if (c.target == doublet::Target::Es310) failures += check(row, c, Sabotage::AddGuard);
    if (!failures.empty()) {
      ++red;
      std::printf("%s with x + guard: %s", row.name, failures.substr(0, failures.find('\n') + 1).c_str());
    } else {
      still_green += std::string(row.name) + " ";
    }
  }
  std::printf("x + guard: %d of %d flagged rows red\n", red, flagged);
  EXPECT_EQ(still_green, "");
}

// Values outside float-float range are diagnosed at compile time, not silently Inf or 0.
TEST(ExtremesConstants, OutOfRangeConstantsAreDiagnosed) {
  for (const char* literal : {"1e100lf", "-1e39lf", "1e+309"}) {
    std::string src = std::string("#version 450\nlayout(local_size_x = 1) in;\n"
                                  "layout(std430, binding = 0) buffer B { vec2 o; };\n"
                                  "void main() {\n  double x = double(o.x);\n  double r = x * ") +
                      literal + ";\n  o = vec2(float(r), 0.0);\n}\n";
    doublet::Options opt;
    opt.stage = doublet::Stage::Compute;
    opt.target = doublet::Target::Es310;
    opt.file_name = "range.comp";
    auto r = doublet::lower(src, opt);
    EXPECT_FALSE(r.ok) << literal;
    bool located = false;
    for (const auto& d : r.diagnostics)
      if (d.severity == doublet::Severity::Error && d.line == 6 && d.column > 0) located = true;
    EXPECT_TRUE(located) << literal << ": no error at line 6 with a column";
  }
}

// Host split helpers report values outside float range (include/doublet/split.hpp).
TEST(ExtremesHostSplit, SplitCheckedReportsOutOfRange) {
  doublet::FloatPair p;
  EXPECT_EQ(doublet::split_checked(1e39, p), doublet::SplitStatus::Overflow);
  EXPECT_TRUE(std::isinf(p.hi) && p.hi > 0 && p.lo == 0);
  EXPECT_EQ(doublet::split_checked(-1e100, p), doublet::SplitStatus::Overflow);
  EXPECT_TRUE(std::isinf(p.hi) && p.hi < 0 && p.lo == 0);
  EXPECT_EQ(doublet::split_checked(1e-300, p), doublet::SplitStatus::Underflow);
  EXPECT_EQ(doublet::split_checked(1e-40, p), doublet::SplitStatus::Underflow);
  // 1 + 2^-25 + 2^-52: hi = 1, and lo would need the 28 bits from 2^-25 to 2^-52.
  EXPECT_EQ(doublet::split_checked(1.0 + 0x1p-25 + 0x1p-52, p), doublet::SplitStatus::Rounded);
  EXPECT_EQ(doublet::split_checked(1.5, p), doublet::SplitStatus::Exact);
  EXPECT_EQ(doublet::split_checked(kInf, p), doublet::SplitStatus::Exact);
  EXPECT_TRUE(std::isinf(p.hi) && p.lo == 0);
  EXPECT_EQ(doublet::split_checked(kNaN, p), doublet::SplitStatus::Exact);
  EXPECT_TRUE(std::isnan(p.hi));
  EXPECT_EQ(doublet::split_checked(-0.0, p), doublet::SplitStatus::Exact);
  EXPECT_TRUE(p.hi == 0 && std::signbit(p.hi));
  // Just below FLT_MAX + half an ulp still rounds to FLT_MAX (finite); the join is the value.
  EXPECT_EQ(doublet::split_checked(static_cast<double>(FLT_MAX) + 0x1p100, p), doublet::SplitStatus::Exact);
  EXPECT_EQ(p.hi, FLT_MAX);
}

// join() keeps the sign of a zero: (-0, +0) is -0 (verify joins every lowered output with it).
TEST(ExtremesHostSplit, JoinKeepsTheSignOfZero) {
  EXPECT_TRUE(std::signbit(doublet::join(-0.0f, 0.0f)));
  EXPECT_TRUE(std::signbit(doublet::join(-0.0f, -0.0f)));
  EXPECT_FALSE(std::signbit(doublet::join(0.0f, -0.0f)));
  EXPECT_EQ(doublet::join(1.0f, -0x1p-30f), 1.0 - 0x1p-30);
  EXPECT_TRUE(std::signbit(doublet::join(doublet::split(-0.0))));
  const float hi[] = {-0.0f, 2.0f}, lo[] = {0.0f, 0x1p-25f};
  double x[2];
  doublet::join(hi, lo, x);
  EXPECT_TRUE(std::signbit(x[0]));
  EXPECT_EQ(x[1], 2.0 + 0x1p-25);
}

}  // namespace
