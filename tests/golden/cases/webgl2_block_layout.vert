// targets: es300 webgl2
#version 450
// A uniform block without a layout is `shared` (glslang's default), which WebGL 2.0 refuses ("Only
// std140 layout is allowed in WebGL"): webgl2 prints it std140, es300 keeps shared.
uniform Transforms {
  mat4 model;
  mat4 view_projection;
};
in vec3 position;
in dvec3 offset;
void main() {
  dvec3 p = dvec3(position) + offset;
  gl_Position = view_projection * model * vec4(vec3(p), 1.0);
}
