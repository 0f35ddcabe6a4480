#version 450
// A two-body orbit integrated with 32 leapfrog (kick-drift-kick) steps, 26 double operations per
// step: the realistic loop of issue 23, which did not compile in WebGL2 or WebGPU in any df64 mode
// while the runtime had per-operation branches.
flat in dvec4 state;      // position (x, y), velocity (vx, vy) in km and km/s
uniform double mu;        // gravitational parameter, km^3/s^2
uniform double dt;        // time step, s
layout(location = 0) out vec4 position;
void main() {
  dvec2 p = state.xy, v = state.zw;
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
  position = vec4(vec2(p), vec2(p - dvec2(vec2(p))));
}
