// target: es300
#version 450
in vec4 position;
out Varyings { vec2 uv; float depth; } outv;
void main() {
  outv.uv = position.xy;
  outv.depth = position.z;
  gl_Position = position;
}
