#version 450
// issue 23's loop speed kernel (tools/browser/speed-suite.mjs): the orbit integrator of
// tests/browser-compile/orbit_leapfrog.frag (32 leapfrog steps, 26 double operations each, sqrt and
// division), with each pixel's initial state read as hi/lo float words from a texture, so nothing
// folds.
uniform sampler2D words;  // texel (2x, y): px_hi px_lo py_hi py_lo; texel (2x + 1, y): vx_hi vx_lo vy_hi vy_lo
uniform double mu;        // gravitational parameter, km^3/s^2
uniform double dt;        // time step, s
layout(location = 0) out vec4 position;  // hi.x hi.y lo.x lo.y
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  dvec2 p = dvec2(double(a.x) + double(a.y), double(a.z) + double(a.w));
  dvec2 v = dvec2(double(b.x) + double(b.y), double(b.z) + double(b.w));
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
