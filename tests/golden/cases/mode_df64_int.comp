// targets: es310 glsl450
// options: --mode df64-int
#version 310 es
// Mode df64-int: df64's algorithms with the integer error-free transformations of
// rules/int.glsl (TwoSum/TwoProd error terms as exact integer residuals); no optimizer guard.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { double x[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = x[4u * i], b = x[4u * i + 1u];
  x[4u * i + 2u] = (a + b) * (a - b) / sqrt(a);
  double c = x[4u * i + 3u];
  c += a * a;
  x[4u * i + 3u] = c;
}
