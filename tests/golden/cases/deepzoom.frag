// targets: wgsl
#version 450
// Deep-zoom Mandelbrot iteration in doubles (the fragment path, gl_FragCoord).
uniform dvec2 center;
uniform double scale;
uniform int max_iterations;
layout(location = 0) out vec4 color;
void main() {
  dvec2 c = center + dvec2(gl_FragCoord.xy) * scale;
  dvec2 z = dvec2(0.0);
  int n = 0;
  for (; n < max_iterations; n++) {
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
    if (dot(vec2(z), vec2(z)) > 4.0) break;
  }
  float t = float(n) / float(max_iterations);
  color = vec4(t, t * t, sqrt(t), 1.0);
}
