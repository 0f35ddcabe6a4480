// targets: es310 es320
#version 310 es
// optimize_df: products and quotients by powers of two become exact scalings (df_mul_pow2);
// 3.0 and 0.1 are not powers of two (0.1 is not even a float: it keeps the general product).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Data { double x; dvec3 v; double r[6]; dvec3 rv; };
void main() {
  r[0] = x * 2.0lf;
  r[1] = 0.5lf * x;
  r[2] = x / 4.0lf;
  r[3] = x * -0.125lf;
  r[4] = x * 3.0lf;
  r[5] = x * 0.1lf;
  rv = v * 2.0lf + v / dvec3(2.0lf, 4.0lf, 0.5lf);
}
