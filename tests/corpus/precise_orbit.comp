#version 450
// Orbit propagation that marks its error-sensitive update `precise` (as fp64 code written for
// drivers that reassociate does): a Kepler-problem velocity-Verlet step.
#include "engine_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Positions { dvec3 position[]; };
layout(std430, binding = 1) buffer Velocities { dvec3 velocity[]; };

uniform double dt;

dvec3 gravity(dvec3 r) {
  double d = length(r);
  return -ENGINE_EARTH_GM * r / (d * d * d);
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec3 r = position[i];
  dvec3 v = velocity[i];
  dvec3 a = gravity(r);
  precise dvec3 r_next = r + v * dt + a * (0.5lf * dt * dt);
  precise dvec3 v_next = v + (a + gravity(r_next)) * (0.5lf * dt);
  position[i] = r_next;
  velocity[i] = v_next;
}
