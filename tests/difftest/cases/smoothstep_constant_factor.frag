#version 450
// Seed 5062: a constant factor times smoothstep; native reassociated it into smoothstep's expansion before its built-ins were NoContraction.
flat in dvec2 in0;
layout(location = 0) out vec4 r0;
uniform dvec3 b1;
void main() {
  dvec2 x0 = in0;
  dvec2 t = fma(dvec2(1.5lf), smoothstep(-4.0lf, 4.0lf, x0 - b1.zx), dvec2(1.5lf));
  r0 = vec4(float(t.x), float(t.x - double(float(t.x))), float(t.y), float(t.y - double(float(t.y))));
}
