// targets: es310 es320 glsl450
#version 450
// Built-ins that involve no double pass through unchanged (issue 24): atomicLoad/atomicStore
// (GL_KHR_memory_scope_semantics), subgroup built-ins on floats and uints, next to double code.
#extension GL_KHR_memory_scope_semantics : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Counter { uint n; float total; };
layout(std430, binding = 1) buffer Data { double y[]; };
void main() {
  uint seen = atomicLoad(n, gl_ScopeDevice, gl_StorageSemanticsBuffer, gl_SemanticsRelaxed);
  float partial = subgroupAdd(float(gl_LocalInvocationID.x));
  uvec4 mask = subgroupBallot(partial > 1.0);
  if (subgroupElect()) atomicStore(n, seen + subgroupBallotBitCount(mask), gl_ScopeDevice, gl_StorageSemanticsBuffer, gl_SemanticsRelaxed);
  y[gl_GlobalInvocationID.x] = y[gl_GlobalInvocationID.x] * 3.0lf + double(partial);
}
