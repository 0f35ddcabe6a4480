#version 450
// issue 23's straight-line speed kernel as a compute shader, the WebGPU twin of straight.frag
// (tools/browser/speed-suite.mjs --apis webgpu): a relative-to-eye transform per element, a double
// position minus a double eye, times a dmat4 (3 subtractions, 16 products, 12 sums; no loop, no
// branch). One invocation per element; each reads its own position from a storage buffer of doubles,
// so nothing folds.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Positions { double position[]; };  // x y z per element
layout(std430, binding = 1) writeonly buffer Clip { double clip[]; };            // x y z w per element
uniform dvec3 eye;
uniform dmat4 mvp;
uniform uint count;  // elements
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  dvec3 p = dvec3(position[3u * i], position[3u * i + 1u], position[3u * i + 2u]);
  dvec4 c = mvp * dvec4(p - eye, 1.0);
  clip[4u * i] = c.x;
  clip[4u * i + 1u] = c.y;
  clip[4u * i + 2u] = c.z;
  clip[4u * i + 3u] = c.w;
}
