// Bugs found by lowering glslang's own test shaders (glslang_suite_test.cpp), each reduced to a few
// lines that need no fetched corpus.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

using namespace doublet;

Options options(Stage stage, Target target, Mode mode = Mode::Df64) {
  Options o;
  o.stage = stage;
  o.target = target;
  o.mode = mode;
  o.file_name = "peer.glsl";
  o.disabled_lints = {"all"};
  return o;
}

std::string messages(const Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += format_diagnostic(d) + "\n";
  return s;
}

// stringToDouble.vert: `double e12 = 1e+309;` is infinity, which mode native printed as `inf.0lf`
// (internal error: 'inf' : undeclared identifier).
TEST(PeerRegressions, NativeInfinityAndNanConstantsArePrintable) {
  const char* shader = R"(#version 450
layout(location = 0) out vec4 color;
uniform double u;
void main() {
  double big = 1e+309;
  double low = -1e+309lf;
  double nan = u < 0.0lf ? big + low : u;
  color = vec4(float(big), float(low), float(nan), 1.0);
}
)";
  Result r = lower(shader, options(Stage::Fragment, Target::Glsl450, Mode::Native));
  ASSERT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("(1.0lf / 0.0lf)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(-1.0lf / 0.0lf)"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("inf"), std::string::npos) << r.output;
}

}  // namespace

namespace {

// missingBodies.vert, link.*.vert, recurse1.frag, spv.unit1.frag, ...: glslang accepts a call of a
// function declared without a body (the body may come from another compilation unit at link time);
// the lowered shader failed re-validation ("no matching overloaded function found": internal error).
// Now each call of an overload without a body is refused where it is.
TEST(PeerRegressions, CallOfAFunctionWithoutBodyIsRefusedAtTheCall) {
  const char* shader = R"(#version 450
layout(location = 0) out vec4 color;
uniform double u;
double scale(double x);
float scale(float x) { return 2.0 * x; }
double global_value();
double g = global_value();
void main() {
  double s = scale(u);
  color = vec4(float(s + g), scale(1.0), 0.0, 1.0);
}
)";
  for (Target t : {Target::Es300, Target::Glsl450}) {
    Result r = lower(shader, options(Stage::Fragment, t));
    ASSERT_FALSE(r.ok) << r.output;
    const std::string m = messages(r);
    EXPECT_NE(m.find("peer.glsl:7:25: error: 'global_value()' is declared but has no body in this shader"),
              std::string::npos) << m;
    EXPECT_NE(m.find("peer.glsl:9:21: error: 'scale(double)' is declared but has no body"), std::string::npos) << m;
    EXPECT_EQ(m.find("scale(float)"), std::string::npos) << m;  // that overload has its body
    EXPECT_EQ(m.find("internal error"), std::string::npos) << m;
  }
}

}  // namespace

