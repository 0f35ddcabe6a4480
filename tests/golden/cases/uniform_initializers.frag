// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Uniforms declared with an initializer (desktop GLSL: the value until the application sets one):
// kept on desktop targets (a split double: both words initialised), on ES declared without one,
// with one warning, and the value in the manifest's "default" (pass uniform-defaults).
uniform double zoom = 1.1lf;
uniform dvec2 center = dvec2(0.5lf, 1.0lf / 3.0lf);
uniform int n = 3;
flat in dvec2 p;
layout(location = 0) out vec4 o;
void main() {
  dvec2 z = p;
  for (int k = 0; k < n; ++k) z = z * zoom + center;
  o = vec4(vec2(z), vec2(z - dvec2(vec2(z))));
}
