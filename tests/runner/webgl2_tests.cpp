// The WebGL2 graphics backend (src/runner/webgl2.hpp) in the real headless Chromium: values reach
// a vertex or fragment stage and come back bit for bit (signed zeros, infinities, denormals, NaN for
// a discarded fragment), several passes when outputs exceed one program's slots, uniforms of every
// kind, a std140 uniform block, the test texture, and a compile error with the browser's info log.
// Every program runs in one run_graphics_batches call: one browser start for the whole file's data.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "browser_test_util.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;
using doublet::runner::GraphicsJob;
using doublet::runner::GraphicsResult;
using doublet::runner::GraphicsStage;

constexpr uint32_t kCount = 200;  // not a multiple of 64: the last row of the grid is partial

// Input component k of sample i: every class of float value, and ordinary ones in between.
float input_value(uint32_t i, int k) {
  const float specials[] = {0.0f, -0.0f, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            0x1p-149f, -0x1.fffffcp-127f, 0x1.fffffep127f, 1.0f / 3.0f};
  const uint32_t n = i * 4 + static_cast<uint32_t>(k);
  if (n % 5 == 0) return specials[(n / 5) % 8];
  return std::ldexp(1.0f + static_cast<float>(n % 977) / 977.0f, static_cast<int>(n % 61) - 30) * (n % 3 ? 1.0f : -1.0f);
}

std::vector<double> inputs(int components) {
  std::vector<double> v;
  for (uint32_t i = 0; i < kCount; ++i)
    for (int k = 0; k < components; ++k) v.push_back(input_value(i, k));
  return v;
}

uint32_t bits(double stored_float) { return std::bit_cast<uint32_t>(static_cast<float>(stored_float)); }

// Copies: the identity, so any change of bits is the transport's. Five vec4 outputs and gl_FragData
// style names are more than one fragment pass (4 attachments) holds.
constexpr const char* kCopyFragment = R"(#version 300 es
precision highp float;
flat in vec4 v;
flat in vec2 w;
layout(location = 0) out vec4 o0;
layout(location = 1) out vec4 o1;
layout(location = 2) out vec4 o2;
layout(location = 3) out vec4 o3;
layout(location = 4) out vec4 o4;
void main() {
  o0 = v;
  o1 = v.wzyx;
  o2 = vec4(w, w.yx);
  o3 = vec4(v.xy, w);
  o4 = -v;
}
)";

// 17 vec4 outputs and gl_Position: two transform-feedback passes (15 slots each).
std::string copy_vertex() {
  std::string s = "#version 300 es\nin vec4 v;\n";
  for (int k = 0; k < 17; ++k) s += "out vec4 o" + std::to_string(k) + ";\n";
  s += "void main() {\n";
  for (int k = 0; k < 17; ++k) s += "  o" + std::to_string(k) + " = v * " + std::to_string(1 << (k % 4)) + ".0;\n";
  return s + "  gl_Position = v.yxwz;\n}\n";
}

// Uniforms (float, vec3, mat2, int, uint, bool), a std140 block, the 2D test texture and discard.
constexpr const char* kResourcesFragment = R"(#version 300 es
precision highp float;
flat in vec2 uv;
uniform float f;
uniform vec3 v3;
uniform mat2 m;
uniform int i;
uniform uint u;
uniform bool b;
layout(std140) uniform Block { vec4 first; float second; } blk;
uniform highp sampler2D tex;
layout(location = 0) out vec4 scalars;
layout(location = 1) out vec4 matrix;
layout(location = 2) out vec4 block;
layout(location = 3) out vec4 texel;
void main() {
  if (uv.x < 0.0) discard;
  scalars = vec4(f, v3.z, float(i), float(u) + (b ? 256.0 : 0.0));
  matrix = vec4(m[0], m[1]);
  block = vec4(blk.first.yw, blk.second, 0.0);
  texel = texelFetch(tex, ivec2(uv), 0);
}
)";

