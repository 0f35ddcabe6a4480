#version 310 es
// Float-float arithmetic in the fragment stage: a product of flat double inputs and a quotient by a
// double uniform (one operation each, so each meets its proven bound), written to the colour as
// (hi, lo) float pairs: fragment outputs cannot be double.
precision highp float;
flat in dvec2 a;
uniform double k;
out vec4 color;
void main() {
  double r = a.x * a.y;
  double q = a.x / k;
  color = vec4(float(r), float(r - double(float(r))), float(q), float(q - double(float(q))));
}
