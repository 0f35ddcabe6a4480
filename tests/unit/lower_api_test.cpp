// Library-level tests of doublet::lower: diagnostics, literal splitting,
// interface splitting and the manifest, guard choice, determinism.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <random>
#include <regex>

#include "doublet/doublet.hpp"
#include "emit/printer.hpp"
#include "frontend/frontend.hpp"

namespace {

doublet::Result lower(const std::string& source, doublet::Stage stage = doublet::Stage::Vertex,
                      doublet::Target target = doublet::Target::Es300) {
  doublet::Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "shader.glsl";
  return doublet::lower(source, o);
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

TEST(Diagnostics, SyntaxErrorPointsAtFileLineAndColumn) {
  auto r = lower("#version 300 es\nvoid main() {\n  double x = 1.0lf\n  x = 2.0lf;\n}\n");
  ASSERT_FALSE(r.ok);
  EXPECT_TRUE(r.output.empty());
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].file, "shader.glsl");
  EXPECT_EQ(r.diagnostics[0].line, 4);
  EXPECT_EQ(r.diagnostics[0].column, 3);
  EXPECT_TRUE(std::regex_search(doublet::format_diagnostic(r.diagnostics[0]),
                                std::regex(R"(^shader\.glsl:4:3: error: .*syntax error)")))
      << messages(r);
}

TEST(Diagnostics, UnknownIdentifierColumnIsTheIdentifier) {
  auto r = lower("#version 300 es\nvoid main() {\n  double x = 1.0lf;\n  x = yy + 2.0lf;\n}\n");
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].line, 4);
  EXPECT_EQ(r.diagnostics[0].column, 7);
  EXPECT_NE(r.diagnostics[0].message.find("'yy'"), std::string::npos) << messages(r);
}

TEST(Diagnostics, EmptyAndBinaryInputsAreErrorsNotCrashes) {
  for (std::string input : {std::string(""), std::string("   \n\n"), std::string("\x7f" "ELF\x02\x01\x01\0\0\0", 10),
                            std::string("\xff\xfe\xfd garbage ((((")}) {
    auto r = lower(input);
    EXPECT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].severity, doublet::Severity::Error);
    EXPECT_GE(r.diagnostics[0].line, 1) << messages(r);
  }
}

TEST(Diagnostics, ReservedPrefixIsRejected) {
  auto r = lower("#version 300 es\nuniform double df_x;\nvoid main() { gl_Position = vec4(float(df_x)); }\n");
  ASSERT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("reserves"), std::string::npos) << messages(r);
}

TEST(Diagnostics, MissingStageIsReported) {
  doublet::Options o;
  auto r = doublet::lower("void main() {}", o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("stage"), std::string::npos);
}

// The literal 0.1lf becomes hi + lo with hi = float(0.1) and lo = float(0.1 - hi) != 0.
TEST(Literals, DoubleLiteralsAreSplitExactly) {
  for (double value : {0.1, 6378137.0, 3.986004418e14, 1.0 / 3.0, -2.5e-7}) {
    char literal[64];
    std::snprintf(literal, sizeof literal, "%.17e", value);
    std::string src = std::string("#version 300 es\nout vec2 parts;\nvoid main() {\n  double x = ") + literal +
                      "lf;\n  parts = vec2(float(x), float(x - double(float(x))));\n  gl_Position = vec4(0.0);\n}\n";
    auto r = lower(src);
    ASSERT_TRUE(r.ok) << messages(r);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex(R"(df_double x = df_double\(([^,]+), ([^)]+)\))"))) << r.output;
    float hi = std::strtof(m[1].str().c_str(), nullptr), lo = std::strtof(m[2].str().c_str(), nullptr);
    EXPECT_EQ(hi, static_cast<float>(value)) << literal;
    EXPECT_EQ(lo, static_cast<float>(value - static_cast<double>(static_cast<float>(value)))) << literal;
    // 6378137 fits a float exactly (< 2^24); the others need lo.
    if (static_cast<double>(static_cast<float>(value)) != value)
      EXPECT_NE(lo, 0.0f) << literal << ": lo must carry the bits float cannot";
  }
}

TEST(Printer, FloatLiteralsReadBackExactly) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<uint32_t> bits;
  for (int i = 0; i < 20000; ++i) {
    uint32_t b = bits(rng);
    float f;
    std::memcpy(&f, &b, sizeof f);
    if (!std::isfinite(f)) continue;
    std::string lit = doublet::emit::float_literal(f);
    EXPECT_EQ(std::strtof(lit.c_str(), nullptr), f) << lit;
    EXPECT_NE(lit.find_first_of(".e"), std::string::npos) << lit << " would read as an int";
  }
}

