// targets: glsl450
#version 450
// 64-bit integers (GL_ARB_gpu_shader_int64) pass through on desktop 4.x; their conversions to and
// from doubles lower (src/lower/lower_doubles.cpp, int64_conversion; the bit casts:
// int64_bit_casts.comp). Against native fp64 and int64 on lavapipe (tests/golden CMake).
#extension GL_ARB_gpu_shader_int64 : require
layout(local_size_x = 16) in;
layout(std430, binding = 0) buffer Data { dvec2 x[]; };
layout(std430, binding = 1) buffer Results { dvec4 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec2 v = x[i] * 1.0e6lf;
  int64_t micro = int64_t(v.x) * 1000l - int64_t(v.y);
  uint64_t bits = uint64_t(abs(micro)) ^ 0x5555555555555555ul;
  i64vec2 pair = i64vec2(dvec2(v.y, -v.x) * 4096.0lf);
  double back = double(micro) / 7.0lf;
  double huge = 1.0e19lf + abs(v.x);  // past 2^63: uint64_t's top bit
  double wide = double(bits >> 11) + double(uint64_t(huge) >> 11);
  // pair * 3l, not pair: native lavapipe folds double(int64_t(x)) into fp64 trunc(x), which on AVX2-only
  // machines leaves the fraction of |x| > 2^24 (docs/extremes.md) and would make native the wrong oracle.
  dvec2 both = dvec2(pair * 3l) + dvec2(u64vec2(uint64_t(i) << 40, 3ul));
  r[i] = dvec4(back, wide, both);
}
