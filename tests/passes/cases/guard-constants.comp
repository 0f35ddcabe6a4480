// target: es310
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) writeonly buffer Out { double r[]; };
double g = 0.7lf;
double product(double a, double b) { return a * b; }
dvec2 transform(dmat2 m, dvec2 v) { return m * v; }
void main() {
  r[0] = product(-2.5315213579651239lf, g);
  dvec2 t = transform(dmat2(1.1lf, 2.2lf, 3.3lf, 4.4lf), dvec2(0.1lf, 0.3lf));
  r[1] = t.x + t.y * 2.0lf;
}
