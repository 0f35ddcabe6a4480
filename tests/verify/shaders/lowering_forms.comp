#version 310 es
// Issue 13: forms the printer and lowering once got wrong, each stored as a (hi, lo) pair and
// compared with native fp64: a comma expression as an argument and in initialisers (it must stay
// one argument), a double loop index, compound assignment through a computed index (with and
// without side effects: c++ must run once), and a swizzle of a swizzle written.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 operands[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec2 results[]; };
void store(uint slot, double r) { float hi = float(r); results[slot] = vec2(hi, float(r - double(hi))); }
double h(double a) { return a * a + 1.0lf; }
double h(dvec2 a, double b) { return a.x * b - a.y; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = operands[i];
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  dvec2 p = dvec2(x, y);
  uint slot = i * 8u;
  store(slot + 0u, h((p, x)));
  double q = (p, y);
  double b[2] = double[2]((p, x), y);
  store(slot + 1u, q + b[0] * b[1]);
  double s = 0.0lf;
  for (double t = 0.0lf; t < 2.0lf; t += 0.25lf) s += t * x;
  store(slot + 2u, s);
  double a[4] = double[4](x, y, x * y, x - y);
  uint k = i % 3u;
  a[k + 1u] += y / 3.0lf;
  int c = 0;
  a[c++] *= x;
  store(slot + 3u, a[k + 1u]);
  store(slot + 4u, a[0]);
  store(slot + 5u, double(c));
  dvec4 w = dvec4(x, y, x + y, x * y);
  w.xz.y = y * 0.375lf + x;
  w.wzyx.yx += dvec2(x, y);
  store(slot + 6u, w.z);
  store(slot + 7u, w.w);
}
