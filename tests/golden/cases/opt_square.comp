// targets: es310 es320
#version 310 es
// optimize_df: a product of a value with itself becomes df_sqr (bit-identical to df_mul(x, x),
// 18 flops instead of 24) when both operands are the same side-effect-free expression; the
// product of two different values, or of a call's result with itself, stays df_mul.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Data { double x; double y; dvec2 z; double a[4]; double r[5]; };
void main() {
  r[0] = x * x;
  r[1] = z.x * z.x - z.y * z.y;
  r[2] = a[1] * a[1];
  r[3] = (x + y) * (x + y);
  r[4] = x * y;
}
