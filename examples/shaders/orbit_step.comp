#version 310 es
// One integration step per invocation for many satellites: position and velocity in
// double, stored as (hi, lo) pairs. Steps move a satellite centimetres at a radius of
// thousands of kilometres, where float positions are half a metre apart.
#include "include/float_float_io.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer State { vec2 state[]; };  // x, y, z, vx, vy, vz per satellite

uniform double dt;   // seconds
uniform double mu;   // gravitational parameter, m^3/s^2 (Earth: 3.986004418e14)

void main() {
  uint s = 6u * gl_GlobalInvocationID.x;
  dvec3 p = dvec3(load_pair(state[s]), load_pair(state[s + 1u]), load_pair(state[s + 2u]));
  dvec3 v = dvec3(load_pair(state[s + 3u]), load_pair(state[s + 4u]), load_pair(state[s + 5u]));
  double r2 = dot(p, p);
  v -= p * (mu / (r2 * sqrt(r2)) * dt);   // semi-implicit Euler
  p += v * dt;
  state[s] = store_pair(p.x);
  state[s + 1u] = store_pair(p.y);
  state[s + 2u] = store_pair(p.z);
  state[s + 3u] = store_pair(v.x);
  state[s + 4u] = store_pair(v.y);
  state[s + 5u] = store_pair(v.z);
}
