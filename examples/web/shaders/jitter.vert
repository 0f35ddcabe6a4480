#version 300 es
// Satellites on a geostationary orbit seen from a camera 10-50 m away (`doublet demo jitter`'s
// shader). Positions are Earth-centred metres (~4.2e7, where neighbouring floats are 2-4 m apart);
// the eye is subtracted in double.
in dvec3 position;             // Earth-centred, metres
in vec3 color;
uniform dvec3 eye;             // camera position, Earth-centred, metres
uniform mat4 view_projection;  // rotation and projection only
out vec3 v_color;

void main() {
  dvec3 relative = position - eye;
  v_color = color;
  gl_Position = view_projection * vec4(vec3(relative), 1.0);
}
