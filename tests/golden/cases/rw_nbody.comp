// targets: es310 es320 glsl450
#version 450
// Real-world style (issue 12): an n-body integration step as simulation codes write it. Storage
// blocks of double positions and velocities, a shared-memory tile, barriers, a global initialiser
// from a uniform, a local const, an atomic counter of close encounters.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Positions { dvec4 position[]; };
layout(std430, binding = 1) buffer Velocities { dvec4 velocity[]; };
layout(std430, binding = 2) writeonly buffer NextPositions { dvec4 next_position[]; };
layout(binding = 3, offset = 0) uniform atomic_uint close_encounters;
uniform double dt;
uniform double softening;
uniform int body_count;

shared dvec4 tile[64];
double softening2 = softening * softening;

void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec3 p = position[i].xyz;
  dvec3 acceleration = dvec3(0.0lf);
  for (int start = 0; start < body_count; start += 64) {
    tile[gl_LocalInvocationID.x] = position[start + int(gl_LocalInvocationID.x)];
    barrier();
    for (int j = 0; j < 64; ++j) {
      const dvec3 d = tile[j].xyz - p;
      double r2 = dot(d, d) + softening2;
      if (r2 < 4.0lf * softening2) atomicCounterIncrement(close_encounters);
      acceleration += d * (tile[j].w / (r2 * sqrt(r2)));
    }
    barrier();
  }
  velocity[i].xyz += acceleration * dt;
  next_position[i] = dvec4(p + velocity[i].xyz * dt, position[i].w);
}
