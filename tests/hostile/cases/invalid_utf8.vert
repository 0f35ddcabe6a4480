#version 300 es
void main() {
  float ÿþ = 1.0;
  gl_Position = vec4(0.0);
}
