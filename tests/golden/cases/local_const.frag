// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Local 'const' declarations whose initialisers are not constant expressions (GLSL 4.20+), used
// as call arguments, and a const parameter (issue 12): lowered as ordinary locals.
uniform double u;
uniform dvec2 v;
const double g = 1.0lf / 3.0lf;
varying vec2 uv;
double f(dvec2 p) { return p.x + p.y; }
double h(const double x) { const double y = x * x; return y; }
void main() {
  const double a = u * 2.0lf;
  const dvec2 p = v * a;
  const float fl = float(u);
  gl_FragColor = vec4(float(f(p)), float(a + h(g)), fl, 1.0);
}
