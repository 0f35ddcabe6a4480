#version 300 es
// Relative-to-eye rendering of a globe. Vertices are Earth-centred (ECEF) positions in
// metres, ~6.4e6 from the origin, where neighbouring floats are 0.5 m apart: transformed
// in float, a city-scale mesh jitters by that much as the camera moves. In double the
// eye is subtracted first; the small eye-relative offset is then exact enough in float.
//
// doublet turns `position` into the attribute pair position_hi/position_lo and `eye` into
// eye_hi/eye_lo (see the manifest); the host fills them with doublet::split.
layout(location = 0) in dvec3 position;   // ECEF, metres
layout(location = 2) in vec3 normal;
uniform dvec3 eye;                        // camera position, ECEF, metres
uniform mat4 view_projection;             // rotation and projection only: no translation
out vec3 v_normal;
out float v_height;                       // metres above the WGS84 equatorial radius

void main() {
  dvec3 relative = position - eye;
  v_normal = normal;
  v_height = float(length(position) - 6378137.0lf);
  gl_Position = view_projection * vec4(vec3(relative), 1.0);
}