namespace {

// spv.subgroup.frag, spv.drawParams.vert, spv.multiView.frag, ... (about 30 files): the shader's
// #extension directives were dropped, so its uses of their built-ins failed re-validation
// ("required extension not requested": internal error). They are carried now, except to WebGL,
// whose shaders enable none (refused there at the use).
TEST(PeerRegressions, TheShadersExtensionsAreCarriedIntoTheOutput) {
  const char* shader = R"(#version 450
#extension GL_KHR_shader_subgroup_basic : enable
#extension GL_ARB_gpu_shader_fp64 : enable
layout(location = 0) out vec4 color;
uniform double u;
void main() {
  color = vec4(float(u * 3.0lf), float(gl_SubgroupSize), 0.0, 1.0);
}
)";
  for (Target t : {Target::Es310, Target::Glsl450}) {
    Result r = lower(shader, options(Stage::Fragment, t));
    ASSERT_TRUE(r.ok) << to_string(t) << "\n" << messages(r);
    EXPECT_NE(r.output.find("#extension GL_KHR_shader_subgroup_basic : enable\n"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("GL_ARB_gpu_shader_fp64"), std::string::npos) << r.output;  // no double left
  }
  Result web = lower(shader, options(Stage::Fragment, Target::Webgl2));
  ASSERT_FALSE(web.ok) << web.output;
  const std::string m = messages(web);
  EXPECT_NE(m.find("peer.glsl:7:"), std::string::npos) << m;
  EXPECT_NE(m.find("gl_SubgroupSize"), std::string::npos) << m;
  EXPECT_EQ(m.find("internal error"), std::string::npos) << m;
}

// spv.dead-after-return.vert, GL_ARB_draw_instanced.vert, spv.150.vert, ...: desktop constructs
// an ES target lacks (a non-flat `out int`, a vertex input array, a struct output holding a struct)
// failed re-validation: internal errors. glslang says the same of the user's own text compiled as
// the target, so they are refused at the user's line with glslang's words.
TEST(PeerRegressions, WhatTheTargetLacksInTheUsersOwnTextIsRefusedAtItsLine) {
  const char* input_array = R"(#version 450
uniform double u;
layout(location = 0) in vec4 weights[2];
void main() {
  gl_Position = (weights[0] + weights[1]) * float(u);
}
)";
  const char* int_output = R"(#version 450
uniform double u;
layout(location = 0) out int id;
void main() {
  id = int(u);
  gl_Position = vec4(0.0);
}
)";
  const std::pair<const char*, const char*> cases[] = {
      {input_array, "peer.glsl:3:1: error: target es300 does not allow this (glslang, compiling the shader itself as "
                    "es300: 'vertex input arrays' : not supported with this profile: es); change it, or choose a "
                    "target that allows it"},
      {int_output, "peer.glsl:3:26: error: target es300 does not allow this (glslang, compiling the shader itself as "
                   "es300: 'int' : must be qualified as flat out)"}};
  for (const auto& [shader, expected] : cases) {
    Result r = lower(shader, options(Stage::Vertex, Target::Es300));
    ASSERT_FALSE(r.ok) << r.output;
    const std::string m = messages(r);
    EXPECT_NE(m.find(expected), std::string::npos) << m;
    EXPECT_EQ(m.find("internal error"), std::string::npos) << m;
    // The same shader for a desktop target lowers.
    Result desktop = lower(shader, options(Stage::Vertex, Target::Glsl450));
    EXPECT_TRUE(desktop.ok) << messages(desktop);
  }
}

}  // namespace

namespace {

// recurse1.vert: unnamed parameters (`float bar(int) { ... }`) have no symbol id of their own, so
// every one became the first one's variable: bar's int parameter was printed as an earlier
// function's float, and on ES the call bar(2) no longer matched (internal error).
TEST(PeerRegressions, EachUnnamedParameterKeepsItsOwnType) {
  const char* shader = R"(#version 310 es
precision highp float;
layout(location = 0) out vec4 color;
uniform double u;
float first(float) { return 1.0; }
float second(int) { return 2.0; }
double third(double, double b) { return b * u; }
void main() {
  color = vec4(first(0.5), second(2), float(third(u, u)), 1.0);
}
)";
  for (Target t : {Target::Es310, Target::Glsl450}) {
    Result r = lower(shader, options(Stage::Fragment, t));
    ASSERT_TRUE(r.ok) << to_string(t) << "\n" << messages(r);
    EXPECT_NE(r.output.find("float second(int "), std::string::npos) << r.output;
  }
}

}  // namespace

