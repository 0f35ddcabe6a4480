// run_graphics: vertex and fragment stages on lavapipe and Mesa GLES, inputs and outputs read
// bit-exactly through the wrapper's storage buffers; native doubles in both stages on lavapipe.
#include <cmath>

#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

class Graphics : public ::testing::TestWithParam<std::tuple<Backend, GraphicsStage>> {};

// The same text works in both stages: after wrapping, `in`/`out` are plain globals.
constexpr const char* kFloatShader = R"(#version 300 es
precision highp float;
in vec2 a;
in float b;
uniform float k;
uniform mat2 m;
flat out vec2 r;
out float s;
void main() {
  r = m * a * b + k;
  s = a.x / b;
}
)";

TEST_P(Graphics, FloatOutputsAreBitExact) {
  const auto [backend, stage] = GetParam();
  REQUIRE_BACKEND(backend);
  GraphicsJob job;
  job.stage = stage;
  job.glsl = kFloatShader;
  job.count = 200;  // more than a 64-pixel row
  for (uint32_t i = 0; i < job.count; ++i) {
    job.inputs["a"].push_back(1.0 + i * 0x1p-10);
    job.inputs["a"].push_back(-3.0 - i);
    job.inputs["b"].push_back(0.75 + i);
  }
  job.uniforms["k"] = {0.125};
  job.uniforms["m"] = {2, 0, 0, 4};  // column-major diag(2, 4)
  const GraphicsResult r = run_graphics(backend, job);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.outputs.at("r").size(), 2u * job.count);
  ASSERT_EQ(r.outputs.at("s").size(), job.count);
  for (uint32_t i = 0; i < job.count; ++i) {
    const float ax = static_cast<float>(job.inputs["a"][2 * i]), ay = static_cast<float>(job.inputs["a"][2 * i + 1]);
    const float b = static_cast<float>(job.inputs["b"][i]);
    EXPECT_EQ(r.outputs.at("r")[2 * i], 2.0f * ax * b + 0.125f) << i;
    EXPECT_EQ(r.outputs.at("r")[2 * i + 1], 4.0f * ay * b + 0.125f) << i;
    EXPECT_EQ(bits<uint32_t>(static_cast<float>(r.outputs.at("s")[i])), bits<uint32_t>(ax / b)) << i;
  }
}

class GraphicsStageOnly : public ::testing::TestWithParam<GraphicsStage> {};

TEST_P(GraphicsStageOnly, NativeDoublesRunOnLavapipe) {
  REQUIRE_BACKEND(Backend::Vulkan);
  GraphicsJob job;
  job.stage = GetParam();
  job.glsl = R"(#version 450
in dvec3 p;
uniform dvec3 eye;
flat out dvec3 d;
void main() { d = p - eye; }
)";
  job.count = 3;
  job.inputs["p"] = {1e7 + 0.1, 2, 3, 4, 5, 6, 7, 8, 9};
  job.uniforms["eye"] = {1e7, 1, 1};
  const GraphicsResult r = run_graphics(Backend::Vulkan, job);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<double>& d = r.outputs.at("d");
  EXPECT_EQ(d[0], (1e7 + 0.1) - 1e7);  // exact in double; float would be off by ~0.1
  EXPECT_EQ(d[8], 8.0);
}

INSTANTIATE_TEST_SUITE_P(Stages, GraphicsStageOnly, ::testing::Values(GraphicsStage::Vertex, GraphicsStage::Fragment),
                         [](const auto& info) { return std::string(info.param == GraphicsStage::Vertex ? "Vertex" : "Fragment"); });

class GraphicsBackend : public ::testing::TestWithParam<Backend> {};

TEST_P(GraphicsBackend, VertexStageCapturesGlPosition) {
  REQUIRE_BACKEND(GetParam());
  GraphicsJob job;
  job.glsl = "#version 310 es\nin vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n";
  job.count = 2;
  job.inputs["p"] = {1, 2, 3, -4, -5, -6};
  const GraphicsResult r = run_graphics(GetParam(), job);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.outputs.at("gl_Position"), (std::vector<double>{1, 2, 3, 1, -4, -5, -6, 1}));
}

INSTANTIATE_TEST_SUITE_P(Backends, GraphicsBackend, ::testing::Values(Backend::Vulkan, Backend::Gles), backend_param_name);

