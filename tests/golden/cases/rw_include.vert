// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 300 es
// Real-world style (issue 12): engine-style shared headers (#include with include guards, one
// header including another), a global initialised from a double uniform in a header, and a
// relative-to-eye position, as a GIS renderer writes it.
#extension GL_GOOGLE_include_directive : require
#include "rw_camera.glsl"
#include "rw_geodesy.glsl"
in vec3 a_lon_lat_height;
out float v_height;
void main() {
  dvec3 ecef = geodetic_to_ecef(double(a_lon_lat_height.x), double(a_lon_lat_height.y), double(a_lon_lat_height.z));
  v_height = a_lon_lat_height.z;
  gl_Position = u_view_projection * vec4(vec3(ecef - g_eye), 1.0);
}
