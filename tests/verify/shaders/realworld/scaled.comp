#version 450
// SCALE comes from -D and the helper from an #include: both must reach the native run too.
#include "scale_helpers.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { double x[]; };
layout(std430, binding = 1) writeonly buffer Out { double y[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  y[i] = scaled(x[i]) * SCALE;
}
