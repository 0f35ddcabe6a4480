// target: es300
#version 450
uniform double a;
uniform double b;
out vec4 color;
void main() {
  double s = a * b + a;
  color = vec4(float(s));
}
