#version 310 es
// Escape-time counts of a 64x64 grid around `center`, `scale` apart: a deep zoom where
// neighbouring points differ by less than a float can resolve near `center`.
#extension GL_GOOGLE_include_directive : require
#include "float_float_io.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, binding = 0) writeonly buffer Counts { uint counts[]; };

uniform dvec2 center;   // becomes center_hi / center_lo
uniform double scale;   // distance between neighbouring points
uniform int max_iterations;

void main() {
  uvec2 id = gl_GlobalInvocationID.xy;
  dvec2 c = center + dvec2(double(int(id.x) - 32), double(int(id.y) - 32)) * scale;
  dvec2 z = dvec2(0.0lf);
  int n = 0;
  while (n < max_iterations && dot(z, z) < 4.0lf) {
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
    ++n;
  }
  counts[id.y * 64u + id.x] = uint(n);
}
