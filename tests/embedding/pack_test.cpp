// doublet/pack.hpp against real manifests from doublet::lower: uniforms, interleaved
// vertex data, float-float arrays in blocks, and malformed manifests.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "doublet/pack.hpp"

namespace {
using namespace doublet::pack;

const char* kVertex = R"(#version 300 es
layout(location = 0) in dvec3 position;
layout(location = 2) in vec2 uv;
uniform dvec3 eye;
uniform double scale;
uniform mat4 viewProj;
out vec2 v_uv;
void main() {
  v_uv = uv;
  gl_Position = viewProj * vec4(vec3((position - eye) * scale), 1.0);
}
)";

Manifest lowered_manifest() {
  doublet::Options o;
  o.stage = doublet::Stage::Vertex;
  o.target = doublet::Target::Es300;
  o.file_name = "globe.vert";
  doublet::Result r = doublet::lower(kVertex, o);
  for (const auto& d : r.diagnostics) ADD_FAILURE() << doublet::format_diagnostic(d);
  std::string error;
  auto m = parse_manifest(r.manifest.to_json(), &error);
  EXPECT_TRUE(m.has_value()) << error;
  return m.value_or(Manifest{});
}

TEST(Pack, ParsesTheManifestDoubletWrites) {
  Manifest m = lowered_manifest();
  EXPECT_EQ(m.stage, "vert");
  EXPECT_EQ(m.target, "es300");
  EXPECT_EQ(m.guard_kind, "uniform");
  const Variable* position = m.find("position");
  ASSERT_NE(position, nullptr);
  EXPECT_TRUE(position->split);
  EXPECT_EQ(position->lowered_names, (std::vector<std::string>{"position_hi", "position_lo"}));
  EXPECT_EQ(position->components(), 3);
  EXPECT_EQ(position->locations.size(), 2u);
  const Variable* uv = m.find("uv");
  ASSERT_NE(uv, nullptr);
  EXPECT_FALSE(uv->split);
  EXPECT_EQ(m.find("nothing"), nullptr);
}

TEST(Pack, UniformValuesSplitEachComponent) {
  Manifest m = lowered_manifest();
  const double eye[3] = {6378137.123456789, -1.0 / 3.0, 42.0};
  auto values = uniform_values(*m.find("eye"), eye);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].name, "eye_hi");
  EXPECT_EQ(values[1].name, "eye_lo");
  EXPECT_EQ(values[0].components, 3);
  for (int c = 0; c < 3; ++c) {
    doublet::FloatPair p = doublet::split(eye[c]);
    EXPECT_EQ(values[0].value[c], p.hi);
    EXPECT_EQ(values[1].value[c], p.lo);
  }
  EXPECT_EQ(uniform_values(*m.find("scale"), {0.1}).size(), 2u);
  EXPECT_TRUE(uniform_values(*m.find("scale"), {0.1, 0.2}).empty()) << "wrong component count";
}

// A uniform declared with an initializer: on ES the lowered shader declares it without one (a
// warning says so) and the manifest carries the value; on desktop GLSL both words are initialised
// to doublet::split of it. The values below are the shader's own literals.
const char* kInitialised = R"(#version 450
uniform double zoom = 6378137.123456789lf;
uniform dvec2 center = dvec2(-0.333333333333333314829616256247lf, 42.0lf);
uniform int steps = 3;
flat in dvec2 p;
layout(location = 0) out vec4 o;
void main() {
  dvec2 z = p;
  for (int k = 0; k < steps; ++k) z = z * zoom + center;
  o = vec4(vec2(z), 0.0, 1.0);
}
)";

doublet::Result lower_initialised(doublet::Target target) {
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.target = target;
  o.file_name = "zoom.frag";
  return doublet::lower(kInitialised, o);
}

TEST(Pack, UniformDefaultsReachTheManifestOnEs) {
  doublet::Result r = lower_initialised(doublet::Target::Es300);
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].severity, doublet::Severity::Warning);
  EXPECT_NE(r.diagnostics[0].message.find("'zoom', 'center', 'steps'"), std::string::npos) << r.diagnostics[0].message;
  EXPECT_EQ(r.output.find("= 6378137"), std::string::npos) << "ES has no uniform initializers";
  std::string error;
  auto m = parse_manifest(r.manifest.to_json(), &error);
  ASSERT_TRUE(m.has_value()) << error;
  EXPECT_EQ(m->find("zoom")->default_value, (std::vector<double>{6378137.123456789}));
  EXPECT_EQ(m->find("center")->default_value, (std::vector<double>{-0.333333333333333314829616256247, 42.0}));
  EXPECT_EQ(m->find("steps")->default_value, (std::vector<double>{3.0}));
  auto values = uniform_values(*m->find("zoom"), m->find("zoom")->default_value);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].value[0], doublet::split(6378137.123456789).hi);
  EXPECT_EQ(values[1].value[0], doublet::split(6378137.123456789).lo);
}

TEST(Pack, UniformInitializersAreSplitOnDesktop) {
  for (doublet::Target t : {doublet::Target::Glsl330, doublet::Target::Glsl450}) {
    doublet::Result r = lower_initialised(t);
    ASSERT_TRUE(r.ok);
    EXPECT_TRUE(r.diagnostics.empty());
    // The printed literals, read back as floats, are split()'s words.
    auto literal = [&](const std::string& declaration) {
      const size_t at = r.output.find(declaration);
      EXPECT_NE(at, std::string::npos) << declaration;
      return at == std::string::npos ? 0.0f : std::strtof(r.output.c_str() + at + declaration.size(), nullptr);
    };
    const doublet::FloatPair zoom = doublet::split(6378137.123456789);
    EXPECT_EQ(literal("uniform float zoom_hi = "), zoom.hi);
    EXPECT_EQ(literal("uniform float zoom_lo = "), zoom.lo);
    EXPECT_NE(zoom.lo, 0.0f);
    const doublet::FloatPair cx = doublet::split(-0.333333333333333314829616256247);
    EXPECT_EQ(literal("uniform vec2 center_hi = vec2("), cx.hi);
    EXPECT_EQ(literal("uniform vec2 center_lo = vec2("), cx.lo);
    EXPECT_NE(r.output.find("uniform int steps = 3;"), std::string::npos);
  }
}

