// target: es100
#version 450
uniform int bits;
void main() {
  int masked = bits & 7;
  gl_FragColor = vec4(float(masked));
}
