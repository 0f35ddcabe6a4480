#version 450
// Deep-zoom fractal: one fragment per pixel around a centre at 1e-10 units per pixel, where
// float cannot even tell neighbouring pixels apart. The orbit after a fixed number of steps
// leaves as (hi, lo) pairs.
#include "engine_common.glsl"

uniform dvec2 center;
uniform double pixel_size;
uniform int iterations;       // at most ENGINE_MAX_ITERATIONS (a constant loop bound, for ES 1.00)

flat in dvec2 pixel;          // pixel offset from the centre
out vec4 orbit;               // (re hi, re lo, im hi, im lo)

void main() {
  dvec2 c = center + pixel * pixel_size;
  dvec2 z = dvec2(0.0lf);
  for (int i = 0; i < ENGINE_MAX_ITERATIONS; ++i) {
    if (i >= iterations || dot(z, z) > 4.0lf) break;
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
  }
  orbit = vec4(hi_lo(z.x), hi_lo(z.y));
}
