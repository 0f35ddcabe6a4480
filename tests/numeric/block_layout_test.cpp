// The manifest's std140/std430 offsets for lowered block members (src/lower/block_layout.cpp)
// agree with what the compilers assign: glslang's reflection of the lowered shader (the front end
// of the Vulkan backend), and Mesa GLES through a round trip: the host writes hi/lo at the
// manifest's offsets, the shader doubles every value, the host reads them back there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

const char* kShader = R"(#version 450
layout(local_size_x = 1) in;
struct Particle { dvec3 position; double mass; };
layout(std430, binding = 0) buffer Scene {
  double scale;
  dvec3 origin;
  dmat3 basis;
  float tag;
  dvec2 pairs[2];
  Particle particles[2];
} scene;
void main() {
  scene.scale *= 2.0lf;
  scene.origin *= 2.0lf;
  scene.basis *= 2.0lf;
  scene.tag *= 2.0;
  for (int i = 0; i < 2; ++i) {
    scene.pairs[i] *= 2.0lf;
    scene.particles[i].position *= 2.0lf;
    scene.particles[i].mass *= 2.0lf;
  }
}
)";

doublet::Result lowered(doublet::Target target) {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = target;
  o.file_name = "blocks.comp";
  return doublet::lower(kShader, o);
}

TEST(BlockLayout, ManifestOffsetsMatchGlslangReflection) {
  auto r = lowered(doublet::Target::Glsl450);
  ASSERT_TRUE(r.ok);
  doublet::runner::ShaderInterface iface;
  std::string error;
  ASSERT_TRUE(doublet::runner::reflect_compute(r.output, &iface, &error)) << error;
  std::map<std::string, uint32_t> reflected;
  for (const auto& m : iface.members) reflected[m.name] = m.offset;
  std::string names;
  for (const auto& [n, o] : reflected) names += n + "@" + std::to_string(o) + " ";
  ASSERT_EQ(r.manifest.variables.size(), 1u);
  int checked = 0;
  for (const auto& m : r.manifest.variables[0].members) {
    if (m.hi_offset < 0) continue;
    // Reflection names leaves without array indices: "Scene.pairs.hi", "Scene.particles.mass.lo".
    std::string base = m.name;
    for (size_t at; (at = base.find("[0]")) != std::string::npos;) base.erase(at, 3);
    for (const char* word : {"hi", "lo"}) {
      std::string leaf = base + "." + word;
      auto it = reflected.find(leaf);
      if (it == reflected.end()) it = reflected.find("Scene." + leaf);
      ASSERT_NE(it, reflected.end()) << leaf << " not reflected; reflected: " << names;
      EXPECT_EQ(it->second, static_cast<uint32_t>(m.offset + (word[0] == 'h' ? m.hi_offset : m.lo_offset))) << leaf;
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

// Columns and rows of a manifest type: double (1, 1), dvec3 (1, 3), dmat3 (3, 3), dmat2x4 (2, 4).
std::pair<int, int> shape(std::string type) {
  type = type.substr(0, type.find('['));
  if (type == "double") return {1, 1};
  if (type.rfind("dvec", 0) == 0) return {1, type[4] - '0'};
  int c = type[4] - '0';
  return {c, type.size() > 5 ? type[6] - '0' : c};
}

// Every float word of every double member, as (byte offset of hi, byte offset of lo).
std::vector<std::pair<uint32_t, uint32_t>> double_words(const doublet::InterfaceVariable& block) {
  std::map<std::string, const doublet::BlockMember*> by_name;
  for (const auto& m : block.members) by_name[m.name] = &m;
  std::vector<std::pair<uint32_t, uint32_t>> words;
  for (const auto& m : block.members) {
    if (m.hi_offset < 0) continue;
    // "particles[0].mass" repeats with the stride of "particles"; "pairs" with its own stride.
    int count = 1, stride = 0;
    if (auto bracket = m.name.find("[0]"); bracket != std::string::npos) {
      const doublet::BlockMember* array = by_name.at(m.name.substr(0, bracket));
      count = array->size / array->array_stride;
      stride = array->array_stride;
    } else if (m.array_stride) {
      count = m.size / m.array_stride;
      stride = m.array_stride;
    }
    auto [cols, rows] = shape(m.type);
    for (int e = 0; e < count; ++e)
      for (int c = 0; c < cols; ++c)
        for (int r = 0; r < rows; ++r) {
          uint32_t at = m.offset + e * stride + c * m.matrix_stride + r * 4;
          words.push_back({at + m.hi_offset, at + m.lo_offset});
        }
  }
  return words;
}

TEST(BlockLayout, HostWritesAtManifestOffsetsRoundTripOnGles) {
  ASSERT_EQ(doublet::runner::backend_unavailable_reason(doublet::runner::Backend::Gles), "");
  auto r = lowered(doublet::Target::Es310);
  ASSERT_TRUE(r.ok);
  const auto& block = r.manifest.variables.at(0);
  uint32_t size = 0;
  for (const auto& m : block.members) size = std::max<uint32_t>(size, m.offset + m.size);
  auto words = double_words(block);
  ASSERT_EQ(words.size(), 1u + 3u + 9u + 2u * 2u + 2u * 4u);
  std::vector<uint8_t> buffer(size, 0);
  std::vector<double> values;
  for (size_t k = 0; k < words.size(); ++k) {
    double v = std::ldexp(1.0 + 1.0 / 3.0 + static_cast<double>(k) / 7.0, static_cast<int>(k % 9) - 4);
    float hi = static_cast<float>(v), lo = static_cast<float>(v - hi);
    std::memcpy(&buffer[words[k].first], &hi, 4);
    std::memcpy(&buffer[words[k].second], &lo, 4);
    values.push_back(static_cast<double>(hi) + lo);
  }
  uint32_t tag_offset = 0;
  for (const auto& m : block.members)
    if (m.name == "tag") tag_offset = m.offset;
  float tag = 0.75f;
  std::memcpy(&buffer[tag_offset], &tag, 4);
  doublet::runner::ComputeJob job;
  job.glsl = r.output;
  job.buffers = {buffer};
  auto run = doublet::runner::run_compute(doublet::runner::Backend::Gles, job);
  ASSERT_TRUE(run.ok) << run.error;
  const auto& out = run.buffers[0];
  for (size_t k = 0; k < words.size(); ++k) {
    float hi, lo;
    std::memcpy(&hi, &out[words[k].first], 4);
    std::memcpy(&lo, &out[words[k].second], 4);
    EXPECT_EQ(static_cast<double>(hi) + lo, 2 * values[k]) << "word " << k << " at " << words[k].first;
  }
  float tag_out;
  std::memcpy(&tag_out, &out[tag_offset], 4);
  EXPECT_EQ(tag_out, 1.5f);
}

}  // namespace
