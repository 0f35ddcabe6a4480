// targets: es310 es320
// options: --mode df64-fast
#version 310 es
// Mode df64-fast: float-float with the cheaper rules of rules/fast.glsl (sloppy addition,
// unrenormalised remainder in the division); the product and sqrt are the accurate ones.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { double x[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = x[4u * i], b = x[4u * i + 1u];
  x[4u * i + 2u] = (a + b) * (a - b) / sqrt(a);
  double c = x[4u * i + 3u];
  c += a;
  x[4u * i + 3u] = c;
}
