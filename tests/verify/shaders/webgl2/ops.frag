#version 300 es
// Held-out-style accuracy check of float-float arithmetic in the fragment stage, for
// `doublet verify --backend webgl2` (tests/verify/webgl2_verify_test.cpp): add, sub, mul, div and
// sqrt of random operands, a cancelling sum, and a three-stage expression, each result written
// as a (hi, lo) float pair (fragment outputs cannot be double; the spec joins them).
precision highp float;
flat in dvec2 ab;  // operands: log-uniform magnitudes in [2^-20, 2^20], random signs
flat in dvec2 cd;  // cancellation pairs from the spec: d = -c (1 + 2^-k)
flat in dvec3 e;   // positive operands of the three-stage expression
layout(location = 0) out vec4 add_sub;
layout(location = 1) out vec4 mul_div;
layout(location = 2) out vec4 sqrt_cancel;
layout(location = 3) out vec4 chain;
vec2 pair(double r) {
  float hi = float(r);
  return vec2(hi, float(r - double(hi)));
}
void main() {
  add_sub = vec4(pair(ab.x + ab.y), pair(ab.x - ab.y));
  mul_div = vec4(pair(ab.x * ab.y), pair(ab.x / ab.y));
  sqrt_cancel = vec4(pair(sqrt(abs(ab.x))), pair(cd.x + cd.y));
  double fma_like = e.x * e.y + e.z;
  chain = vec4(pair(sqrt(fma_like) / (e.x + e.y)), pair(fma_like));
}
