#version 450
in dvec2 in0;
out double r0;
uniform double u2 = -1.0lf;
void main() {
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
  dvec2 x0 = in0;
  r0 = x0.x * x0.y + 0.5lf;
}