TEST(Pack, VertexLayoutInterleavesHiLoAndFloats) {
  Manifest m = lowered_manifest();
  VertexLayout layout = vertex_layout(m, {"position", "uv"});
  ASSERT_TRUE(layout.ok()) << layout.error;
  ASSERT_EQ(layout.slots.size(), 3u);
  EXPECT_EQ(layout.stride_floats, 8u);
  EXPECT_EQ(layout.slots[0].name, "position_hi");
  EXPECT_EQ(layout.slots[1].name, "position_lo");
  EXPECT_EQ(layout.slots[1].offset_floats, 3u);
  EXPECT_EQ(layout.slots[2].name, "uv");
  EXPECT_EQ(layout.slots[2].offset_floats, 6u);
  EXPECT_EQ(layout.slots[0].location, m.find("position")->locations[0]);

  const std::vector<double> positions = {1e7 + 0.1, 2.0, 3.0, -4.0, 5.5e6 + 1.0 / 3.0, 6.0};
  const std::vector<double> uvs = {0.25, 0.5, 0.75, 1.0};
  std::vector<float> vbo;
  std::string error;
  ASSERT_TRUE(pack_vertices(layout, {{"position", positions}, {"uv", uvs}}, vbo, &error)) << error;
  ASSERT_EQ(vbo.size(), 16u);
  for (int v = 0; v < 2; ++v) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(doublet::join(vbo[8 * v + c], vbo[8 * v + 3 + c]), doublet::join(doublet::split(positions[3 * v + c])));
    EXPECT_EQ(vbo[8 * v + 6], static_cast<float>(uvs[2 * v]));
    EXPECT_EQ(vbo[8 * v + 7], static_cast<float>(uvs[2 * v + 1]));
  }
}

TEST(Pack, VertexPackingRejectsMismatches) {
  Manifest m = lowered_manifest();
  EXPECT_FALSE(vertex_layout(m, {"eye"}).ok()) << "a uniform is not a vertex input";
  EXPECT_FALSE(vertex_layout(m, {"missing"}).ok());
  VertexLayout layout = vertex_layout(m, {"position", "uv"});
  std::vector<float> vbo;
  const std::vector<double> one_vertex = {1, 2, 3}, two_uvs = {0, 0, 1, 1}, half_vec = {1, 2};
  std::string error;
  EXPECT_FALSE(pack_vertices(layout, {{"position", one_vertex}, {"uv", two_uvs}}, vbo, &error));
  EXPECT_NE(error.find("vertex counts"), std::string::npos) << error;
  EXPECT_FALSE(pack_vertices(layout, {{"position", one_vertex}}, vbo, &error));
  EXPECT_FALSE(pack_vertices(layout, {{"position", half_vec}, {"uv", two_uvs}}, vbo, &error));
}

TEST(Pack, PairLayoutsFollowStd140AndStd430) {
  EXPECT_EQ(pair_layout(1, BlockLayout::Std430).stride, 2u);
  EXPECT_EQ(pair_layout(1, BlockLayout::Std140).stride, 4u);
  EXPECT_EQ(pair_layout(2, BlockLayout::Std430).lo_offset, 2u);
  EXPECT_EQ(pair_layout(3, BlockLayout::Std430).lo_offset, 4u);  // vec3 is 16-byte aligned
  EXPECT_EQ(pair_layout(3, BlockLayout::Std430).stride, 8u);
  EXPECT_EQ(pair_layout(4, BlockLayout::Std140).stride, 8u);

  std::vector<float> out;
  const std::vector<double> values = {1.0 / 3.0, 2.0 / 3.0, 1e-3, 4.0, 5.0, 6.0};
  pack_pairs(values, 3, BlockLayout::Std430, out);
  ASSERT_EQ(out.size(), 16u);
  EXPECT_EQ(doublet::join(out[1], out[5]), doublet::join(doublet::split(values[1])));
  EXPECT_EQ(out[3], 0.0f) << "padding is zero";
  EXPECT_EQ(doublet::join(out[8 + 2], out[8 + 6]), doublet::join(doublet::split(values[5])));
}

TEST(Pack, MalformedManifestsAreReported) {
  std::string error;
  EXPECT_FALSE(parse_manifest("", &error));
  EXPECT_FALSE(error.empty());
  EXPECT_FALSE(parse_manifest("[1, 2]", &error));
  EXPECT_FALSE(parse_manifest(R"({"stage": "vert"})", &error));
  EXPECT_FALSE(parse_manifest(R"({"variables": [{"name": "x", "split": true, "lowered_names": ["x_hi"]}]})", &error));
  EXPECT_FALSE(parse_manifest(R"({"variables": [)", &error));
  auto ok = parse_manifest(R"({"variables": [{"name": "a\u0062", "split": false, "lowered_type": "vec2",
                                              "lowered_names": ["ab"], "locations": [3]}], "guard": {"kind": "none"}})",
                           &error);
  ASSERT_TRUE(ok) << error;
  EXPECT_EQ(ok->variables[0].name, "ab");
  EXPECT_EQ(ok->variables[0].location(0), 3);
  EXPECT_EQ(ok->guard_kind, "none");
}

}  // namespace
