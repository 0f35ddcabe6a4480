#version 450
// Seed 4927: exact != native before native's built-ins were NoContraction (lavapipe reassociated refract's expansion around a constant eta).
flat in dvec2 in0;
layout(location = 0) out vec4 r0;
uniform dvec3 b1;
void main() {
  dvec2 x0 = in0;
  dvec2 t = refract(dvec2(x0.y, b1.z), dvec2(0.6lf, 0.8lf), 1.25lf);
  r0 = vec4(float(t.x), float(t.x - double(float(t.x))), float(t.y), float(t.y - double(float(t.y))));
}
