// verify() on the constructs real shaders use (issue 12): named uniform blocks with doubles,
// samplers, arrays of structs in buffers, -D and #include in the native run, gl_FragColor and
// gl_FragData (ES 1.00 text), int/uint/bool uniforms, and parameters declared on their own line.
// Every case runs on lavapipe and GLES; an unavailable driver fails the test.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "runner/runner.hpp"
#include "verify/report.hpp"
#include "verify/verify.hpp"

namespace doublet::verify {
namespace {

const std::string kDir = std::string(DOUBLET_VERIFY_SHADERS) + "/realworld/";

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

VerifyReport run(const std::string& file, Target target, double min_bits, Sabotage sabotage = Sabotage::None,
                 const std::vector<std::pair<std::string, std::string>>& defines = {}) {
  VerifyOptions o;
  o.lower.file_name = kDir + file;
  o.lower.stage = stage_from_path(file);
  o.lower.target = target;
  o.lower.defines = defines;
  o.lower.include_dirs = {kDir + "include"};
  o.samples = 256;
  o.sabotage = sabotage;
  o.min_bits = min_bits;
  if (std::ifstream(kDir + file + ".json")) EXPECT_EQ(parse_spec(read(kDir + file + ".json"), &o.spec), "");
  return verify(read(kDir + file), o);
}

double worst_bits(const VerifyReport& r, const std::string& output_prefix) {
  double worst = kMaxBits;
  for (const BackendRun& run : r.runs)
    for (const OutputStats& o : run.outputs)
      if (o.name.rfind(output_prefix, 0) == 0) worst = std::min(worst, o.min_bits);
  return worst;
}

void expect_passed_on_both_backends(const VerifyReport& r) {
  ASSERT_EQ(r.input_error, "") << format_table(r);
  ASSERT_EQ(r.runs.size(), 2u) << format_table(r);
  for (const BackendRun& run : r.runs) {
    EXPECT_EQ(run.error, "") << format_table(r);
    EXPECT_FALSE(run.outputs.empty());
  }
  EXPECT_TRUE(r.passed()) << format_table(r);
}

bool has_note(const VerifyReport& r, const std::string& part) {
  for (const std::string& n : r.notes)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

TEST(VerifyRealWorld, UniformBlockWithDoublesIsFilledInBothRuns) {
  const VerifyReport r = run("camera_block.vert", Target::Es300, 44);
  expect_passed_on_both_backends(r);
  EXPECT_GE(worst_bits(r, "clip"), 44);
  // The block's values matter: unguarded, the driver deletes the error terms and half the bits go.
  const VerifyReport fp32 = run("camera_block.vert", Target::Es300, 44, Sabotage::DropGuard);
  ASSERT_EQ(fp32.input_error, "") << format_table(fp32);
  EXPECT_LT(worst_bits(fp32, "clip"), 30) << format_table(fp32);
}

TEST(VerifyRealWorld, SamplerReadingFragmentShaderRunsEndToEnd) {
  const VerifyReport r = run("textured.frag", Target::Es300, 40);
  expect_passed_on_both_backends(r);
  EXPECT_TRUE(has_note(r, "sampler 'albedo'")) << format_table(r);
  const VerifyReport fp32 = run("textured.frag", Target::Es300, 40, Sabotage::DropLo);
  ASSERT_EQ(fp32.input_error, "") << format_table(fp32);
  EXPECT_LT(worst_bits(fp32, "color.xy"), 30) << format_table(fp32);
}

TEST(VerifyRealWorld, ArrayOfStructBufferMembersAreOutputs) {
  const VerifyReport r = run("particles.comp", Target::Es310, 40);
  expect_passed_on_both_backends(r);
  for (const char* member : {"p.position[]", "p.velocity[]", "p.mass[]", "p.radius[]"})
    EXPECT_LT(worst_bits(r, member), kMaxBits + 1) << member << " is not compared:\n" << format_table(r);
  EXPECT_GE(worst_bits(r, "p.mass[]"), 44);
}

TEST(VerifyRealWorld, DefinesReachTheNativeRun) {
  const VerifyReport r = run("defined.comp", Target::Es310, 44, Sabotage::None, {{"SCALE", "3.0lf"}});
  expect_passed_on_both_backends(r);
}

TEST(VerifyRealWorld, DefinesAndIncludesReachTheNativeRun) {
  const VerifyReport r = run("scaled.comp", Target::Es310, 44, Sabotage::None, {{"SCALE", "3.0lf"}});
  expect_passed_on_both_backends(r);
  EXPECT_GE(worst_bits(r, "y[]"), 44);
}

TEST(VerifyRealWorld, MissingIncludeIsAnInputError) {
  VerifyOptions o;
  o.lower.file_name = kDir + "scaled.comp";
  o.lower.stage = Stage::Compute;
  o.lower.target = Target::Es310;
  o.lower.defines = {{"SCALE", "3.0lf"}};  // no -I: the header is not found
  const VerifyReport r = verify(read(kDir + "scaled.comp"), o);
  EXPECT_NE(r.input_error.find("scale_helpers.glsl"), std::string::npos) << r.input_error;
  EXPECT_TRUE(r.runs.empty());
}

TEST(VerifyRealWorld, FragColorAndFragDataOnEs100) {
  const VerifyReport color = run("legacy_color.frag", Target::Es100, 44);
  expect_passed_on_both_backends(color);
  EXPECT_GE(worst_bits(color, "gl_FragColor.xy"), 44);
  const VerifyReport data = run("legacy_data.frag", Target::Es100, 44);
  expect_passed_on_both_backends(data);
  EXPECT_GE(worst_bits(data, "gl_FragData[0].xy"), 44);
  EXPECT_LT(worst_bits(data, "gl_FragData[1]"), kMaxBits + 1) << "slot 1 is not compared";
}

// The runner sets int/uint/bool uniforms (and verify feeds them from --range/spec values).
TEST(VerifyRealWorld, IntegerUniformsReachBothDrivers) {
  runner::GraphicsJob job;
  job.stage = runner::GraphicsStage::Vertex;
  job.glsl = "#version 310 es\nuniform int k;\nuniform uvec2 u;\nuniform bool b;\nout vec4 r;\n"
             "void main() { r = vec4(float(k), float(u.x), float(u.y), b ? 1.0 : -1.0); gl_Position = r; }\n";
  job.count = 2;
  job.uniforms = {{"k", {-3}}, {"u", {5, 7}}, {"b", {1}}};
  for (runner::Backend backend : {runner::Backend::Vulkan, runner::Backend::Gles}) {
    const runner::GraphicsResult got = runner::run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << runner::backend_name(backend) << ": " << got.error;
    EXPECT_EQ(got.outputs.at("r"), (std::vector<double>{-3, 5, 7, 1, -3, 5, 7, 1})) << runner::backend_name(backend);
  }
}

// Every sampler2D/3D/Cube reads the runner's test texture, the same texels on both drivers.
TEST(VerifyRealWorld, SamplersReadTheTestTextureOnBothDrivers) {
  runner::GraphicsJob job;
  job.stage = runner::GraphicsStage::Fragment;
  job.glsl = "#version 310 es\nprecision highp float;\nprecision highp sampler3D;\nuniform sampler2D t2;\n"
             "uniform sampler3D t3;\nuniform samplerCube cube;\nin vec2 uv;\nout vec4 a;\nout vec4 c;\nout vec4 f;\n"
             "void main() { a = texture(t2, uv); c = texture(t3, vec3(uv, 0.53125)); f = texture(cube, vec3(0.3, 1.0, 0.2)); }\n";
  job.count = 3;
  const uint32_t n = runner::kTextureSize;
  const std::pair<uint32_t, uint32_t> texel[3] = {{0, 0}, {5, 9}, {15, 2}};
  for (const auto& [x, y] : texel) {
    job.inputs["uv"].push_back((x + 0.5) / n);
    job.inputs["uv"].push_back((y + 0.5) / n);
  }
  const std::vector<float> plane = runner::test_texture(runner::TextureKind::Tex2D);
  const std::vector<float> volume = runner::test_texture(runner::TextureKind::Tex3D);
  const std::vector<float> cube = runner::test_texture(runner::TextureKind::Cube);
  const uint32_t layer = 8;  // z = 0.53125 is texel 8's centre
  // Direction (0.3, 1, 0.2): face +Y (2), s = (0.3 + 1) / 2 -> texel 10, t = (0.2 + 1) / 2 -> texel 9.
  const size_t cube_texel = ((2 * size_t{n} + 9) * n + 10) * 4;
  for (runner::Backend backend : {runner::Backend::Vulkan, runner::Backend::Gles}) {
    const runner::GraphicsResult got = runner::run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << runner::backend_name(backend) << ": " << got.error;
    for (size_t s = 0; s < 3; ++s)
      for (size_t c = 0; c < 4; ++c) {
        const size_t at = (size_t{texel[s].second} * n + texel[s].first) * 4 + c;
        EXPECT_EQ(got.outputs.at("a")[s * 4 + c], plane[at]) << runner::backend_name(backend) << " sample " << s;
        EXPECT_EQ(got.outputs.at("c")[s * 4 + c], volume[size_t{layer} * n * n * 4 + at])
            << runner::backend_name(backend) << " sample " << s;
        EXPECT_EQ(got.outputs.at("f")[s * 4 + c], cube[cube_texel + c]) << runner::backend_name(backend) << " cube";
      }
  }
}

// `out vec3 p,` on its own line in a parameter list is not a global output (nor an error).
TEST(VerifyRealWorld, ParameterOnItsOwnLineIsNotAnOutput) {
  const std::string glsl =
      "#version 310 es\nout vec4 color;\nvoid place(\n  out vec3 p,\n  in float s)\n{\n  p = vec3(s);\n}\n"
      "/* a comment with\nout float nothing;\n*/\nvoid main() { vec3 p; place(p, 2.0); color = vec4(p, 1.0); gl_Position = color; }\n";
  runner::GraphicsInterface iface;
  std::string error;
  ASSERT_TRUE(runner::reflect_graphics(runner::GraphicsStage::Vertex, glsl, &iface, &error)) << error;
  ASSERT_EQ(iface.outputs.size(), 2u);
  EXPECT_EQ(iface.outputs[0].name, "color");
  EXPECT_EQ(iface.outputs[1].name, "gl_Position");
  EXPECT_TRUE(iface.inputs.empty());
}

}  // namespace
}  // namespace doublet::verify

namespace doublet::verify {
namespace {

// An output interface block is captured member by member ("vs_out.n"); one without an instance
// name by member name.
TEST(VerifyRealWorld, InterfaceBlocksAreCapturedByMember) {
  const std::string glsl =
      "#version 320 es\nout VertexData {\n  flat vec3 n;\n  vec2 uv;\n} vs_out;\nout Extra {\n  float w;\n};\n"
      "void main() { vs_out.n = vec3(1.0); vs_out.uv = vec2(2.0); w = 3.0; gl_Position = vec4(0.0); }\n";
  runner::GraphicsInterface iface;
  std::string error;
  ASSERT_TRUE(runner::reflect_graphics(runner::GraphicsStage::Vertex, glsl, &iface, &error)) << error;
  ASSERT_EQ(iface.outputs.size(), 4u);
  EXPECT_EQ(iface.outputs[0].name, "vs_out.n");
  EXPECT_EQ(iface.outputs[1].name, "vs_out.uv");
  EXPECT_EQ(iface.outputs[2].name, "w");
  runner::GraphicsJob job;
  job.glsl = glsl;
  job.count = 2;
  for (runner::Backend backend : {runner::Backend::Vulkan, runner::Backend::Gles}) {
    const runner::GraphicsResult got = runner::run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << runner::backend_name(backend) << ": " << got.error;
    EXPECT_EQ(got.outputs.at("vs_out.uv"), (std::vector<double>{2, 2, 2, 2}));
    EXPECT_EQ(got.outputs.at("w"), (std::vector<double>{3, 3}));
  }
}

}  // namespace
}  // namespace doublet::verify
