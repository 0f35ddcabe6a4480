// targets: es310 es320 glsl450
#version 310 es
// A swizzle of a swizzle of a double vector written (plain, compound, ++) composes into one
// swizzle of the vector: v.xz.y is v.z, v.wzyx.yx is v.zw.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double r[]; };
void main() {
  dvec4 v = dvec4(r[0], r[1], r[2], r[3]);
  v.xz.y = 7.0lf;
  v.wzyx.yx += dvec2(1.0lf, 2.0lf);
  v.zyx.xy.y *= 3.0lf;
  ++v.xw.y;
  r[4] = v.x + v.y + v.z + v.w;
}
