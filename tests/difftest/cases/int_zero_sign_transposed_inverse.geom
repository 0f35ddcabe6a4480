#version 450
layout(points) in;
layout(points, max_vertices = 1) out;
in dvec4 in0[];
out dvec2 r1;
uniform double u0 = 0.0lf;
void main() {
  dvec4 x0 = in0[0];
  dmat3 v8 = inverse(dmat3(3.0lf) + dmat3(19.0lf));
  if (smoothstep(-2.0lf, 2.0lf, x0[1]) <= packDouble2x32(unpackDouble2x32(v8[1][0]))) {
    x0.ywz = (transpose(v8) * (dmat3(1.0lf))[1]);
  }
  r1 = -(x0.xy / (1.0lf + abs(u0)));
  EmitVertex();
}
