#version 300 es
void main() {
  double x = 1.0lf;
  gl_Position = vec4(float(x + undefined_thing));
}
