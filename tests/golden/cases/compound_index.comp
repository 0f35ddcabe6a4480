// targets: es310 es320 glsl450
#version 310 es
// Compound assignment through a computed index: without side effects the element is read and
// written inline (array elements, vector components, matrix columns and elements); with them
// (i++, a call) it is passed once to an inout helper.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { uint k; double r[]; };
int next(inout int c) { c += 1; return c; }
void main() {
  double x[4] = double[4](1.0lf, 2.0lf, 3.0lf, 4.0lf);
  dvec3 y[2] = dvec3[2](dvec3(1.0lf), dvec3(2.0lf));
  dmat2 m[2] = dmat2[2](dmat2(1.0lf), dmat2(2.0lf));
  uint i = k;
  int c = int(k);
  x[i + 1u] += 0.5lf;
  y[c - 1] *= 2.0lf;
  x[i++] -= 0.5lf;
  x[next(c)] *= r[0];
  y[next(c) - 2] /= dvec3(3.0lf);
  m[next(c) - 3] *= dmat2(r[1]);
  dvec3 v = y[0];
  v[c - 2] += 1.0lf;
  dmat3 n = dmat3(r[2]);
  n[c - 3] += dvec3(1.0lf);
  n[c - 4][c - 3] -= 0.5lf;
  r[0] = x[1] + x[2] + y[0].y + v.z + m[1][1][1] + n[1][1];
}
