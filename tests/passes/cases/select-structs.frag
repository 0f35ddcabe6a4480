// target: webgl2
#version 450
uniform double a;
uniform double b;
uniform bool pick;
out vec4 color;
void main() {
  double m = pick ? a : b;
  color = vec4(float(m));
}
