// target: es300
#version 450
uniform double scale;
out vec4 color;
void main() {
  double x = scale * 0.1;
  color = vec4(float(x));
}
