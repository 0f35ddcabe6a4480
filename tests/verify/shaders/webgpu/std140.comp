#version 450
// std140 storage blocks in WGSL (tests/verify/webgpu_verify_test.cpp): WGSL would read these arrays
// of doubles and floats with 8- and 4-byte strides where std140 (and so the host) puts them 16 apart;
// doublet pads them to std140's stride (docs/web.md, "std140 blocks in WGSL").
layout(local_size_x = 64) in;
layout(std140, binding = 0) readonly buffer Products { double a[]; };
layout(std140, binding = 1) readonly buffer Factors { double b[]; };
layout(std140, binding = 2) readonly buffer Offsets { float f[]; };
layout(std140, binding = 3) writeonly buffer Out { double o[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  o[i] = a[i] * b[i] + double(f[i]);
}
