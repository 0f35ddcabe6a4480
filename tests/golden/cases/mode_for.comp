// targets: es310
// options: --mode fp32 --mode-for integrate=df64 --mode-for main.t=df64
#version 310 es
// --mode-for NAME=MODE: the whole shader is fp32 except the function 'integrate' (its
// arithmetic and its parameters/locals/return value) and main's local 't'.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer State { vec4 state[]; };
uniform double dt;

double integrate(double x, double v) {
  return x + v * dt;
}

void main() {
  double t = double(state[0].w);
  double x = double(state[0].x);
  t = integrate(t, 1.0lf);
  x = integrate(x, double(state[0].y));
  state[0] = vec4(float(x), state[0].y, 0.0, float(t));
}
