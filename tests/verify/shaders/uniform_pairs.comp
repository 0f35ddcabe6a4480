#version 310 es
// Double uniforms (split into _hi/_lo by the lowering), one sample per dispatch; each result is
// stored as a (hi, lo) float pair so the float interface keeps ~48 bits.
layout(local_size_x = 1) in;
uniform dvec2 a;
uniform double s;
layout(std430, binding = 0) writeonly buffer Result { vec4 r; };
vec2 pair(double x) { float hi = float(x); return vec2(hi, float(x - double(hi))); }
void main() {
  dvec2 v = a * s + a.yx;
  r = vec4(pair(v.x), pair(v.y / s));
}
