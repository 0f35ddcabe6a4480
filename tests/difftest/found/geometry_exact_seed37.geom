#version 450
layout(points) in;
layout(points, max_vertices = 1) out;
in double in0[];
in dvec2 in1[];
in dvec2 in2[];
in dvec4 in3[];
out dvec4 r0;
out dvec4 r1;
double scratch;
dvec2 f0(dvec3 p0, inout double p1, out dvec2 p2) {
  double local_scratch;
  p2 = (dmat2(2.0lf))[0];
  dmat2 v1 = dmat2(1.0lf);
  int w2 = 0;
  while (w2 < 2) {
    w2++;
    if (p0.y == p1) continue;
    p2 = dvec2(vec2(p2.xy));
  }
  return (p2 / (1.5lf + abs(double(float(p1)))));
}
void main() {
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
  double x0 = in0[0];
  dvec2 x1 = in1[0];
  dvec2 x2 = in2[0];
  dvec4 x3 = in3[0];
  dvec4 q4;
  dvec4 v3 = modf((fma(x3, dvec4(-4.0lf, -4.0lf, -3.4375lf, -1.3997876316364422lf), x1.yxyy) * fract(x1.x)), q4);
  x0 += fma(x0, -3.7313317748610615lf, x1.y);
  q4 = (((x0 != x0) ? x3.xyxz : x3.xzyx) + (scratch = q4[2], scratch * x1.y));
  dvec4 q6;
  dvec4 v5 = modf(ldexp((x1.yxyy * v3.yyzw), ivec4(-3)), q6);
  double a7[4] = double[4]((v3.z / (1.5lf + abs(x2[0]))), -(q4.z), q4[2], -3.4379196100040676lf);
  r0 = faceforward(mix(x2.xyxx, x3.xxyx, x2.xxyy), mod(x3, 1.0lf + abs(x3.xwxx)), ((x2.y < x2.x) ? x2.yxxy : x1.xyxy));
  r1 = dvec4(vec4((x3.yxww + x1.xyxy)));
  EmitVertex();
}