TEST(Interfaces, DoubleInterfacesSplitIntoHiAndLoWithManifest) {
  auto r = lower(
      "#version 300 es\nlayout(location = 0) in dvec3 position;\nlayout(location = 2) in vec2 uv;\n"
      "uniform dvec3 eye;\nuniform mat4 viewProj;\n"
      "void main() { gl_Position = viewProj * vec4(vec3(position - eye), uv.x); }\n");
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("layout(location = 0) in vec3 position_hi;"), std::string::npos) << r.output;
  // dvec3 at 0 used locations 0-1 and uv uses 2: lo goes to the first free one.
  EXPECT_NE(r.output.find("layout(location = 3) in vec3 position_lo;"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("uniform vec3 eye_hi;"), std::string::npos);
  EXPECT_NE(r.output.find("uniform vec3 eye_lo;"), std::string::npos);
  std::string code = std::regex_replace(r.output, std::regex(R"(//[^\n]*)"), "");
  EXPECT_FALSE(std::regex_search(code, std::regex(R"(\b(double|dvec[234])\b)"))) << r.output;
  auto j = nlohmann::json::parse(r.manifest.to_json());
  ASSERT_EQ(j["variables"].size(), 4u);
  EXPECT_EQ(j["variables"][0]["name"], "position");
  EXPECT_EQ(j["variables"][0]["type"], "dvec3");
  EXPECT_EQ(j["variables"][0]["lowered_names"], nlohmann::json::array({"position_hi", "position_lo"}));
  EXPECT_EQ(j["variables"][0]["locations"], nlohmann::json::array({0, 3}));
  EXPECT_EQ(j["variables"][1]["split"], false);
  EXPECT_EQ(j["guard"]["kind"], "uniform");
  EXPECT_EQ(j["guard"]["uniform"], "df_guard");
}

TEST(Interfaces, SuffixesAreConfigurableAndClashesDiagnosed) {
  doublet::Options o;
  o.stage = doublet::Stage::Vertex;
  o.hi_suffix = "High";
  o.lo_suffix = "Low";
  auto r = doublet::lower("#version 300 es\nin double h;\nvoid main() { gl_Position = vec4(float(h)); }\n", o);
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("in float hHigh;"), std::string::npos) << r.output;
  auto clash = lower("#version 300 es\nin double h;\nin float h_hi;\nvoid main() { gl_Position = vec4(float(h) + h_hi); }\n");
  EXPECT_FALSE(clash.ok);
  EXPECT_NE(messages(clash).find("h_hi"), std::string::npos) << messages(clash);
}

TEST(Guard, PreciseOnEs320UniformOnEs300) {
  const char* src = "#version 300 es\nuniform double a;\nout float r;\nvoid main() { r = float(a * a); }\n";
  auto es300 = lower(src, doublet::Stage::Fragment, doublet::Target::Es300);
  ASSERT_TRUE(es300.ok) << messages(es300);
  EXPECT_NE(es300.output.find("uniform highp float df_guard[2];"), std::string::npos);
  EXPECT_NE(es300.output.find(" - df_guard[int(df_guard[1])])"), std::string::npos);
  EXPECT_EQ(es300.manifest.guard.uniform_type, "float[2]");
  EXPECT_EQ(es300.output.find("precise "), std::string::npos);
  auto es320 = lower(src, doublet::Stage::Fragment, doublet::Target::Es320);
  ASSERT_TRUE(es320.ok) << messages(es320);
  EXPECT_NE(es320.output.find("precise "), std::string::npos);
  EXPECT_EQ(es320.manifest.guard.kind, "precise");
}

