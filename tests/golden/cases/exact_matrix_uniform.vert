// targets: es300 webgl2
// options: --mode exact
#version 450
// Mode exact: a Cesium/deck.gl-style model matrix, `uniform dmat4 u_model`, becomes
// `uniform uvec4 u_model[8]`: the host's 16 column-major doubles, unchanged, in one glUniform4uiv.
layout(location = 0) in dvec3 position;
uniform dmat4 u_model;
uniform mat4 u_view_projection;
void main() {
  dvec4 world = u_model * dvec4(position, 1.0);
  gl_Position = u_view_projection * vec4(world);
}
