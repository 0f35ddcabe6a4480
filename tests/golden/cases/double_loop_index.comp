// targets: es310 es320 glsl450
#version 310 es
// A double loop index: the for-init is lowered before the condition and the step read it.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double r[]; };
void main() {
  double e = r[0];
  double s = 0.0lf;
  for (double t = 0.0lf; t < e; t += 0.25lf) s += t;
  for (dvec2 u = dvec2(0.0lf); u.x < e; u += dvec2(0.5lf, 1.0lf)) s += u.y;
  r[1] = s;
}
