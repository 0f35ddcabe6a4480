#version 450
in dvec2 in0;
in double in1;
in dvec4 in2;
in dvec4 in3;
out dvec3 r2;
const dvec2 C0 = dvec2(1.9555907743480452lf, 1.1737221052707341lf);
const dvec3 C1 = dvec3(-3.8125lf);
dvec2 f2(dvec3 p0) {
  return (C0[0] - fma(C1.zx, C1.zy, dvec2(-3.0lf, -0.4375lf)));
}
void main() {
  dvec4 x3 = in3;
  r2 = fma((dmat3(1.0lf) * C0.yyy), smoothstep(-4.0lf, 4.0lf, x3.zwy), C0.yyy);
}
