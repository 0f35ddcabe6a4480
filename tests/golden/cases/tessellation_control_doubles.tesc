// targets: es310 es320 glsl450
#version 450
// Tessellation control: per-vertex double inputs (hi/lo arrays, joined at main's start); each
// invocation stores its own vertex of a per-vertex double output (q[gl_InvocationID]) at main's
// end (src/lower/split_interfaces.cpp); a double decides the tessellation levels.
layout(vertices = 3) out;
in dvec3 p[];
out dvec3 q[];
uniform dvec3 eye;
uniform double detail;
void main() {
  dvec3 rel = p[gl_InvocationID] - eye;
  q[gl_InvocationID] = rel * 2.0lf;
  float level = float(clamp(detail / length(rel), 1.0lf, 16.0lf));
  gl_TessLevelOuter[gl_InvocationID] = level;
  gl_TessLevelInner[0] = level;
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
}