namespace {

// web.array.frag, spv.AofA.frag: a function returning an array was printed without the array
// size (`float foo(...)` for `float[4] foo(...)`); spv.paramMemory.frag, reflection.vert: an
// image parameter lost its memory qualifiers, and glslang refuses a call that drops one. Both were
// internal errors on every target.
TEST(PeerRegressions, ArrayReturnTypesAndParameterMemoryQualifiersArePrinted) {
  const char* shader = R"(#version 310 es
precision highp float;
layout(binding = 0, rgba32f) coherent writeonly uniform highp image2D img;
layout(location = 0) out vec4 color;
uniform double u;
double[2] pair(double a) { return double[](a, 2.0lf * a); }
void store(coherent writeonly highp image2D i, vec4 v) { imageStore(i, ivec2(0), v); }
void main() {
  double p[2] = pair(u);
  store(img, vec4(float(p[1])));
  color = vec4(float(p[0]));
}
)";
  for (Target t : {Target::Es310, Target::Glsl450})
    for (Mode m : {Mode::Df64, Mode::Fp32, Mode::Exact}) {
      Result r = lower(shader, options(Stage::Fragment, t, m));
      ASSERT_TRUE(r.ok) << to_string(t) << " " << to_string(m) << "\n" << messages(r);
      EXPECT_NE(r.output.find("[2] pair("), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("void store(coherent writeonly "), std::string::npos) << r.output;
    }
}

}  // namespace

namespace {

// spv.uniformInitializerStruct.frag: an anonymous struct type was printed with an empty name
// (`uniform void parts[2]`: internal error), and every anonymous struct shared the first one's
// fields. Each gets a name of its own.
TEST(PeerRegressions, AnonymousStructsGetNamesOfTheirOwn) {
  const char* shader = R"(#version 310 es
precision highp float;
layout(location = 0) out vec4 color;
uniform double u;
struct { float r; double d; } a;
struct { int n; } b[2];
void main() {
  a.r = 1.0; a.d = u; b[1].n = 3;
  color = vec4(a.r, float(a.d), float(b[1].n), 1.0);
}
)";
  for (Mode m : {Mode::Df64, Mode::Fp32, Mode::Exact}) {
    Result r = lower(shader, options(Stage::Fragment, Target::Es310, m));
    ASSERT_TRUE(r.ok) << to_string(m) << "\n" << messages(r);
    EXPECT_NE(r.output.find("anonymous_struct1"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("anonymous_struct2 b[2]"), std::string::npos) << r.output;
  }
}

// The same file's `uniform struct {...} parts[2] = {...};`: a uniform's initializer (its default
// value, desktop GLSL) was silently dropped, so the lowered uniform read 0; then it was refused.
// Now desktop targets keep it (a split double: both words), ES records it in the manifest with a
// warning, and a struct initializer (the manifest has no place for one) is refused by name.
TEST(PeerRegressions, UniformInitializersAreCarriedNotDropped) {
  const char* shader = R"(#version 450
layout(location = 0) out vec4 color;
layout(location = 0) uniform float k = 2.0;
layout(location = 1) uniform double d = 3.0lf;
void main() { color = vec4(k, float(d), 0.0, 1.0); }
)";
  for (Mode m : {Mode::Df64, Mode::Native}) {
    Result r = lower(shader, options(Stage::Fragment, Target::Glsl450, m));
    ASSERT_TRUE(r.ok) << messages(r);
    EXPECT_NE(r.output.find("uniform float k = 2.0;"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(m == Mode::Native ? "uniform double d = 3.0lf;" : "uniform float d_hi = 3.0;"),
              std::string::npos) << r.output;
  }
  Result es = lower(shader, options(Stage::Fragment, Target::Es310, Mode::Df64));
  ASSERT_TRUE(es.ok) << messages(es);
  EXPECT_NE(messages(es).find("peer.glsl:3:36: warning: uniforms 'k', 'd' declared with an initializer: target "
                              "es310 has no uniform initializers"), std::string::npos) << messages(es);
  EXPECT_NE(es.output.find("layout(location = 0) uniform float k;"), std::string::npos) << es.output;
  const char* with_struct = R"(#version 450
layout(location = 0) out vec4 color;
struct S { float a; double b; };
uniform S s = S(1.0, 2.0lf);
void main() { color = vec4(s.a, float(s.b), 0.0, 1.0); }
)";
  Result r = lower(with_struct, options(Stage::Fragment, Target::Glsl450, Mode::Df64));
  ASSERT_FALSE(r.ok) << r.output;
  EXPECT_NE(messages(r).find("error: uniform 's' has a struct initializer"), std::string::npos) << messages(r);
}

}  // namespace

