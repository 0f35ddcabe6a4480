#version 450
// issue 23's loop speed kernel as a compute shader, the WebGPU twin of loop.frag
// (tools/browser/speed-suite.mjs --apis webgpu): the orbit integrator of
// tests/browser-compile/orbit_leapfrog.frag (32 leapfrog steps, 26 double operations each, sqrt and
// division). One invocation per element; each reads its initial state from a storage buffer of
// doubles, so nothing folds.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer States { double state[]; };  // px py vx vy per element
layout(std430, binding = 1) writeonly buffer Positions { double position[]; };  // px py per element
uniform double mu;  // gravitational parameter, km^3/s^2
uniform double dt;  // time step, s
uniform uint count;  // elements
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  dvec2 p = dvec2(state[4u * i], state[4u * i + 1u]);
  dvec2 v = dvec2(state[4u * i + 2u], state[4u * i + 3u]);
  for (int k = 0; k < 32; ++k) {
    double r2 = p.x * p.x + p.y * p.y;
    double r = sqrt(r2);
    double f = -mu / (r2 * r);
    v += 0.5 * dt * f * p;
    p += dt * v;
    r2 = p.x * p.x + p.y * p.y;
    r = sqrt(r2);
    f = -mu / (r2 * r);
    v += 0.5 * dt * f * p;
  }
  position[2u * i] = p.x;
  position[2u * i + 1u] = p.y;
}
