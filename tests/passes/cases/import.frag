// target: es300
#version 450
flat in dvec2 v;
out vec4 color;
void main() {
  double s = v.x + v.y;
  color = vec4(float(s), 0.0, 0.0, 1.0);
}
