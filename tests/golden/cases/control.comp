// targets: wgsl
#version 450
// Control flow and language features WGSL spells differently: loops, do-while, out parameters,
// ternaries, ++, mod, compound assignment, swizzle assignment, shared memory and barriers.
layout(local_size_x = 8, local_size_y = 2) in;
layout(std430, binding = 2) buffer Data { dvec2 acc[16]; float f[]; };
shared float tile[16];
void split(double x, out float hi, inout float count) {
  hi = float(x);
  count += 1.0;
}
int steps(int n) {
  int k = 0;
  do { k++; n = n / 2; } while (n > 1);
  return k;
}
void main() {
  uint i = gl_LocalInvocationIndex;
  tile[i] = float(i);
  barrier();
  double s = 0.0lf;
  for (int k = 0; k < 4; ++k) {
    if (k == 2) continue;
    s += double(tile[(i + uint(k)) % 16u]) * 0.1lf;
  }
  float hi;
  float count = 0.0;
  split(s, hi, count);
  vec3 v = vec3(1.0);
  v.xz = vec2(hi, count);
  float m = mod(v.x, 3.0);
  acc[i].x = s;
  acc[i].y = i > 3u ? double(m) : s * 2.0lf;
  f[i] = float(steps(int(i) + 3)) + v.z + (isnan(m) ? 1.0 : 0.0);
}
