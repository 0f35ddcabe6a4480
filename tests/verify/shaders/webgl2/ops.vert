#version 300 es
// Held-out-style accuracy check of float-float arithmetic in the vertex stage, for
// `doublet verify --backend webgl2` (tests/verify/webgl2_verify_test.cpp): add, sub, mul, div and
// sqrt of random operands, a cancelling sum, and a three-stage expression, as double outputs
// (the lowering splits each into _hi/_lo float outputs; transform feedback captures them).
in dvec2 ab;  // operands: log-uniform magnitudes in [2^-20, 2^20], random signs
in dvec2 cd;  // cancellation pairs from the spec: d = -c (1 + 2^-k)
in dvec3 e;   // positive operands of the three-stage expression
out dvec4 add_sub_mul_div;
out dvec2 sqrt_cancel;
out double chain;
void main() {
  add_sub_mul_div = dvec4(ab.x + ab.y, ab.x - ab.y, ab.x * ab.y, ab.x / ab.y);
  sqrt_cancel = dvec2(sqrt(abs(ab.x)), cd.x + cd.y);
  chain = sqrt(e.x * e.y + e.z) / (e.x + e.y);
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
