#version 450
// Browser probe: each texel holds two doubles as (a_hi, a_lo, b_hi, b_lo); the result r of the
// chosen operation goes out as (hi, lo) = (float(r), float(r - hi)).
uniform sampler2D u_in;
uniform int u_op;
out vec4 o;
void main() {
  vec4 t = texelFetch(u_in, ivec2(gl_FragCoord.xy), 0);
  double a = double(t.x) + double(t.y);
  double b = double(t.z) + double(t.w);
  double r;
  if (u_op == 0) r = a + b;
  else if (u_op == 1) r = a - b;
  else if (u_op == 2) r = a * b;
  else if (u_op == 3) r = a / b;
  else r = sqrt(abs(a));
  float hi = float(r);
  o = vec4(hi, float(r - double(hi)), 0.0, 1.0);
}
