// targets: wgsl
#version 450
// Loose uniform arrays of scalars and 2-vectors: WGSL pads their elements to vec4 (array_stride
// 16 in the manifest) and reads each through its first components (src/emit/wgsl_printer.cpp).
layout(local_size_x = 16) in;
uniform double d[3];
uniform dvec2 w[2];
uniform float f[2];
layout(std430, binding = 0) buffer Data { dvec2 x[]; };
layout(std430, binding = 1) buffer Results { dvec2 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  r[i] = x[i] * d[i % 3u] + w[i % 2u] * double(f[1]) + d[0];
}
