#version 310 es
// Advances many bodies on circular orbits by a small time step, `steps` times, with
// positions and velocities in double. Each step adds a displacement ~1e-9 of the
// radius: in float the additions would round away, in float-float they accumulate.
#extension GL_GOOGLE_include_directive : require
#include "float_float_io.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer State { vec2 state[]; };  // x, y, vx, vy as (hi, lo) pairs per body

uniform double dt;      // becomes dt_hi / dt_lo (see the manifest)
uniform double mu;      // gravitational parameter
uniform int steps;

void main() {
  uint b = gl_GlobalInvocationID.x;
  dvec2 p = dvec2(load_pair(state[4u * b]), load_pair(state[4u * b + 1u]));
  dvec2 v = dvec2(load_pair(state[4u * b + 2u]), load_pair(state[4u * b + 3u]));
  for (int i = 0; i < steps; ++i) {
    double r2 = dot(p, p);
    double inv_r3 = 1.0lf / (r2 * sqrt(r2));
    v -= p * (mu * inv_r3 * dt);   // semi-implicit Euler: velocity first
    p += v * dt;
  }
  state[4u * b] = store_pair(p.x);
  state[4u * b + 1u] = store_pair(p.y);
  state[4u * b + 2u] = store_pair(v.x);
  state[4u * b + 3u] = store_pair(v.y);
}