TEST(GraphicsWrap, UnsupportedDeclarationsAreReported) {
  GraphicsInterface iface;
  std::string error;
  EXPECT_FALSE(reflect_graphics(GraphicsStage::Vertex, "#version 310 es\nin vec3 p[2];\nvoid main() {}\n", &iface, &error));
  EXPECT_NE(error.find("unsupported in/out declaration"), std::string::npos) << error;
  EXPECT_FALSE(reflect_graphics(GraphicsStage::Vertex, "#version 130\nin vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n",
                                &iface, &error));
  EXPECT_NE(error.find("unsupported '#version 130'"), std::string::npos) << error;
}

// ES 1.00 text runs as ES 3.10: `attribute` is an input, `varying` a vertex output.
TEST(GraphicsWrap, Es100AttributesAndVaryingsAreCaptured) {
  GraphicsInterface iface;
  std::string error;
  ASSERT_TRUE(reflect_graphics(GraphicsStage::Vertex,
                               "#version 100\nattribute vec3 p;\nvarying vec2 uv;\n"
                               "void main() { uv = p.xy; gl_Position = vec4(p, 1.0); }\n",
                               &iface, &error)) << error;
  ASSERT_EQ(iface.inputs.size(), 1u);
  EXPECT_EQ(iface.inputs[0].name, "p");
  ASSERT_EQ(iface.outputs.size(), 2u);
  EXPECT_EQ(iface.outputs[0].name, "uv");
  EXPECT_EQ(iface.outputs[1].name, "gl_Position");
}

TEST(GraphicsWrap, ReflectsInputsOutputsAndUniforms) {
  GraphicsInterface iface;
  std::string error;
  ASSERT_TRUE(reflect_graphics(GraphicsStage::Fragment, kFloatShader, &iface, &error)) << error;
  ASSERT_EQ(iface.inputs.size(), 2u);
  EXPECT_EQ(iface.inputs[0].name, "a");
  EXPECT_EQ(iface.inputs[1].offset, 8u);
  EXPECT_EQ(iface.input_stride, 16u);  // vec2 + float, aligned to 8
  ASSERT_EQ(iface.outputs.size(), 2u);
  EXPECT_EQ(iface.uniforms.size(), 2u);
  for (const auto& u : iface.uniforms)
    if (u.name == "m") EXPECT_TRUE(u.components == 4 && u.columns == 2);
}

std::string param_name(const ::testing::TestParamInfo<std::tuple<Backend, GraphicsStage>>& info) {
  return std::string(backend_name(std::get<0>(info.param))) +
         (std::get<1>(info.param) == GraphicsStage::Vertex ? "Vertex" : "Fragment");
}

INSTANTIATE_TEST_SUITE_P(Stages, Graphics,
                         ::testing::Combine(::testing::Values(Backend::Vulkan, Backend::Gles),
                                            ::testing::Values(GraphicsStage::Vertex, GraphicsStage::Fragment)),
                         param_name);

// Geometry and tessellation jobs run on lavapipe (desktop 4.50 text) and on Mesa's GLES (ES 3.20
// text: all five stages linked, input primitives or patches drawn).
class GraphicsPrimitiveStages : public ::testing::TestWithParam<Backend> {};

std::string version_line(Backend b) { return b == Backend::Gles ? "#version 320 es" : "#version 450"; }

