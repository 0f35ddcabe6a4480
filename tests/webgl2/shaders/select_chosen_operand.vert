#version 450
// --target webgl2 numerically (tests/webgl2/CMakeLists.txt): ternaries on doubles and dvec2, which
// select_structs rewrites, with a side effect in the operands (calls: evaluating both operands
// would add 0.125 to r), in && and in a loop condition and step. Compared with native fp64.
in double a;
in double b;

flat out double r;
flat out double s;
flat out double t;
double bump(inout int calls, double v) {
  calls += 1;
  return v;
}
void main() {
  int calls = 0;
  int k = int(a * 2.0lf) - 3;
  double x = k > 0 ? bump(calls, a * b) : bump(calls, a / b);
  dvec2 v = (k > 1 && (k > 3 ? a : b) > 0.5lf) ? dvec2(a + b, a - b) : dvec2(a - b, a * b);
  double acc = a;
  for (int i = 0; (i < 3 ? acc : acc * 2.0lf) < 64.0lf && i < 8; acc = (i++ % 2 == 0 ? acc * 1.5lf + b : acc + a)) {}
  r = x + double(calls) * 0.125lf;
  s = v.x * v.y;
  t = acc;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
