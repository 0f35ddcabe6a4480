// targets: wgsl
#version 450
// Language features WGSL spells differently (INT_MIN, infinity, const arrays, loose uniform
// arrays, struct locals, while, grouped case labels, shifts, atan2, bool mix).
layout(local_size_x = 4) in;
struct S { double a; int b; };
layout(std430, binding = 0) buffer B { float v[]; };
uniform vec4 arr[3];
const float big[2] = float[2](1e38, -2.5);
float g = 2.0;
void main() {
  int i = 0;
  int m = -2147483648;
  float inf = uintBitsToFloat(0x7f800000u);
  S s = S(1.0lf, 2);
  S t = s;
  v[i] = 1.0;
  i++;
  v[1] = (s.b == t.b) ? inf : big[1] + arr[2].y;
  while (i < 10 && v[0] > 0.0) { i += 2; if (i == 5) break; }
  switch (i) { case 1: case 2: v[2] = 3.0; break; default: v[2] = float(m); }
  v[3] = float(s.a * double(g)) + atan(1.0, 2.0) + inversesqrt(4.0);
  v[4] = float(i >> 1) + float(uint(i) << 2u);
  uvec2 bits = floatBitsToUint(vec2(v[6], v[7]));
  bits = ((bits >> 23u) & 0xffu) | (bits << uvec2(1u, 2u)) ^ 1u;  // the integer forms df64-int's runtime uses
  v[6] = uintBitsToFloat(bits.x) + uintBitsToFloat(bits.y);
  bvec2 bb = lessThan(vec2(1.0), vec2(2.0));
  v[5] = mix(1.0, 2.0, bb.x) + (all(bb) ? 1.0 : 0.0);
}
