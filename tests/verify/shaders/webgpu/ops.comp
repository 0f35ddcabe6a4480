#version 450
// Held-out-style accuracy check for `doublet verify --backend webgpu`
// (tests/verify/webgpu_verify_test.cpp): add, sub, mul, div and sqrt of random operands and a
// three-stage expression, each a double in its own output array (read back as hi + lo).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec4 operands[]; };
layout(std430, binding = 1) writeonly buffer Sums { dvec2 add_sub[]; };
layout(std430, binding = 2) writeonly buffer Products { dvec2 mul_div[]; };
layout(std430, binding = 3) writeonly buffer Roots { dvec2 sqrt_chain[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 v = operands[i];
  add_sub[i] = dvec2(v.x + v.y, v.x - v.y);
  mul_div[i] = dvec2(v.x * v.y, v.x / v.y);
  double p = v.z * v.w + v.x;
  sqrt_chain[i] = dvec2(sqrt(v.x), sqrt(p) / (v.z + v.w));
}
