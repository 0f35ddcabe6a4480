// target: es300
#version 450
flat in dvec3 v;
out vec4 o;
void twice(inout double x) { x = x * 2.0lf; }
double split_off(out double rest, double x) { rest = x - 1.0lf; return x + rest; }
void main() {
  dvec3 w = v;
  dmat2 m = dmat2(w.x, w.y, w.z, 1.0lf);
  twice(w.y);
  twice(m[1][0]);
  double s = split_off(w.z, w.x) + 1.0lf;
  o = vec4(vec3(w), float(s + m[1][0]));
}
