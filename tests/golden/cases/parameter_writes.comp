// targets: wgsl
#version 450
// A parameter written through a swizzle (doublet's df_assign_* helper takes it by pointer) and
// passed to an out parameter: WGSL parameters are immutable and have no address, so each gets a
// local copy (Chromium rejected "&p0", found by the differential tester, docs/robustness.md).
// A comma inside an expression becomes a statement before it (src/lower/hoist_commas.cpp).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { dvec4 v[]; };
double scratch;
void halve(inout double x) { x *= 0.5lf; }
dvec2 bend(dvec4 p, double q) {
  p.yz = p.zy + dvec2(q);
  halve(q);
  return p.yz * q;
}
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 a = v[i];
  a.zw = bend(a, a.w);
  a.xy = (scratch = a.z * 2.0lf, dvec2(scratch)) + a.xy;
  v[i] = a;
}
