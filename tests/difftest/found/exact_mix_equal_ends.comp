#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer A { dvec4 a[]; };
layout(std430, binding = 1) buffer B { dvec4 b[]; };
layout(std430, binding = 2) buffer R { dvec4 r0[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 x = a[i];
  dvec4 t = b[i];
  r0[i] = mix(x.xyxx, x.zzwx, t);
}
