#version 450
// Newtonian gravity of a star on bodies of its system, in SI units (m, kg, s): the force
// G M m / r^2 and the potential energy -G M m / r. G M m reaches 3e47, far beyond float's
// 3.4e38, so float-float overflows on it however its bits are spent; binary64 does not
// (docs/plan.md, "When the plan chooses mode exact").
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Bodies { dvec2 body[]; };  // x: distance to the star (m), y: mass (kg)
layout(std430, binding = 1) writeonly buffer Force { double force[]; };    // newtons
layout(std430, binding = 2) writeonly buffer Energy { double energy[]; };  // joules
uniform double star_mass;                                               // kg

const double G = 6.67430e-11;  // m^3 kg^-1 s^-2 (CODATA 2018)

void main() {
  uint i = gl_GlobalInvocationID.x;
  double r = body[i].x, m = body[i].y;
  double gmm = G * star_mass * m;
  force[i] = gmm / (r * r);
  energy[i] = -gmm / r;
}
