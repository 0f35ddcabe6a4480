#version 450
// An array of structs with double members in a storage buffer: every member is an output.
layout(local_size_x = 64) in;
struct Particle { dvec3 position; dvec3 velocity; double mass; float radius; };
layout(std430, binding = 0) buffer Particles { Particle p[]; };
uniform double dt;
void main() {
  uint i = gl_GlobalInvocationID.x;
  p[i].position += p[i].velocity * dt;
  p[i].mass *= 1.0lf + dt;
  p[i].radius *= 2.0;
}
