// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Structs with double members (nested), arrays of doubles (constant and dynamic indexing),
// const double arrays, double function overloads, flat double varyings, discard.
struct Inner { double w; dvec2 uv; };
struct Outer { Inner inner; double scale[2]; dmat2 m; };
flat in double depth;
flat in int k;
uniform Outer params;
out vec4 color;
const double kTable[3] = double[3](0.5lf, 0.25lf, 0.125lf);
double twice(double x) { return x + x; }
dvec2 twice(dvec2 x) { return x + x; }
Outer make(double s) {
  Outer o;
  o.inner = Inner(s, dvec2(s, 1.0lf));
  o.scale[0] = s;
  o.scale[1] = twice(s);
  o.m = dmat2(s);
  return o;
}
void main() {
  Outer o = make(depth);
  double acc[4];
  for (int i = 0; i < 4; ++i) acc[i] = double(i) * o.scale[i % 2];
  acc[k] += kTable[k % 3] + params.scale[1];
  dvec2 t = twice(o.inner.uv) + o.m[1] + o.m * o.inner.uv + params.inner.uv;
  double s = acc[0] + acc[1] + acc[2] + acc[3] + o.inner.w * t.x;
  switch (int(s)) {
    case 0: s += 1.0lf; break;
    default: break;
  }
  if (s > 1.0lf) discard;
  color = vec4(float(s), float(t.y), float(kTable[1]), 1.0);
}
