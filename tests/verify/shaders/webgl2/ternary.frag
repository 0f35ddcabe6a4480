#version 300 es
// A double ternary: doublet lowers it to a ternary on df_double structs, which GLSL ES 3.00 allows
// and WebGL forbids ("ternary operator is not allowed for structures"). With --target es300,
// `doublet verify --backend webgl2` must report the browser's compile log as a driver failure.
precision highp float;
flat in dvec2 ab;
out vec4 color;
void main() {
  double r = ab.x > ab.y ? ab.x * ab.y : ab.x / ab.y;
  float hi = float(r);
  color = vec4(hi, float(r - double(hi)), 0.0, 0.0);
}
