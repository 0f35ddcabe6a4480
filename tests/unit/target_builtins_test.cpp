// Built-ins a target lacks (issue 12): a positioned diagnostic naming the built-in, the target and
// the stage, never "internal error: the lowered shader is not valid".
#include <gtest/gtest.h>

#include "doublet/doublet.hpp"

namespace {

doublet::Result lower_for(const std::string& source, doublet::Stage stage, doublet::Target target) {
  doublet::Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "user.glsl";
  return doublet::lower(source, o);
}

struct Case {
  const char* what;
  doublet::Stage stage;
  doublet::Target target;
  std::string source;
  int line, column;
  std::string expected;  // start of the message
};

TEST(TargetBuiltins, MissingBuiltinIsAPositionedDiagnosticNotAnInternalError) {
  const std::string vertex_ids =
      "#version 450\nuniform double k;\nvoid main() {\n  gl_Position = vec4(float(k));\n"
      "  gl_PointSize = float(gl_VertexID);\n}\n";
  const std::string clip =
      "#version 450\nuniform double k;\nvoid main() {\n  gl_Position = vec4(float(k));\n"
      "  gl_ClipDistance[0] = 1.0;\n}\n";
  const std::string depth =
      "#version 450\nuniform double k;\nout vec4 c;\nvoid main() {\n  c = vec4(1.0);\n"
      "  gl_FragDepth = float(k);\n}\n";
  const std::string lod =
      "#version 450\nuniform sampler2D s;\nuniform double k;\nin vec2 uv;\nout vec4 c;\n"
      "void main() {\n  c = textureLod(s, uv, float(k));\n}\n";
  const Case cases[] = {
      {"gl_VertexID on es100", doublet::Stage::Vertex, doublet::Target::Es100, vertex_ids, 5, 24,
       "the built-in 'gl_VertexID' does not exist in es100 vertex shaders"},
      {"gl_ClipDistance on es300", doublet::Stage::Vertex, doublet::Target::Es300, clip, 5, 3,
       "the built-in 'gl_ClipDistance' does not exist in es300 vertex shaders"},
      {"gl_ClipDistance on es320", doublet::Stage::Vertex, doublet::Target::Es320, clip, 5, 3,
       "the built-in 'gl_ClipDistance' does not exist in es320 vertex shaders"},
      {"gl_FragDepth on es100", doublet::Stage::Fragment, doublet::Target::Es100, depth, 6, 3,
       "the built-in 'gl_FragDepth' does not exist in es100 fragment shaders"},
      {"textureLod in an es100 fragment shader", doublet::Stage::Fragment, doublet::Target::Es100, lod, 7, 33,  // glslang places a call at its ')' 
       "the built-in 'textureLod' (texture2DLod there) has no such overload in es100 fragment shaders"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    doublet::Result r = lower_for(c.source, c.stage, c.target);
    ASSERT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    const doublet::Diagnostic& d = r.diagnostics.front();
    EXPECT_EQ(d.message.rfind(c.expected, 0), 0u) << doublet::format_diagnostic(d);
    EXPECT_EQ(d.message.find("internal error"), std::string::npos) << d.message;
    EXPECT_EQ(d.line, c.line) << doublet::format_diagnostic(d);
    EXPECT_EQ(d.column, c.column) << doublet::format_diagnostic(d);
  }
}

// The advice names the targets that have the variable (asked of glslang), or says that a
// compatibility-profile built-in exists in none of them.
TEST(TargetBuiltins, AdviceNamesTheTargetsThatHaveIt) {
  const std::string clip =
      "#version 450\nuniform double k;\nvoid main() {\n  gl_Position = vec4(float(k));\n"
      "  gl_ClipDistance[0] = 1.0;\n}\n";
  doublet::Result r = lower_for(clip, doublet::Stage::Vertex, doublet::Target::Es300);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("; remove it, or target one that has it (glsl330, glsl450)"), std::string::npos)
      << r.diagnostics[0].message;
  const std::string compat =
      "#version 400 compatibility\nuniform dvec3 offset;\nvoid main() {\n"
      "  gl_Position = vec4(dvec3(gl_Vertex.xyz) + offset, 1.0);\n}\n";
  for (doublet::Target t : {doublet::Target::Es300, doublet::Target::Glsl450}) {
    r = lower_for(compat, doublet::Stage::Vertex, t);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].line, 4);
    EXPECT_NE(r.diagnostics[0].message.find("the built-in 'gl_Vertex' does not exist in"), std::string::npos);
    EXPECT_NE(r.diagnostics[0].message.find("(a compatibility-profile built-in: doublet's desktop targets are core "
                                            "profiles); pass the value as a uniform or an attribute instead"),
              std::string::npos)
        << r.diagnostics[0].message;
  }
}

TEST(TargetBuiltins, TargetsThatHaveTheBuiltinStillLowerIt) {
  const std::string clip =
      "#version 450\nuniform double k;\nvoid main() {\n  gl_Position = vec4(float(k));\n"
      "  gl_ClipDistance[0] = float(k);\n}\n";
  for (doublet::Target t : {doublet::Target::Glsl330, doublet::Target::Glsl450}) {
    doublet::Result r = lower_for(clip, doublet::Stage::Vertex, t);
    EXPECT_TRUE(r.ok) << (r.diagnostics.empty() ? "" : doublet::format_diagnostic(r.diagnostics[0]));
  }
}

// ES forbids computed indices into fragment output arrays, which gl_FragData[i] would need there.
TEST(TargetBuiltins, FragDataWithAComputedIndexIsAnErrorOnEsOnly) {
  const std::string source = "#version 110\nuniform double k;\nvoid main() {\n"
                             "  for (int i = 0; i < 2; ++i) gl_FragData[i] = vec4(float(k));\n}\n";
  for (doublet::Target t : {doublet::Target::Es100, doublet::Target::Es300, doublet::Target::Es310, doublet::Target::Es320}) {
    doublet::Result r = lower_for(source, doublet::Stage::Fragment, t);
    ASSERT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(r.diagnostics[0].line, 4) << doublet::format_diagnostic(r.diagnostics[0]);
    EXPECT_EQ(r.diagnostics[0].message.rfind("gl_FragData indexed by a computed value cannot be expressed on es", 0), 0u)
        << r.diagnostics[0].message;
  }
  for (doublet::Target t : {doublet::Target::Glsl330, doublet::Target::Glsl450}) {
    doublet::Result r = lower_for(source, doublet::Stage::Fragment, t);
    EXPECT_TRUE(r.ok) << (r.diagnostics.empty() ? "" : doublet::format_diagnostic(r.diagnostics[0]));
  }
}

// A rule the target lacks (isnan on ES 1.00) is reported where the shader asks for it.
TEST(TargetBuiltins, RuleTheTargetLacksPointsAtItsUse) {
  doublet::Result r = lower_for("#version 450\nuniform double k;\nout vec4 c;\nvoid main() {\n"
                                "  c = vec4(isnan(k) ? 1.0 : 0.0);\n}\n",
                                doublet::Stage::Fragment, doublet::Target::Es100);
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics[0].line, 5) << doublet::format_diagnostic(r.diagnostics[0]);
  EXPECT_GT(r.diagnostics[0].column, 0);
  EXPECT_NE(r.diagnostics[0].message.find("df_isnan is not available on ES 1.00"), std::string::npos);
}

}  // namespace
