#version 300 es
// Mandelbrot set for deep zooms: with float the picture turns blocky below a
// pixel size of about 1e-7; double (lowered to float-float) goes much further.
// Only +, -, * and comparisons on doubles.
precision highp float;

uniform dvec2 center;   // complex-plane point at the middle of the viewport
uniform double scale;   // complex-plane units per pixel
uniform vec2 halfSize;  // half the viewport size in pixels
out vec4 color;

void main() {
  dvec2 c = center + dvec2(gl_FragCoord.xy - halfSize) * scale;
  dvec2 z = dvec2(0.0);
  int n = 0;
  for (int i = 0; i < 32; i++) {
    double x2 = z.x * z.x;
    double y2 = z.y * z.y;
    if (x2 + y2 > double(4.0)) break;
    z = dvec2(x2 - y2, (z.x + z.x) * z.y) + c;
    n++;
  }
  float t = float(n) / 32.0;
  color = n == 32 ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(t, t * t, sqrt(t), 1.0);
}
