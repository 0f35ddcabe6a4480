// targets: es300 webgl2
#version 450
// Ternaries whose value is a double, a dvecN, a dmatN, a struct holding doubles or an array of
// doubles: lowered they select df_* structs, which WebGL forbids (docs/web.md), so on webgl2
// select_structs rewrites each into a selection through a temporary. Operands with side effects,
// nested ternaries, a ternary in a loop condition and step, in the right operand of && and ||.
struct Body { double mass; dvec2 at; };
uniform double ua;
uniform double ub;
uniform int un;
out vec4 color;
int calls = 0;
double counted(double v) {
  calls += 1;
  return v;
}
Body body(double m) { return Body(m, dvec2(m, -m)); }
void main() {
  int n = un;
  double x = n > 0 ? counted(ua) : counted(ub);
  double y = n > 1 ? (n > 2 ? ua : ub) : (n < -1 ? ua * ub : ua - ub);
  dvec2 v = n == 3 ? dvec2(ua, ub) : dvec2(ub, ua);
  dmat2 m = n != 0 ? dmat2(ua) : dmat2(ub);
  Body b = x > y ? body(x) : body(y);
  double table[2] = n > 0 ? double[2](ua, ub) : double[2](ub, ua);
  double acc = 0.0lf;
  for (int i = 0; (i < 2 ? acc + ua : acc - ub) < 8.0lf && i < 16; acc = (i++ > 4 ? acc * 2.0lf : acc + 1.0lf)) {}
  bool hit = n > 0 && (n > 5 ? ++n : n--) > 0 && (n > 1 ? ua : counted(ub)) > 0.5lf;
  bool miss = n < 0 || (n == 2 ? ua : counted(ua + ub)) < 0.25lf;
  double sum = x + y + v.x + m[1][1] + b.at.y + table[1] + acc + double(calls) + (hit ? 1.0lf : 0.0lf) +
               (miss ? 2.0lf : 0.0lf);
  color = vec4(float(sum), float(sum - double(float(sum))), 0.0, 1.0);
}