// Without the uniform guard (`precise`, df64-int's none) no rule reads it, but a double uniform's
// words are read through it, out of reach of uniform inliners (Config::reads_uniforms_through_guard);
// a shader without double uniforms declares none.
TEST(Guard, UniformsReadThroughItWithoutTheUniformGuard) {
  const char* src = "#version 300 es\nuniform double a;\nout float r;\nvoid main() { r = float(a * a); }\n";
  const std::string read = "a = df_double(a_hi - df_guard[int(df_guard[1])], a_lo - df_guard[int(df_guard[1])]);";
  for (doublet::Mode mode : {doublet::Mode::Df64, doublet::Mode::Df64Int}) {
    doublet::Options o;
    o.stage = doublet::Stage::Fragment;
    o.target = doublet::Target::Es320;
    o.mode = mode;
    auto r = doublet::lower(src, o);
    ASSERT_TRUE(r.ok) << messages(r);
    EXPECT_NE(r.output.find("uniform highp float df_guard[2];"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(read), std::string::npos) << r.output;
    size_t reads = 0;
    for (size_t at = r.output.find("df_guard[int("); at != std::string::npos; at = r.output.find("df_guard[int(", at + 1)) ++reads;
    EXPECT_EQ(reads, 2u) << r.output;  // the two words, nothing else
    EXPECT_EQ(r.manifest.guard.kind, mode == doublet::Mode::Df64 ? "precise" : "none");
    EXPECT_EQ(r.manifest.guard.uniform_name, "df_guard");
    EXPECT_EQ(r.manifest.guard.uniform_type, "float[2]");
  }
  auto no_uniform = lower("#version 300 es\nflat in double a;\nout float r;\nvoid main() { r = float(a * a); }\n",
                          doublet::Stage::Fragment, doublet::Target::Es320);
  ASSERT_TRUE(no_uniform.ok) << messages(no_uniform);
  EXPECT_EQ(no_uniform.output.find("df_guard"), std::string::npos) << no_uniform.output;
  EXPECT_EQ(no_uniform.manifest.guard.uniform_name, "");
}

// ES 1.00 fragment shaders index uniform arrays by constants only, and WGSL's uniform buffer holds
// the guard as one f32: both keep the scalar guard (docs/accuracy.md).
TEST(Guard, ScalarOnEs100AndWgsl) {
  const char* src = "#version 300 es\nuniform double a;\nvoid main() { gl_Position = vec4(float(a * a + a)); }\n";
  for (doublet::Target target : {doublet::Target::Es100, doublet::Target::Wgsl}) {
    auto r = lower(src, doublet::Stage::Vertex, target);
    ASSERT_TRUE(r.ok) << messages(r);
    EXPECT_EQ(r.output.find("df_guard["), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("df_guard"), std::string::npos) << r.output;
    EXPECT_EQ(r.manifest.guard.uniform_type, "float");
  }
}

// A float-float constant reads the guard even where no rule is called (a struct copied and
// compared): the guard is declared all the same, and the manifest names it. (WGSL refuses the
// comparison; WgslRefusals.AreErrorsWithPositions checks that this is that refusal, not an
// undeclared guard.)
TEST(Guard, DeclaredForConstantsWithoutRules) {
  const char* src = "#version 300 es\nstruct S { double d; };\nout vec4 r;\n"
                    "void main() { S s = S(1.5lf); S t = s; r = vec4(s == t ? 1.0 : 0.0); }\n";
  for (doublet::Target target : {doublet::Target::Es100, doublet::Target::Es300}) {
    auto out = lower(src, doublet::Stage::Fragment, target);
    ASSERT_TRUE(out.ok) << doublet::to_string(target) << ": " << messages(out);
    EXPECT_NE(out.output.find("df_guard"), std::string::npos) << out.output;
    EXPECT_EQ(out.manifest.guard.kind, "uniform");
    EXPECT_EQ(out.manifest.guard.uniform_name, "df_guard");
  }
}

TEST(Guard, PreciseOnATargetWithoutItIsAnError) {
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.target = doublet::Target::Es300;
  o.guard = doublet::GuardKind::Precise;
  auto r = doublet::lower("#version 300 es\nout float r;\nvoid main() { r = 1.0; }\n", o);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(messages(r).find("precise"), std::string::npos);
}

TEST(Output, OnlyTheHelpersUsedAreEmitted) {
  auto r = lower("#version 300 es\nuniform double a, b;\nout float r;\nvoid main() { r = float(a + b); }\n",
                 doublet::Stage::Fragment);
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("df_add("), std::string::npos);
  EXPECT_EQ(r.output.find("df_mul("), std::string::npos);
  EXPECT_EQ(r.output.find("df_div("), std::string::npos);
  EXPECT_EQ(r.output.find("df_sqrt("), std::string::npos);
}

TEST(Output, IsDeterministic) {
  const char* src = "#version 300 es\nin dvec3 p;\nuniform dvec3 e;\nvoid main() { gl_Position = vec4(vec3(p - e) * 2.0, 1.0); }\n";
  auto a = lower(src), b = lower(src);
  ASSERT_TRUE(a.ok);
  EXPECT_EQ(a.output, b.output);
  EXPECT_EQ(a.manifest.to_json(), b.manifest.to_json());
}

