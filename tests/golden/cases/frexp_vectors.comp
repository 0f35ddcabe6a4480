// targets: es310 es320 glsl450
#version 450
// frexp on dvec2/3/4: the width-1 rule applied per component (rules/common.glsl, @per-component
// with an out parameter); results against native fp64 (tests/golden CMake).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Data { dvec4 x[]; };
layout(std430, binding = 1) buffer Mantissas { dvec4 m[]; };
layout(std430, binding = 2) buffer Exponents { dvec4 e[]; };  // doubles, so that verify compares them
void main() {
  uint i = gl_GlobalInvocationID.x;
  ivec4 e4;
  m[i] = frexp(x[i], e4);
  ivec3 e3;
  dvec3 m3 = frexp(x[i].zyx, e3);
  ivec2 e2;
  dvec2 m2 = frexp(x[i].xy * 1024.0lf, e2);
  e[i] = dvec4(e4 + ivec4(e3, e2.x) * 4096 + ivec4(e2.y) * 16777216);
  m[i] += dvec4(m3, m2.x + m2.y);
}
