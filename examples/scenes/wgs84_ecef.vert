#version 300 es
// Points given by latitude, longitude and height, drawn from a camera a few metres away
// (docs/examples-wgs84.md). The ECEF position reaches 6.4e6 m, where floats are 0.5 m apart;
// what the rasteriser needs is the small eye-relative offset. `doublet plan` with
// wgs84.scene.json chooses the precision of each step.
#include "wgs84.glsl"

layout(location = 0) in dvec2 lat_lon;  // radians
layout(location = 1) in double height;  // metres above the ellipsoid
uniform dvec3 eye;                      // camera position, ECEF, metres
uniform mat4 view_projection;           // rotation and projection only: no translation
out vec3 v_rel;                         // position - eye, metres (fog, picking)
out vec3 v_up;                          // ellipsoid normal (lighting)

void main() {
  dvec3 p = geodetic_to_ecef(lat_lon, height);
  dvec3 rel = p - eye;
  v_rel = vec3(rel);
  v_up = up_vector(lat_lon);
  gl_Position = view_projection * vec4(v_rel, 1.0);
}
