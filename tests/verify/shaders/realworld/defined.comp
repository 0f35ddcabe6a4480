#version 450
// SCALE comes from -D only: the native run must see it too.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { double x[]; };
layout(std430, binding = 1) writeonly buffer Out { double y[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  y[i] = x[i] * SCALE;
}
