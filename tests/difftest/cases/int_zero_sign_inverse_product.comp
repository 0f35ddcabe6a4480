#version 450
layout(std140, binding = 0) readonly buffer In0 { dvec4 in0[]; };
layout(std140, binding = 1) readonly buffer In1 { dvec4 in1[]; };
layout(std140, binding = 2) readonly buffer In2 { dvec4 in2[]; };
layout(std430, binding = 5) writeonly buffer Out2 { dvec3 r2[]; };
dvec2 g0 = dvec2(-2.9336486597577025lf, 3.0lf);
dvec4 f3(dvec3 p0) {
  return trunc(mix(p0.yyyx, g0.yxxy, lessThan(p0.yyzy, g0.yyxx)));
}
void main() {
  uint gid = gl_GlobalInvocationID.x;
  dvec4 x0 = in0[gid];
  dvec4 x1 = in1[gid];
  dvec4 x2 = in2[gid];
  r2[gid] = (inverse(dmat3(1.0lf) + dmat3(19.0lf)) * (dmat3(3.0lf))[0]);
}
