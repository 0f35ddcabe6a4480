// targets: glsl450
#version 450
// The 64-bit integer bit casts of doubles (GL_ARB_gpu_shader_int64) go through the binary64 words
// (src/lower/lower_doubles.cpp, lower_int64_bit_casts), per component. Against native on lavapipe
// (tests/golden CMake): a float-float value's pattern is the double nearest to its pair.
#extension GL_ARB_gpu_shader_int64 : require
layout(local_size_x = 16) in;
layout(std430, binding = 0) buffer Data { dvec2 x[]; };
layout(std430, binding = 1) buffer Bits { dvec4 b[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  // The last significand bit flipped, and the low bits of the patterns.
  double nudged = uint64BitsToDouble(doubleBitsToUint64(x[i].x) ^ 1ul);
  i64vec2 patterns = doubleBitsToInt64(x[i]);
  dvec2 again = int64BitsToDouble(patterns);
  b[i] = dvec4(nudged, double(patterns.y & 0xFFFFFl), again - x[i]);
}
