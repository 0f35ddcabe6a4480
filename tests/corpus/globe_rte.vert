#version 450
// Planet/globe renderer, relative-to-eye (RTE): vertices in Earth-centred coordinates (metres),
// the camera anywhere from orbit to the ground. The eye offset is computed in double so that
// the float clip position does not jitter.
#include "engine_common.glsl"

uniform Globe {
  dmat4 view_projection;  // rotation and projection only: the translation is the RTE offset
  dvec3 eye_ecef;
  double exaggeration;    // vertical exaggeration of the terrain
};

in dvec3 position_ecef;
in float height;          // metres above the ellipsoid, along the (float) normal
in vec3 normal;

flat out dvec3 eye_offset;

void main() {
  dvec3 p = position_ecef + dvec3(normal) * (double(height) * exaggeration);
  eye_offset = rte(p, eye_ecef);
  gl_Position = vec4(view_projection * dvec4(eye_offset, 1.0lf));
}
