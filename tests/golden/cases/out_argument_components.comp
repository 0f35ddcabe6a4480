// targets: es310 es320 glsl450
#version 450
// A component of a double vector or matrix passed to an out/inout parameter (f(v.y), f(v[i]),
// f(m[1][0]), f(m[0])) goes through a temporary; the results must equal native fp64's
// (tests/golden CMake).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Data { dvec4 x[]; };
layout(std430, binding = 1) buffer Results { dvec4 r[]; };
void scale(inout double x, double by) { x = x * by + 0.25lf; }
void column(out dvec2 c, double a) { c = dvec2(a, a * a); }
double take(inout double x) { double old = x; x = x / 3.0lf; return old; }
void main() {
  uint n = gl_GlobalInvocationID.x;
  dvec4 v = x[n];
  dvec4 w = v;
  dmat2 m = dmat2(v.x, v.y, v.z, v.w);
  int i = int(n) & 3;
  scale(w.y, w.x);
  scale(w[i], 1.5lf);
  scale(m[1][0], w.z);
  column(m[0], w.w);
  double s = take(w.z) + take(w.x);
  for (int j = 0; j < 2 && take(w.w) > 0.0lf; ++j) s += w.w;
  r[2u * n] = w;
  r[2u * n + 1u] = dvec4(s, m[0][1], m[1][0], m[0][0]);
}
