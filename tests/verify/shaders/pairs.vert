#version 310 es
// Float-float arithmetic in the vertex stage: a split double output (r → r_hi/r_lo), a quotient
// exposed as a (hi, lo) float pair, and gl_Position narrowed from double.
in dvec2 a;
in double b;
uniform double k;
out dvec2 r;
flat out vec2 q;
void main() {
  r = dvec2(a.x * b, a.y + k);
  double s = a.x / b;
  q = vec2(float(s), float(s - double(float(s))));
  gl_Position = vec4(vec2(a - k), 0.0, 1.0);
}
