// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// In/out interface blocks with double members (issue 12). Targets without I/O blocks (es100,
// es300, es310) flatten them into plain varyings named BLOCK_MEMBER (the manifest names the
// block), the double ones split into _hi/_lo; es320 and desktop keep the blocks.
in dvec3 position;
in vec2 uv;
out VertexData {
  flat dvec3 world;
  vec2 uv;
} vout;
out Extra {
  flat double depth;
};
uniform dmat4 model;
void main() {
  dvec4 p = model * dvec4(position, 1.0lf);
  vout.world = p.xyz;
  vout.uv = uv;
  depth = p.z * 0.5lf;
  gl_Position = vec4(p);
}