TEST(WebGl2Runner, ValuesTravelBitExactlyAndErrorsCarryTheInfoLog) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  GraphicsJob fragment{GraphicsStage::Fragment, kCopyFragment, kCount};
  fragment.inputs["v"] = inputs(4);
  fragment.inputs["w"] = inputs(2);
  GraphicsJob vertex{GraphicsStage::Vertex, copy_vertex(), kCount};
  vertex.inputs["v"] = inputs(4);

  GraphicsJob resources{GraphicsStage::Fragment, kResourcesFragment, kCount};
  for (uint32_t s = 0; s < kCount; ++s) {
    // Every fifth sample discards; the others fetch texel (s % 16, s / 16 % 16).
    resources.inputs["uv"].push_back(s % 5 == 4 ? -1.0 : static_cast<double>(s % 16));
    resources.inputs["uv"].push_back(static_cast<double>(s / 16 % 16));
  }
  resources.uniforms = {{"f", {0x1.8p-140}}, {"v3", {1, 2, -0x1.000002p+3}}, {"m", {1.5, -2, 0.25, 7}},
                        {"i", {-9}}, {"u", {4000000000.0}}, {"b", {1}}};
  std::vector<float> block(8, 0.0f);  // std140: vec4 first at 0, float second at 16
  block[1] = -0.0f;
  block[3] = 0x1.234566p+100f;
  block[4] = 0x1p-126f;
  resources.uniform_blocks["Block"].resize(block.size() * 4);
  std::memcpy(resources.uniform_blocks["Block"].data(), block.data(), block.size() * 4);

  GraphicsJob rejected{GraphicsStage::Fragment,
                       "#version 300 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = undeclared_name; }\n", 4};

  const auto batches = doublet::runner::run_graphics_batches(Backend::WebGl2, {{fragment}, {vertex}, {resources}, {rejected}});
  ASSERT_EQ(batches.size(), 4u);
  for (size_t b = 0; b < 3; ++b) ASSERT_TRUE(batches[b].back().ok) << "batch " << b << ": " << batches[b].back().error;
  EXPECT_FALSE(batches[0][0].device.empty());

  const GraphicsResult& f = batches[0][0];
  for (uint32_t s = 0; s < kCount; ++s)
    for (int k = 0; k < 4; ++k) {
      const float x = input_value(s, k);
      EXPECT_EQ(bits(f.outputs.at("o0")[s * 4 + k]), std::bit_cast<uint32_t>(x)) << "sample " << s << " component " << k;
      EXPECT_EQ(bits(f.outputs.at("o1")[s * 4 + 3 - k]), std::bit_cast<uint32_t>(x));
      // The fifth output comes from a second pass. Negation is arithmetic: SwiftShader flushes a
      // denormal operand to zero there (copies, above, keep it).
      if (std::fpclassify(x) != FP_SUBNORMAL)
        EXPECT_EQ(bits(f.outputs.at("o4")[s * 4 + k]), std::bit_cast<uint32_t>(-x));
    }

  const GraphicsResult& v = batches[1][0];
  for (uint32_t s = 0; s < kCount; ++s)
    for (int k = 0; k < 4; ++k) {
      const float x = input_value(s, k);
      for (int o = 0; o < 17; ++o) {
        const float want = x * static_cast<float>(1 << (o % 4));  // exact unless it overflows (to Inf) or is a denormal
        if (std::fpclassify(x) == FP_SUBNORMAL) continue;  // the stage may flush denormal products
        EXPECT_EQ(bits(v.outputs.at("o" + std::to_string(o))[s * 4 + k]), std::bit_cast<uint32_t>(want))
            << "o" << o << " sample " << s << " component " << k;
      }
      EXPECT_EQ(bits(v.outputs.at("gl_Position")[s * 4 + (k ^ 1)]), std::bit_cast<uint32_t>(x));
    }

  const GraphicsResult& r = batches[2][0];
  const std::vector<float> texture = doublet::runner::test_texture(doublet::runner::TextureKind::Tex2D);
  for (uint32_t s = 0; s < kCount; ++s) {
    const double* scalars = &r.outputs.at("scalars")[s * 4];
    if (s % 5 == 4) {  // discarded: never written, reads as NaN like on the other backends
      EXPECT_TRUE(std::isnan(scalars[0])) << "sample " << s;
      continue;
    }
    EXPECT_EQ(bits(scalars[0]), std::bit_cast<uint32_t>(0x1.8p-140f));  // a denormal uniform, copied
    EXPECT_EQ(scalars[1], -0x1.000002p+3);
    EXPECT_EQ(scalars[2], -9.0);
    EXPECT_EQ(scalars[3], 4000000256.0);  // exact in float: 0xEE6B29 << 8
    const std::vector<double> matrix(&r.outputs.at("matrix")[s * 4], &r.outputs.at("matrix")[s * 4 + 4]);
    EXPECT_EQ(matrix, (std::vector<double>{1.5, -2, 0.25, 7}));
    const double* blk = &r.outputs.at("block")[s * 4];
    EXPECT_EQ(bits(blk[0]), std::bit_cast<uint32_t>(-0.0f));
    EXPECT_EQ(blk[1], 0x1.234566p+100f);
    EXPECT_EQ(blk[2], 0x1p-126f);
    const size_t texel = ((s / 16 % 16) * 16 + s % 16) * 4;
    for (int c = 0; c < 4; ++c) EXPECT_EQ(r.outputs.at("texel")[s * 4 + c], texture[texel + c]) << "sample " << s;
  }

  ASSERT_FALSE(batches[3].back().ok);
  EXPECT_NE(batches[3].back().error.find("undeclared_name"), std::string::npos) << batches[3].back().error;
  EXPECT_NE(batches[3].back().error.find("compile failed"), std::string::npos) << batches[3].back().error;
}

TEST(WebGl2Runner, OnlyEs100And300TextRuns) {
  // Decided before any browser starts, so this needs none.
  GraphicsJob job{GraphicsStage::Fragment, "#version 310 es\nprecision highp float;\nout vec4 o;\nvoid main() { o = vec4(1.0); }\n", 1};
  const GraphicsResult r = doublet::runner::run_graphics(Backend::WebGl2, job);
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.error.find("GLSL ES 1.00 and 3.00"), std::string::npos) << r.error;
  EXPECT_FALSE(doublet::runner::run_compute(Backend::WebGl2, {}).ok);
}

}  // namespace
