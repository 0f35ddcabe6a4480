#version 450
// CAD-style viewer: a large assembly in millimetres with model, view and projection matrices in
// double, and a section (clipping) plane whose signed distance the fragment stage would test.
#include "engine_common.glsl"

uniform Transforms {
  dmat4 model;
  dmat4 view;
  dmat4 projection;
};
uniform dvec3 section_origin;
uniform dvec3 section_normal;

in dvec3 vertex;

flat out double section_distance;
flat out dvec3 view_position;

void main() {
  dvec4 world = model * dvec4(vertex, 1.0lf);
  dvec4 eye = view * world;
  view_position = eye.xyz;
  section_distance = dot(world.xyz - section_origin, section_normal);
  gl_Position = vec4(projection * eye);
}
