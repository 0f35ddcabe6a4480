// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 300 es
// Double parameters (in/out/inout), return values, globals and locals.
in dvec2 uv;
uniform double time;
out vec2 v_uv;
dvec2 accumulated;
double scaled(double x, double s) { return x * s; }
void step2(inout dvec2 p, out double speed, in double dt) {
  speed = length(p) / dt;
  p = p + dvec2(dt, -dt);
}
void main() {
  double speed;
  dvec2 p = uv;
  step2(p, speed, time);
  accumulated = p * scaled(speed, 0.5lf);
  v_uv = vec2(accumulated);
  gl_Position = vec4(vec2(p), 0.0, 1.0);
}
