#version 300 es
// Deep-zoom Mandelbrot: with `scale` (the width of a pixel) below ~1e-7, neighbouring
// pixels have the same float coordinates and a float shader draws blocks; in double
// (float-float after lowering) the zoom goes on to ~1e-13.
precision highp float;
uniform dvec2 center;      // becomes center_hi / center_lo
uniform double scale;      // complex-plane units per pixel
uniform vec2 resolution;
uniform int max_iterations;
out vec4 color;

void main() {
  dvec2 c = center + dvec2(gl_FragCoord.xy - 0.5 * resolution) * scale;
  dvec2 z = dvec2(0.0lf);
  int n = 0;
  while (n < max_iterations && dot(z, z) < 4.0lf) {
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
    ++n;
  }
  float t = float(n) / float(max_iterations);
  color = n == max_iterations ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(t, sqrt(t), 0.5 + 0.5 * t, 1.0);
}
