#version 310 es
// wgs84_ecef.vert as a compute pass over buffers of points (timing and bulk checks,
// docs/examples-wgs84.md): one invocation per point.
#include "wgs84.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer LatLon { dvec2 lat_lon[]; };  // radians
layout(std430, binding = 1) readonly buffer Height { double height[]; };  // metres
layout(std430, binding = 2) writeonly buffer Relative { vec4 rel[]; };    // xyz: position - eye, metres
layout(std430, binding = 3) writeonly buffer Up { vec4 up[]; };           // xyz: ellipsoid normal
uniform dvec3 eye;                                                        // camera, ECEF, metres

void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec3 p = geodetic_to_ecef(lat_lon[i], height[i]);
  dvec3 d = p - eye;
  rel[i] = vec4(vec3(d), 0.0);
  up[i] = vec4(up_vector(lat_lon[i]), 0.0);
}
