// target: es320
#version 450
layout(std140) uniform Params { dvec3 b0; dmat2 m; double arr[2]; };
uniform Light { dvec2 dir; } light;
flat in double x;
flat in int i;
layout(location = 0) out vec4 r;
void main() {
  double s = b0.y * x + arr[i] + (m * light.dir).x;
  if (b0.x > 1.5lf) s = s * 2.0lf;
  r = vec4(float(s), float(s - double(float(s))), 0.0, 1.0);
}
