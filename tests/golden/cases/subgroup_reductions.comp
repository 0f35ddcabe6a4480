// targets: es310 glsl450
#version 450
// Reductions and scans on doubles (GL_KHR_shader_subgroup_arithmetic/_clustered): one loop over the
// active lanes in id order, both words moved by shuffles, combined with the mode's double operation
// (docs/accuracy.md, "Subgroup reductions"). Against native fp64 on lavapipe (tests/golden CMake),
// without the clustered forms there (-D NATIVE_ORACLE): Mesa 22.3's lavapipe ignores the cluster size.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_clustered : require
layout(local_size_x = 16) in;
layout(std430, binding = 0) buffer Data { dvec4 x[]; };
layout(std430, binding = 1) buffer Results { dvec3 r[]; };
layout(std430, binding = 2) buffer More { dvec2 s[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec3 v = x[i].xyz;
  double y = x[i].w;
  if (y > 0.5lf) return;  // inactive lanes
  r[i] = subgroupAdd(v) + subgroupInclusiveAdd(v) - subgroupExclusiveAdd(v) * 0.5lf;
  double m = subgroupMul(y + 1.0lf) + subgroupExclusiveMul(y);
  dvec2 mm = subgroupMin(v.xy) - subgroupInclusiveMax(v.yz) + subgroupExclusiveMin(v.zx) - subgroupMax(v.xy);
#ifndef NATIVE_ORACLE
  mm += subgroupClusteredAdd(v.yx, 4u) + subgroupClusteredMin(v.zy, 2u);
  m -= subgroupClusteredMax(y, 8u) * subgroupClusteredMul(v.x, 2u);
#endif
  s[i] = mm + m;
}
