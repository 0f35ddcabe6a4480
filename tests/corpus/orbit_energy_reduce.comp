#version 450
// Science kernel: the total energy of a swarm of satellites, reduced per subgroup (subgroupAdd of
// doubles) and per workgroup, then written per workgroup; the satellite count comes from the
// buffer's runtime length (.length()), the gravitational parameter from a uniform with a default.
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "engine_common.glsl"
layout(local_size_x = 64) in;
struct Satellite { dvec3 position; dvec3 velocity; };
layout(std430, binding = 0) readonly buffer Swarm { Satellite satellites[]; };
layout(std430, binding = 1) writeonly buffer Energies { double energy[]; };
layout(std430, binding = 2) writeonly buffer Closest { double closest[]; };
uniform double u_gm = ENGINE_EARTH_GM;

void main() {
  uint i = gl_GlobalInvocationID.x;
  double e = 0.0lf, r = 1e30lf;
  if (i < uint(satellites.length())) {
    Satellite s = satellites[i];
    r = length(s.position);
    e = 0.5lf * dot(s.velocity, s.velocity) - u_gm / r;
  }
  double subgroup_energy = subgroupAdd(e);
  double subgroup_closest = subgroupMin(r);
  if (subgroupElect()) {
    energy[i / gl_SubgroupSize] = subgroup_energy;
    closest[i / gl_SubgroupSize] = subgroup_closest;
  }
}
