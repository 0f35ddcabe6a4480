// targets: glsl450
#version 450
// Subgroup operations that move a double between invocations move both words (GL_KHR_shader_subgroup_*);
// subgroup built-ins on other types pass through. Results against native fp64 (tests/golden CMake).
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_KHR_shader_subgroup_shuffle_relative : require
#extension GL_KHR_shader_subgroup_quad : require
#extension GL_KHR_shader_subgroup_vote : require
layout(local_size_x = 16) in;
layout(std430, binding = 0) buffer Data { dvec4 x[]; };
layout(std430, binding = 1) buffer Results { dvec4 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 v = x[i] * 3.0lf;
  uint lane = gl_SubgroupInvocationID;
  dvec4 a = subgroupShuffleXor(v, 1u) + subgroupBroadcast(v, 2u);
  double b = subgroupShuffle(v.y, lane ^ 3u) - subgroupBroadcastFirst(v.z) + subgroupQuadSwapHorizontal(v.w);
  dvec2 c = subgroupQuadBroadcast(v.xy, 1u) * double(subgroupBallotBitCount(subgroupBallot(v.x > 0.0lf)));
#ifdef EXACT  // subgroupAllEqual on binary64 words would tell +0 from -0: not lowered in mode exact
  bool same = subgroupAllEqual(v.x > 0.0lf);
#else
  bool same = subgroupAllEqual(v.x * 0.0lf);
#endif
  r[i] = a + dvec4(b, c, same ? 1.0lf : -1.0lf);
}
