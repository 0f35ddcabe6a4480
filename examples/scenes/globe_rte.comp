#version 450
// Relative-to-eye in a compute pass: positions in a buffer array, the eye a uniform, the
// difference stored as float (what a vertex stage would receive). docs/plan.md.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Positions { dvec3 position[]; };
layout(std430, binding = 1) writeonly buffer Relative { vec3 rel[]; };
uniform dvec3 eye;

void main() {
  uint i = gl_GlobalInvocationID.x;
  rel[i] = vec3(position[i] - eye);
}
