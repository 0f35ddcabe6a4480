// reflect_compute: the interface `doublet verify` feeds and reads, from glslang's reflection.
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

const ShaderInterface::Member* member(const ShaderInterface& s, const std::string& name) {
  for (const auto& m : s.members)
    if (m.name == name) return &m;
  return nullptr;
}

TEST(Reflect, NativeDoubleComputeShader) {
  ShaderInterface s;
  std::string error;
  ASSERT_TRUE(reflect_compute(R"(#version 450
layout(local_size_x = 8, local_size_y = 2) in;
uniform dvec3 a;
uniform float f;
layout(std430, binding = 1) readonly buffer In { double k; dvec2 x[]; };
layout(std430, binding = 0) writeonly buffer Out { vec3 r[4]; };
void main() { uint i = gl_GlobalInvocationID.x; r[i % 4u] = vec3(a * x[i].x * k + f); }
)", &s, &error)) << error;
  EXPECT_EQ(s.local_size[0], 8u);
  EXPECT_EQ(s.local_size[1], 2u);
  ASSERT_EQ(s.uniforms.size(), 2u);
  for (const auto& u : s.uniforms) {
    if (u.name == "a") EXPECT_TRUE(u.is_double && u.components == 3);
    else EXPECT_TRUE(u.name == "f" && !u.is_double && u.components == 1) << u.name;
  }
  ASSERT_EQ(s.blocks.size(), 2u);
  const ShaderInterface::Member* x = member(s, "x");
  const ShaderInterface::Member* k = member(s, "k");
  const ShaderInterface::Member* r = member(s, "r");
  ASSERT_TRUE(x && k && r);
  EXPECT_TRUE(s.blocks[x->block].readonly);
  EXPECT_EQ(s.blocks[x->block].binding, 1);
  EXPECT_TRUE(s.blocks[r->block].writeonly);
  EXPECT_EQ(x->array_size, 0u);
  EXPECT_EQ(x->array_stride, 16u);
  EXPECT_EQ(x->offset, 16u);
  EXPECT_TRUE(x->is_double && x->components == 2);
  EXPECT_EQ(k->offset, 0u);
  EXPECT_EQ(r->array_size, 4u);
  EXPECT_EQ(r->array_stride, 16u);
  EXPECT_TRUE(!r->is_double && r->components == 3);
}

}  // namespace
}  // namespace doublet::runner::test
