// targets: es310 es320 glsl450
#version 450
// Tessellation evaluation: per-vertex input arrays of doubles (hi/lo arrays, joined at main's
// start) interpolated in float-float with gl_TessCoord; the double output is split at main's end.
layout(triangles, equal_spacing, ccw) in;
in dvec3 control[];
patch in double height;
flat out dvec3 position;
uniform dvec3 eye;
void main() {
  dvec3 t = dvec3(gl_TessCoord);
  dvec3 p = control[0] * t.x + control[1] * t.y + control[2] * t.z;
  position = p + dvec3(0.0lf, height, 0.0lf);
  gl_Position = vec4(vec3(position - eye), 1.0);
}
