// target: es300
#version 450
uniform double zoom = 1.1lf;
uniform int n = 3;
flat in dvec2 p;
out vec4 o;
void main() {
  dvec2 z = p;
  for (int k = 0; k < n; ++k) z = z * zoom;
  o = vec4(vec2(z), 0.0, 1.0);
}
