// targets: es300 glsl450 webgl2
#version 300 es
// optimize_df: an operand whose lo word is known to be zero (a float widened to double, a double
// constant that is exactly a float) takes the mixed rules: df_mul_f2 (DWTimesFP2), df_add_f
// (DWPlusFP); two such operands give the exact df_two_prod / df_two_sum.
precision highp float;
uniform double x;
uniform float f;
uniform float g;
out vec4 color;
void main() {
  double p = double(f) * x + x * 3.0lf;
  double s = x + double(f) - (double(g) - x) + 1.0lf;
  double e = double(f) * double(g) + (double(f) - double(g));
  double k = x * 0.1lf + x;
  color = vec4(float(p), float(s), float(e), float(k));
}
