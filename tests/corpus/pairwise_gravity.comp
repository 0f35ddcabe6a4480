#version 450
// Science kernel: all-pairs gravity between bodies, the loop bound a uniform body count (the
// usual n-body shape). In metres, seconds and kilograms.
layout(local_size_x = 64) in;

struct Body {
  dvec4 position_mass;  // xyz: position, w: mass
  dvec4 velocity;
};
layout(std430, binding = 0) readonly buffer Current { Body current[]; };
layout(std430, binding = 1) writeonly buffer Next { Body next[]; };

uniform uint body_count;
uniform double dt;
uniform double softening2;

const double G = 6.674e-11lf;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= body_count) return;
  dvec3 p = current[i].position_mass.xyz;
  dvec3 acceleration = dvec3(0.0lf);
  for (uint j = 0u; j < body_count; ++j) {
    dvec3 d = current[j].position_mass.xyz - p;
    double r2 = dot(d, d) + softening2;
    double inv_r = inversesqrt(r2);
    acceleration += d * (G * current[j].position_mass.w * inv_r * inv_r * inv_r);
  }
  dvec3 v = current[i].velocity.xyz + acceleration * dt;
  next[i].velocity = dvec4(v, 0.0lf);
  next[i].position_mass = dvec4(p + v * dt, current[i].position_mass.w);
}
