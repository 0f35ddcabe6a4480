#version 450
// Seed 115: mix with a 0 end the compiler can see; lavapipe rewrote mix(0, b, t) as b * t (-0 where the written 0 * (1 - t) + b * t gives +0) before its built-ins were NoContraction.
flat in dvec2 in0;
layout(location = 0) out vec4 r0;
void main() {
  dvec3 x1 = dvec3(0.0lf, 0.0lf, 1.0lf);
  dvec3 m = mix(x1.xxy, dvec3(-in0.x), dvec3(in0.y - 1.0lf, 0.0lf, in0.y));
  r0 = vec4(float(m.x), float(m.y), float(m.z), float(m.x - double(float(m.x))));
}