namespace {

// glsl.es320.subgroupBasic.comp, spv.atomic.comp, newTexture.frag, 300BuiltIns.frag (56 files):
// built-ins doublet does not import were refused as "unsupported built-in operation", naming none.
// Subgroup built-ins on other types pass through now (they were refused by name).
TEST(PeerRegressions, AnUnsupportedBuiltInIsNamed) {
  const char* shader = R"(#version 450
#extension GL_KHR_shader_subgroup_basic : enable
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double d; uint n; };
void main() {
  d = d * 2.0lf;
  subgroupBarrier();
  n = subgroupElect() ? 1u : 0u;
  float f = noise1(1.0);
}
)";
  Result r = lower(shader, options(Stage::Compute, Target::Glsl450));
  ASSERT_FALSE(r.ok) << r.output;
  const std::string m = messages(r);
  EXPECT_EQ(m.find("subgroupBarrier"), std::string::npos) << m;
  EXPECT_EQ(m.find("subgroupElect"), std::string::npos) << m;
  EXPECT_NE(m.find("error: built-in function 'noise1' is not supported by doublet"), std::string::npos) << m;
}

}  // namespace

namespace {

// spv.functionSemantics.frag: an out argument converted after the call (a double variable for an
// `out float` parameter) goes through glslang's hidden `tempReturn`, a global it never declares:
// the lowered text used it undeclared (internal error on every target).
TEST(PeerRegressions, ConvertedOutArgumentsKeepTheirTemporariesDeclared) {
  const char* shader = R"(#version 450
layout(location = 0) out vec4 color;
uniform double u;
float half_of(double a, out float r) { r = float(a) * 0.5; return 1.0; }
void main() {
  double d;
  float k = half_of(u, d);
  color = vec4(float(d * u), k, 0.0, 1.0);
}
)";
  for (Target t : {Target::Es310, Target::Glsl450})
    for (Mode m : {Mode::Df64, Mode::Fp32, Mode::Exact}) {
      Result r = lower(shader, options(Stage::Fragment, t, m));
      ASSERT_TRUE(r.ok) << to_string(t) << " " << to_string(m) << "\n" << messages(r);
      EXPECT_NE(r.output.find("float tempReturn;"), std::string::npos) << r.output;
    }
}

}  // namespace

namespace {

// spv.fragmentShaderBarycentric2/4.frag, spv.perprimitiveNV.frag: per-vertex and per-primitive
// qualifiers were dropped, so `pervertexEXT in float a[3]` became an ordinary input (its three
// locations then overlapped the next input's: internal error; alone it was a different shader).
TEST(PeerRegressions, PerVertexAndPerPrimitiveQualifiersAreRefusedNotDropped) {
  const char* shader = R"(#version 450
#extension GL_EXT_fragment_shader_barycentric : require
#extension GL_NV_mesh_shader : require
layout(location = 0) pervertexEXT in float ids[3];
layout(location = 4) in B { perprimitiveNV float f; };
layout(location = 0) out float value;
uniform double u;
void main() { value = float(u) * (gl_BaryCoordEXT.x * ids[0] + f); }
)";
  Result r = lower(shader, options(Stage::Fragment, Target::Glsl450));
  ASSERT_FALSE(r.ok) << r.output;
  const std::string m = messages(r);
  EXPECT_NE(m.find("peer.glsl:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("'ids' is declared 'pervertexEXT', a qualifier doublet does not carry"), std::string::npos) << m;
  EXPECT_NE(m.find("'f' is declared 'perprimitiveNV'"), std::string::npos) << m;
  EXPECT_EQ(m.find("internal error"), std::string::npos) << m;
}

}  // namespace
