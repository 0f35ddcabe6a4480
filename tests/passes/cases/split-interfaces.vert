// target: es300
#version 450
in dvec2 position;
uniform double zoom;
void main() {
  dvec2 p = position * zoom;
  gl_Position = vec4(vec2(p), 0.0, 1.0);
}
