#version 300 es
// Relative-to-eye rendering of a globe tile (docs/plan.md). Earth-centred positions in metres
// reach 6.4e6, where floats are 0.5 m apart; the eye is subtracted in double and the small
// eye-relative offset `rel` is what the rest of the shader needs. `doublet plan` decides, from
// globe.scene.json, whether `rel` may be stored as float after the subtraction.
layout(location = 0) in dvec3 position;  // ECEF, metres
uniform dvec3 eye;                       // camera position, ECEF, metres
uniform mat4 view_projection;            // rotation and projection only: no translation
flat out dvec3 v_rel;                    // eye-relative position, metres (lighting, fog)
out float v_height;                      // metres above the polar radius (a tile near the pole)

void main() {
  dvec3 rel = position - eye;
  v_rel = rel;
  v_height = float(length(position) - 6356752.0lf);
  gl_Position = view_projection * vec4(vec3(rel), 1.0);
}
