// target: webgl2
#version 450
flat in dvec2 v;
out vec4 first;
layout(location = 0) out vec4 held;
out vec4 second[2];
void main() {
  double s = v.x * v.y;
  first = vec4(float(s));
  held = vec4(1.0);
  second[0] = vec4(float(v.x));
  second[1] = vec4(float(v.y));
}
