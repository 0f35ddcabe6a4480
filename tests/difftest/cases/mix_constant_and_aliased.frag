#version 450
// Seeds 37, 70089: mix with two constant ends and mix with aliased operands; native folded both before its built-ins were NoContraction.
flat in dvec2 in0;
layout(location = 0) out vec4 r0;
uniform dvec3 b1;
void main() {
  dvec2 x0 = in0;
  dvec2 t = mix(dvec2(2.0lf), dvec2(3.25lf, 1.5lf), clamp(x0 - 1.0lf, 0.0lf, 1.0lf)) + dvec2(mix(x0.x, b1.x, x0.x), mix(x0.y, x0.y, b1.z));
  r0 = vec4(float(t.x), float(t.x - double(float(t.x))), float(t.y), float(t.y - double(float(t.y))));
}
