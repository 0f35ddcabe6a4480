#version 450
// Science kernel: one symplectic-Euler step of satellites around the Earth (central mass
// only), in metres and seconds. Positions of 1e7 m updated by centimetres need doubles.
#include "engine_common.glsl"

layout(local_size_x = 64) in;

struct Satellite {
  dvec3 position;
  dvec3 velocity;
};
layout(std430, binding = 0) buffer Satellites { Satellite satellites[]; };

uniform double dt;

void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec3 r = satellites[i].position;
  double inverse_distance = 1.0lf / sqrt(dot(r, r));
  dvec3 acceleration = -ENGINE_EARTH_GM * r * (inverse_distance * inverse_distance * inverse_distance);
  dvec3 v = satellites[i].velocity + acceleration * dt;
  satellites[i].velocity = v;
  satellites[i].position = r + v * dt;
}