// Geometry jobs: one triangle per sample, its per-vertex inputs one input per element; every
// EmitVertex() stores one output record of the sample, and a record never emitted reads as NaN.
TEST_P(GraphicsPrimitiveStages, EachEmitVertexStoresOneRecordOfItsSample) {
  REQUIRE_BACKEND(GetParam());
  GraphicsJob job;
  job.stage = GraphicsStage::Geometry;
  job.glsl = version_line(GetParam()) + R"(
layout(triangles) in;
layout(points, max_vertices = 3) out;
in float a[];
out float sum;
out float corner;
void main() {
  for (int k = 0; k < 2; ++k) {
    sum = a[0] + a[1] + a[2];
    corner = a[k] * 2.0 + gl_in[k].gl_Position.x;
    gl_Position = vec4(float(k));
    EmitVertex();
  }
  EndPrimitive();
}
)";
  job.count = 2;
  job.inputs["a[0]"] = {1, 10};
  job.inputs["a[1]"] = {2, 20};
  job.inputs["a[2]"] = {4, 40};
  job.inputs["gl_in[0].gl_Position"] = {0.5, 0, 0, 0, 0.25, 0, 0, 0};
  job.inputs["gl_in[1].gl_Position"] = {0.125, 0, 0, 0, 8, 0, 0, 0};
  const GraphicsResult r = run_graphics(GetParam(), job);
  ASSERT_TRUE(r.ok) << r.error;
  const std::vector<double>& sum = r.outputs.at("sum");
  const std::vector<double>& corner = r.outputs.at("corner");
  ASSERT_EQ(sum.size(), 6u);  // 2 samples × 3 records
  EXPECT_EQ(sum[0], 7);
  EXPECT_EQ(sum[1], 7);
  EXPECT_TRUE(std::isnan(sum[2]));  // the third vertex is never emitted
  EXPECT_EQ(sum[3], 70);
  EXPECT_EQ(corner[0], 2.5);
  EXPECT_EQ(corner[1], 4.125);
  EXPECT_EQ(corner[3], 20.25);
  EXPECT_EQ(corner[4], 48);
  EXPECT_TRUE(std::isnan(corner[5]));
  EXPECT_EQ(r.outputs.at("gl_Position")[4], 1);  // record 1 of sample 0: gl_Position = vec4(1)
}

// Tessellation control jobs: one patch per sample; invocation k stores record k (its own element of
// a per-vertex output, the levels it wrote, 0 for the ones it did not).
TEST_P(GraphicsPrimitiveStages, ControlInvocationsStoreTheirOwnRecord) {
  REQUIRE_BACKEND(GetParam());
  GraphicsJob job;
  job.stage = GraphicsStage::TessControl;
  job.glsl = version_line(GetParam()) + R"(
layout(vertices = 2) out;
in float a[];
out float twice[];
void main() {
  twice[gl_InvocationID] = a[gl_InvocationID] * 2.0 + a[1 - gl_InvocationID];
  gl_TessLevelOuter[gl_InvocationID] = a[0] + 1.0;
}
)";
  job.count = 2;
  job.inputs["a[0]"] = {1, 10};
  job.inputs["a[1]"] = {3, 30};
  const GraphicsResult r = run_graphics(GetParam(), job);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.outputs.at("twice"), (std::vector<double>{5, 7, 50, 70}));
  const std::vector<double>& outer = r.outputs.at("gl_TessLevelOuter");
  ASSERT_EQ(outer.size(), 16u);  // 4 records × vec4
  EXPECT_EQ((std::vector<double>(outer.begin(), outer.begin() + 8)), (std::vector<double>{2, 0, 0, 0, 0, 2, 0, 0}));
  EXPECT_EQ(outer[8], 11);
}

// Tessellation evaluation jobs: the user's code runs at the sample's own gl_TessCoord, with the
// domain's corner elements of its per-vertex inputs.
TEST_P(GraphicsPrimitiveStages, EvaluationRunsAtTheSamplesTessCoord) {
  REQUIRE_BACKEND(GetParam());
  GraphicsJob job;
  job.stage = GraphicsStage::TessEvaluation;
  job.glsl = version_line(GetParam()) + R"(
layout(triangles, equal_spacing, ccw) in;
in float h[];
patch in float base;
out float value;
void main() {
  value = base + h[0] * gl_TessCoord.x + h[1] * gl_TessCoord.y + h[2] * gl_TessCoord.z;
  gl_Position = vec4(value);
}
)";
  job.count = 2;
  job.inputs["h[0]"] = {1, 100};
  job.inputs["h[1]"] = {2, 200};
  job.inputs["h[2]"] = {4, 400};
  job.inputs["base"] = {0.5, 0.25};
  job.inputs["gl_TessCoord"] = {0.5, 0.25, 0.25, 0, 0, 1};
  const GraphicsResult r = run_graphics(GetParam(), job);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.outputs.at("value"), (std::vector<double>{0.5 + 0.5 + 0.5 + 1, 400.25}));
}

INSTANTIATE_TEST_SUITE_P(Backends, GraphicsPrimitiveStages, ::testing::Values(Backend::Vulkan, Backend::Gles),
                         backend_param_name);

}  // namespace
}  // namespace doublet::runner::test
