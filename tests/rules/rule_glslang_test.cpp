// Every rule x width x guard style x target: emitted into a tiny shader that calls it and
// re-validated by the real glslang front end in that target's profile and version.
#include <gtest/gtest.h>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <mutex>
#include <sstream>

#include "emitted_glsl.hpp"
#include "rules/rule_library.hpp"

namespace doublet::rules {
namespace {

struct Target {
  const char* name;
  const char* version_line;
  int version;
  EProfile profile;
  int es_version;  // what the compiler passes in EmitRequest (desktop: 320)
};

const Target kTargets[] = {
    {"es100", "#version 100", 100, EEsProfile, 100},   {"es300", "#version 300 es", 300, EEsProfile, 300},
    {"es310", "#version 310 es", 310, EEsProfile, 310}, {"es320", "#version 320 es", 320, EEsProfile, 320},
    {"glsl330", "#version 330", 330, ECoreProfile, 320}, {"glsl450", "#version 450", 450, ECoreProfile, 320},
};

// `precise` exists in ES 3.20 and GLSL 4.00+; ES 3.10 gets it from GL_EXT_gpu_shader5.
// ES 1.00/3.00 have no way to say it, and glslang 12 does not accept it in GLSL 3.30 even with
// GL_ARB_gpu_shader5 ("undeclared identifier"): those targets use the Uniform guard.
const char* precise_extension(const Target& t) {
  return t.version == 310 ? "#extension GL_EXT_gpu_shader5 : require\n" : "";
}
bool precise_possible(const Target& t) { return t.version >= 310 && t.version != 330; }

const char* guard_name(GuardStyle g) {
  return g == GuardStyle::Precise ? "precise" : g == GuardStyle::Uniform ? "uniform" : "none";
}

bool glslang_parses(const std::string& source, const Target& t, std::string* log) {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
  glslang::TShader shader(EShLangVertex);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  const bool ok = shader.parse(GetDefaultResources(), t.version, t.profile, false, false, EShMsgDefault);
  *log = shader.getInfoLog();
  return ok;
}

std::string caller_shader(const Target& t, GuardStyle g, const std::string& rules,
                          const test::EmittedFunction& f, bool exact_words) {
  std::ostringstream s;
  s << t.version_line << "\n";
  if (g == GuardStyle::Precise) s << precise_extension(t);
  if (t.profile == EEsProfile) s << "precision highp float;\nprecision highp int;\n";
  s << rules << "\nvoid main() {\n";
  // `out` parameters need an lvalue: a local of the parameter's type.
  for (size_t i = 0; i < f.params.size(); ++i)
    if (f.params[i].first.rfind("out ", 0) == 0) s << "  " << f.params[i].first.substr(4) << " out" << i << ";\n";
  s << "  " << f.ret << " r = " << f.name << "(";
  for (size_t i = 0; i < f.params.size(); ++i)
    s << (i ? ", " : "")
      << (f.params[i].first.rfind("out ", 0) == 0 ? "out" + std::to_string(i) : test::sample_value(f.params[i].first, exact_words));
  s << ");\n  gl_Position = vec4(0.0);\n}\n";
  return s.str();
}

// The lowest ES version any chunk of `name` declares with @min-es.
int min_es(const std::string& name) {
  int v = 100;
  for (const auto& info : RuleLibrary::builtin().info())
    if (info.name == name && info.variant.empty()) v = std::max(v, info.min_es);
  return v;
}

class RuleCompiles : public ::testing::TestWithParam<std::tuple<int, GuardStyle>> {};

TEST_P(RuleCompiles, EveryRuleAndWidth) {
  const Target& t = kTargets[std::get<0>(GetParam())];
  const GuardStyle g = std::get<1>(GetParam());
  const RuleLibrary& lib = RuleLibrary::builtin();
  int compiled = 0, refused = 0;
  for (const auto& ref : lib.all()) {
    SCOPED_TRACE(ref.name + " width " + std::to_string(ref.width) + " " + t.name + " guard " + guard_name(g));
    EmitRequest req;
    req.used = {ref};
    req.guard = g;
    req.es_version = t.es_version;
    req.exact_words = ref.name.rfind("ex_", 0) == 0;  // rules/exact.glsl: uint words
    // What the compiler passes: umulExtended/findMSB variants where the target has them.
    req.integer_functions = t.version >= 310 && t.version != 330;
    EmitResult r = lib.emit(req);
    if (min_es(ref.name) > 100) {
      if (t.es_version < min_es(ref.name)) {
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.error.find("is not available on ES 1.00"), std::string::npos) << r.error;
        ++refused;
        continue;
      }
    }
    ASSERT_TRUE(r.ok) << r.error;
    auto fns = test::split_functions(r.text);
    ASSERT_FALSE(fns.empty());
    const std::string source = caller_shader(t, g, r.text, fns.back(), req.exact_words);
    std::string log;
    EXPECT_TRUE(glslang_parses(source, t, &log)) << log << "\n" << source;
    ++compiled;
  }
  EXPECT_GT(compiled, 80);
  RecordProperty("compiled", compiled);
  RecordProperty("refused", refused);
  std::cout << "[ info ] " << t.name << " guard " << guard_name(g) << ": " << compiled << " shaders parsed, "
            << refused << " refused\n";
}

// df64-int (rules/int.glsl): the same rules with the integer EFTs swapped in parse on every
// ES 3.00+ and desktop target, in every guard style; ES 1.00 has no uint and refuses them.
TEST_P(RuleCompiles, EveryRuleAndWidthWithIntegerEfts) {
  const Target& t = kTargets[std::get<0>(GetParam())];
  const GuardStyle g = std::get<1>(GetParam());
  const RuleLibrary& lib = RuleLibrary::builtin();
  int compiled = 0, with_int = 0;
  for (const auto& ref : lib.all()) {
    if (ref.name.rfind("ex_", 0) == 0) continue;  // mode exact's rules: no float EFTs to swap
    SCOPED_TRACE(ref.name + " width " + std::to_string(ref.width) + " " + t.name + " guard " + guard_name(g));
    EmitRequest req;
    req.used = {ref};
    req.guard = g;
    req.es_version = t.es_version;
    req.integer_eft = true;
    EmitResult r = lib.emit(req);
    if (t.es_version < 300) {
      if (!r.ok) EXPECT_NE(r.error.find("is not available on ES 1.00"), std::string::npos) << r.error;
      continue;
    }
    ASSERT_TRUE(r.ok) << r.error;
    if (ref.name != "df_split")  // only asked for by name: nothing in df64-int calls it
      EXPECT_EQ(r.text.find("4097.0"), std::string::npos) << "a float Veltkamp split in df64-int";
    if (r.text.find("df_int_") != std::string::npos) ++with_int;
    auto fns = test::split_functions(r.text);
    ASSERT_FALSE(fns.empty());
    const std::string source = caller_shader(t, g, r.text, fns.back(), false);
    std::string log;
    EXPECT_TRUE(glslang_parses(source, t, &log)) << log << "\n" << source;
    ++compiled;
  }
  if (t.es_version >= 300) {
    EXPECT_GT(compiled, 80);
    EXPECT_GT(with_int, 60);
  }
}

// The guard really matters to glslang: without the extension, `precise` is not a keyword in
// ES 3.10, so the Precise output must be rejected there (the matrix above is not vacuous).
TEST(RuleCompilesNegative, PreciseNeedsExtensionOnEs310) {
  const Target& t = kTargets[2];
  EmitRequest req;
  req.used = {{"df_add", 1}};
  req.guard = GuardStyle::Precise;
  EmitResult r = RuleLibrary::builtin().emit(req);
  ASSERT_TRUE(r.ok);
  auto fns = test::split_functions(r.text);
  std::string source = caller_shader(t, GuardStyle::None, r.text, fns.back(), false);
  std::string log;
  EXPECT_FALSE(glslang_parses(source, t, &log)) << source;
}

TEST(RuleCompilesNegative, GlslangRejectsBrokenShader) {
  std::string log;
  EXPECT_FALSE(glslang_parses("#version 100\nvoid main() { uint x = 1u; }\n", kTargets[0], &log));
}

std::string param_name(const ::testing::TestParamInfo<std::tuple<int, GuardStyle>>& info) {
  return std::string(kTargets[std::get<0>(info.param)].name) + "_" + guard_name(std::get<1>(info.param));
}

// Every target with every guard it can express: `precise` needs ES 3.10+ or desktop 4.00+
// (the compiler refuses it elsewhere, which tests/unit checks), so no test is skipped.
std::vector<std::tuple<int, GuardStyle>> target_guard_pairs() {
  std::vector<std::tuple<int, GuardStyle>> pairs;
  for (int t = 0; t < 6; ++t)
    for (GuardStyle g : {GuardStyle::Precise, GuardStyle::Uniform, GuardStyle::None})
      if (g != GuardStyle::Precise || precise_possible(kTargets[t])) pairs.emplace_back(t, g);
  return pairs;
}

INSTANTIATE_TEST_SUITE_P(AllTargets, RuleCompiles, ::testing::ValuesIn(target_guard_pairs()), param_name);

}  // namespace
}  // namespace doublet::rules
