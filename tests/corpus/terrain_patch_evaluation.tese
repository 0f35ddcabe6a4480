#version 450
// Planet terrain LOD, evaluation stage: the patch centre (a per-patch input) plus the corners'
// offsets weighted by gl_TessCoord gives each generated vertex in earth-centred metres; the
// relative-to-eye position keeps millimetres where float keeps half a metre.
#include "engine_common.glsl"
layout(triangles, equal_spacing, ccw) in;
in dvec3 c_offset[];
patch in dvec3 p_center;
patch in double p_distance;
uniform dvec3 u_eye;
flat out dvec3 e_relative;
out float e_distance;

void main() {
  dvec3 offset = c_offset[0] * double(gl_TessCoord.x) + c_offset[1] * double(gl_TessCoord.y) +
                 c_offset[2] * double(gl_TessCoord.z);
  e_relative = rte(p_center + offset, u_eye);
  e_distance = float(p_distance);
  gl_Position = vec4(vec3(e_relative * 1e-6lf), 1.0);
}
