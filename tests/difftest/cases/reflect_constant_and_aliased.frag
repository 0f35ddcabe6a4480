#version 450
// Seeds 70272, 70571: reflect with a constant normal, and with aliased operands; native folded both before its built-ins were NoContraction.
flat in dvec2 in0;
layout(location = 0) out vec4 r0;
uniform dvec3 b1;
void main() {
  dvec2 x0 = in0;
  dvec2 t = reflect(x0 - b1.xy, (dmat2(3.0lf))[0]) + reflect(x0.xx, x0);
  r0 = vec4(float(t.x), float(t.x - double(float(t.x))), float(t.y), float(t.y - double(float(t.y))));
}
