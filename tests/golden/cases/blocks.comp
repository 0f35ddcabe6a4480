// targets: es310 es320 glsl450
#version 450
// Uniform and storage blocks with double members: each double member becomes a df_* struct
// (hi and lo side by side) in an explicit std140/std430 block, and the manifest lists every
// member's new offset. Compute writes double outputs to a storage block.
layout(local_size_x = 32) in;
struct Particle { dvec3 position; double mass; };
layout(std140, binding = 0) uniform Frame {
  dmat4 transform;
  double dt;
  int count;
  dvec2 offsets[2];
};
layout(std430, binding = 1) buffer Particles { Particle particles[]; } store;
layout(binding = 2) buffer Energy { double total; double energies[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (int(i) >= count) return;
  Particle p = store.particles[i];
  dvec4 moved = transform * dvec4(p.position, 1.0lf);
  p.position = moved.xyz + dvec3(offsets[i % 2u], 0.0lf) * dt;
  store.particles[i] = p;
  energies[i] = 0.5lf * p.mass * dot(p.position, p.position);
  if (i == 0u) total = energies[0];
}
