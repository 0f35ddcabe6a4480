// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Non-square double matrices outside compute (they need ES 3.00: ES 1.00 has square ones only).
uniform dmat3x2 project;
uniform dmat2x4 lift;
in dvec3 position;
void main() {
  dvec2 p = project * position;
  dvec4 q = lift * p + dvec4(position, 1.0lf) * transpose(lift)[0][1];
  dmat4x2 t = transpose(lift) * 2.0lf;
  gl_Position = vec4(q + dvec4(t[3], p));
}
