// target: es310 mode: exact
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double a; double b; dvec3 v; dmat2 m; double out_x; uint count; };
// Pure: called twice below, so its calls share one site too; its own two products share one.
double cube(double x) { return x * x * x; }
void main() {
  double s = a * b + a * a;          // two products, one addition
  double t = cube(s) + cube(b);      // a user's pure function, twice
  dvec3 w = v * s + v * t;           // dvec3 products share one site; the matrix below does not
  dmat2 n = m * m;
  atomicAdd(count, 1u);              // writes memory: ends the run, stays in place
  double u = s > 0.0lf ? s * t : s * s;  // the ?: operands stay where they are
  out_x = u + w.x * w.y + n[0][0] + t * t;
}
