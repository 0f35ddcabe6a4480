// targets: es310 es320 glsl450
#version 450
// Tessellation control: per-patch double outputs, which any invocation may write. Their hi/lo
// patch outputs are stored right after each statement that writes the private copy (a whole
// assignment, a component, an out argument), never after a read, and the copy is joined again
// after barrier() (src/lower/split_interfaces.cpp, PatchOutput).
layout(vertices = 3) out;
in dvec3 p[];
out dvec3 q[];
patch out dvec3 center;
patch out double spread;
uniform dvec3 eye;

void widest(out double w) { w = max(distance(p[0], p[1]), distance(p[1], p[2])); }

void main() {
  if (gl_InvocationID == 0) {
    center = (p[0] + p[1] + p[2]) / 3.0lf;
    center.z -= eye.z;
  } else if (gl_InvocationID == 1) {
    widest(spread);
  }
  barrier();
  q[gl_InvocationID] = p[gl_InvocationID] - center;
  float level = float(clamp(spread / length(center - eye), 1.0lf, 16.0lf));
  gl_TessLevelOuter[gl_InvocationID] = level;
  gl_TessLevelInner[0] = level;
}
