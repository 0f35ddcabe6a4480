#version 450
// Newtonian gravity as in gravity_si.comp, with the physics in functions, as a science kernel
// might be written: G M m reaches 5e48, beyond float's range (3.4e38), but only inside force_of()
// and energy_of(); their results (up to 3e26 N and 3e37 J) fit float-float. The plan makes those
// two functions exact and keeps main in df64 (docs/plan.md, "When the plan chooses mode exact";
// docs/modes.md, "Exact functions"). Scene: gravity_si_functions.scene.json.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Distances { double distance[]; };  // to the star (m)
layout(std430, binding = 1) readonly buffer Masses { double mass[]; };         // kg
layout(std430, binding = 2) writeonly buffer Force { double force[]; };        // newtons
layout(std430, binding = 3) writeonly buffer Energy { double energy[]; };      // joules
uniform double star_mass;                                                   // kg

double force_of(double r, double m, double star) { return 6.67430e-11lf * star * m / (r * r); }
double energy_of(double r, double m, double star) { return -(6.67430e-11lf * star * m) / r; }

void main() {
  uint i = gl_GlobalInvocationID.x;
  force[i] = force_of(distance[i], mass[i], star_mass);
  energy[i] = energy_of(distance[i], mass[i], star_mass);
}
