// Shared header of rw_include.vert: the camera state every pass of the engine includes.
#ifndef RW_CAMERA_GLSL
#define RW_CAMERA_GLSL
#include "rw_geodesy.glsl"
uniform dvec3 u_eye_ecef;
uniform mat4 u_view_projection;
dvec3 g_eye = u_eye_ecef;  // global state from a uniform: initialised at the top of main
#endif
