// targets: es310 es320 glsl450
#version 310 es
// A comma expression as a function argument, an initialiser and an array constructor element
// keeps its parentheses: h((v, 2.0lf)) calls h(double), not h(dvec2, double).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double r[]; };
double h(double a) { return a + 1.0lf; }
double h(dvec2 a, double b) { return a.x * b; }
void main() {
  dvec2 v = dvec2(r[0], r[1]);
  r[2] = h((v, 2.0lf));
  double q = (v, 3.0lf);
  double arr[2] = double[2]((v, 4.0lf), 5.0lf);
  r[3] = q + arr[0];
  for (int i = 0, j = 1; i < 2; ++i, j += 2) r[4] += double(j);
}
