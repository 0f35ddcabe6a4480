// targets: glsl450
// options: --mode native
#version 310 es
// Mode native: the doubles stay; the shader is re-printed for desktop GLSL 4.50 (the reference
// doublet verify compares against, and an escape hatch where the driver has fp64).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { double x[]; };
uniform double scale;
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = x[2u * i];
  x[2u * i + 1u] = sqrt(a) * scale + 0.1lf;
}
