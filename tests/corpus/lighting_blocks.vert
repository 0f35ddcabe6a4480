#version 450
// Engine-style vertex stage with an output interface block (the fragment stage reads
// `VertexData`), world-space lighting terms computed in double from a far-away origin.
#include "engine_common.glsl"

uniform dvec3 world_origin;
uniform dvec3 light_position;

in dvec3 local_position;
in vec3 normal;

out VertexData {
  vec3 to_light;
  vec2 distance_hi_lo;
} vs_out;

void main() {
  dvec3 world = world_origin + local_position;
  dvec3 to_light = light_position - world;
  vs_out.to_light = vec3(normalize(to_light));
  vs_out.distance_hi_lo = hi_lo(length(to_light));
  gl_Position = vec4(vec3(local_position) * 1e-3, 1.0);
}
