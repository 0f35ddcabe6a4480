// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// A uniform block with double members (std140, new offsets in the manifest) in a fragment
// shader, with a flat double varying (full precision; a fragment double input must be flat).
layout(std140) uniform Material {
  dvec4 albedo;
  dmat3 basis;
  double roughness;
};
flat in dvec3 position_flat;

out vec4 color;
void main() {
  dvec3 p = basis * position_flat;
  color = vec4(albedo * roughness) + vec4(vec3(p), 1.0);
}
