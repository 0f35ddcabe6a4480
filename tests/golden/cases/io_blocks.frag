// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// The fragment side of io_blocks.vert: another instance name, the same block names, so the
// flattened varyings (VertexData_world_hi, ...) match the vertex shader's.
in VertexData {
  flat dvec3 world;
  vec2 uv;
} fin;
in Extra {
  flat double depth;
};
out vec4 color;
void main() {
  dvec3 w = fin.world * depth;
  color = vec4(vec3(w), fin.uv.x);
}
