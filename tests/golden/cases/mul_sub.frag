#version 300 es
precision highp float;
// A product and a difference of doubles, narrowed for output.
uniform double a;
uniform double b;
out vec4 color;
void main() {
  double p = a * b - a;
  color = vec4(float(p), 0.0, 0.0, 1.0);
}
