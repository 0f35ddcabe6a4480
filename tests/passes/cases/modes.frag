// target: es300 mode: fp32
#version 450
uniform double scale;
out vec4 color;
void main() {
  double x = scale * 2.0lf;
  color = vec4(float(x));
}
