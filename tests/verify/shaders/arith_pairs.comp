#version 310 es
// x op y for every op, stored as (hi, lo) pairs so the float interface keeps ~48 bits.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 operands[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec2 results[]; };
void store(uint slot, double r) { float hi = float(r); results[slot] = vec2(hi, float(r - double(hi))); }
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = operands[i];
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  store(i * 4u + 0u, x + y);
  store(i * 4u + 1u, x * y);
  store(i * 4u + 2u, x / y);
  store(i * 4u + 3u, sqrt(abs(x)));
}