TEST(Frontend, VersionScanSkipsCommentsAndKnowsEs) {
  using doublet::frontend::scan_version;
  EXPECT_EQ(scan_version("// hi\n/* x\n */ #version 310 es\n").version, 310);
  EXPECT_TRUE(scan_version("#version 310 es\n").es);
  EXPECT_FALSE(scan_version("#version 450\n").es);
  EXPECT_TRUE(scan_version("void main(){}").es);  // no #version: ES 1.00
  EXPECT_EQ(scan_version("void main(){}").version, 100);
}

TEST(Frontend, StageFromPath) {
  EXPECT_EQ(doublet::stage_from_path("a/b/x.vert"), doublet::Stage::Vertex);
  EXPECT_EQ(doublet::stage_from_path("x.frag.glsl"), doublet::Stage::Fragment);
  EXPECT_EQ(doublet::stage_from_path("x.comp"), doublet::Stage::Compute);
  EXPECT_FALSE(doublet::stage_from_path("x.glsl").has_value());
}

}  // namespace

namespace {

// Double constants float-float cannot hold: overflow is an error, underflow a
// warning (an error with Options::constant_range_errors), each at its column.
TEST(ConstantRange, OutOfRangeConstantsAreDiagnosedAtTheirPlace) {
  const char* src =
      "#version 450\nout vec4 o;\nvoid main() {\n"
      "  double a = 1e100lf;\n  double b = 1e-300lf;\n  double c = 1e+309lf;\n"
      "  o = vec4(float(a), float(b), float(c), 1.0);\n}\n";
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.target = doublet::Target::Glsl450;
  o.file_name = "range.frag";
  auto r = doublet::lower(src, o);
  EXPECT_FALSE(r.ok);
  std::string all = messages(r);
  EXPECT_NE(all.find("range.frag:4:14: error: the double constant 1e+100 is outside float-float range"),
            std::string::npos) << all;
  EXPECT_NE(all.find("range.frag:5:14: warning: the double constant 1e-300 is below float-float range"),
            std::string::npos) << all;
  EXPECT_NE(all.find("range.frag:6:14: error: the double constant overflows even double precision"),
            std::string::npos) << all;

  const char* tiny = "#version 450\nout vec4 o;\nvoid main() { double b = 1e-300lf; o = vec4(float(b)); }\n";
  auto warned = doublet::lower(tiny, o);
  EXPECT_TRUE(warned.ok) << messages(warned);
  o.constant_range_errors = true;
  auto refused = doublet::lower(tiny, o);
  EXPECT_FALSE(refused.ok);
  EXPECT_NE(messages(refused).find("error: the double constant 1e-300 is below"), std::string::npos);
}

}  // namespace

// A lowering error in an #include'd file names that file (and its line), not the main source:
// before, ir::Loc carried no file and such errors read "main.comp:<the included file's line>".
namespace {
class OneFileIncluder : public doublet::Includer {
 public:
  std::optional<doublet::IncludeResult> include(std::string_view requested, std::string_view) override {
    if (requested != "lib.glsl") return std::nullopt;
    return doublet::IncludeResult{"lib.glsl", "// library\n\ndouble twice(double x) { return x * 2.0lf; }\n"
                                              "double huge(double x) { return x * 1e300lf; }\n"};
  }
};
}  // namespace

TEST(LowerApi, ErrorsInAnIncludedFileNameThatFile) {
  OneFileIncluder files;
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = doublet::Target::Es310;
  o.constant_range_errors = true;  // 1e300 is beyond float-float: an error placed in lib.glsl
  o.file_name = "main.comp";
  o.includer = &files;
  const auto r = doublet::lower(
      "#version 450\n#extension GL_GOOGLE_include_directive : require\nlayout(local_size_x = 1) in;\n"
      "#include \"lib.glsl\"\nlayout(std430, binding = 0) buffer B { double v[]; };\n"
      "void main() { v[0] = twice(v[1]); v[2] = huge(v[3]); }\n",
      o);
  ASSERT_FALSE(r.ok);
  std::string first;
  for (const auto& d : r.diagnostics)
    if (d.severity == doublet::Severity::Error && first.empty()) first = doublet::format_diagnostic(d);
  EXPECT_EQ(first.rfind("lib.glsl:4:", 0), 0u) << first;
  EXPECT_NE(first.find("1e+300"), std::string::npos) << first;
}
