// Host-side helpers: split doubles into the hi/lo floats a lowered shader
// expects (X_hi, X_lo in the manifest), and join them back.
//
// split(x) gives hi = float(x) (round to nearest) and lo = float(x - hi); the
// pair carries about 48 bits. Values outside float range have no float-float
// representation: split_checked() reports them instead of silently producing
// Inf or 0. Header-only, no dependencies; loops are written to vectorise.
// exact_words()/exact_join(): the uint words of mode exact (bit-exact, the whole double range).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstddef>
#include <cstring>
#include <limits>
#include <span>

namespace doublet {

struct FloatPair {
  float hi = 0;
  float lo = 0;
};

inline FloatPair split(double x) {
  float hi = static_cast<float>(x);
  // Inf/NaN: lo = 0 keeps hi + lo == hi (x - Inf would be NaN).
  float lo = std::isfinite(hi) ? static_cast<float>(x - static_cast<double>(hi)) : 0.0f;
  return {hi, lo};
}

// hi + lo, except that a zero keeps hi's sign: (-0, +0) joins to -0 (IEEE's -0 + +0 is +0).
inline double join(float hi, float lo) {
  if (hi == 0 && lo == 0) return static_cast<double>(hi);
  return static_cast<double>(hi) + static_cast<double>(lo);
}
inline double join(FloatPair p) { return join(p.hi, p.lo); }

enum class SplitStatus {
  Exact,      // hi + lo == x
  Rounded,    // |x| is representable but needs more than ~48 bits (normal: a double has 53)
  Overflow,   // |x| > FLT_MAX: hi is ±Inf
  Underflow,  // 0 < |x| below float's range: hi is 0 or subnormal, precision lost
};

// Like split(), and says whether the value survived.
inline SplitStatus split_checked(double x, FloatPair& out) {
  out = split(x);
  if (std::isnan(x) || std::isinf(x)) return SplitStatus::Exact;  // NaN/Inf carry over as themselves
  if (std::isinf(out.hi)) return SplitStatus::Overflow;
  if (x != 0 && std::fabs(x) < static_cast<double>(std::numeric_limits<float>::min())) return SplitStatus::Underflow;
  return join(out) == x ? SplitStatus::Exact : SplitStatus::Rounded;
}

// Bulk: x[i] → hi[i], lo[i]. The spans must have equal sizes.
inline void split(std::span<const double> x, std::span<float> hi, std::span<float> lo) {
  const std::size_t n = x.size();
  for (std::size_t i = 0; i < n; ++i) {
    float h = static_cast<float>(x[i]);
    hi[i] = h;
    lo[i] = static_cast<float>(x[i] - static_cast<double>(h));
  }
  for (std::size_t i = 0; i < n; ++i)  // rare fix-up kept out of the hot loop
    if (!std::isfinite(hi[i])) lo[i] = 0.0f;
}

// Bulk into interleaved vertex data: for each element of `components` doubles
// (e.g. 3 for dvec3), writes `components` hi floats then `components` lo floats
// at `stride_floats` apart (the attribute pair X_hi, X_lo in one buffer).
inline void split_interleaved(std::span<const double> x, std::size_t components, std::span<float> out,
                              std::size_t stride_floats) {
  const std::size_t count = components ? x.size() / components : 0;
  for (std::size_t v = 0; v < count; ++v) {
    float* dst = out.data() + v * stride_floats;
    for (std::size_t c = 0; c < components; ++c) {
      FloatPair p = split(x[v * components + c]);
      dst[c] = p.hi;
      dst[components + c] = p.lo;
    }
  }
}

inline void join(std::span<const float> hi, std::span<const float> lo, std::span<double> x) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = join(hi[i], lo[i]);
}

// Mode exact (--mode exact): a double travels as the two 32-bit words of its IEEE binary64 bit
// pattern, every value representable (subnormals, ±0, ±Inf, NaN), LOW word first: the order of a
// shader's uvec2 (x = bits 0-31, y = bits 32-63: sign, exponent, top 20 significand bits), of
// GLSL's packDouble2x32/unpackDouble2x32, and of a little-endian host's memory. So the raw bytes of
// a host double array are already the words a lowered shader takes (`double X` -> `uvec2 X`,
// `dvec2` -> `uvec4`; dvec3/dvec4 -> X_xy + X_z/X_zw; block members at their original offsets).
struct ExactWords {
  std::uint32_t lo = 0;  // uvec2.x
  std::uint32_t hi = 0;  // uvec2.y
};
static_assert(sizeof(ExactWords) == sizeof(double));

namespace detail {
// std::bit_cast where the standard library has it; memcpy (the same bits) where it does not
// (Emscripten's libc++ 14, for the WebAssembly build).
template <class To, class From>
inline To bits_as(const From& from) {
#if defined(__cpp_lib_bit_cast)
  return std::bit_cast<To>(from);
#else
  static_assert(sizeof(To) == sizeof(From));
  To to;
  std::memcpy(&to, &from, sizeof(To));
  return to;
#endif
}
}  // namespace detail

inline ExactWords exact_words(double x) {
  const auto bits = detail::bits_as<std::uint64_t>(x);
  return {static_cast<std::uint32_t>(bits), static_cast<std::uint32_t>(bits >> 32)};
}

inline double exact_join(ExactWords w) {
  return detail::bits_as<double>((std::uint64_t{w.hi} << 32) | w.lo);
}

// Bulk: 2 words per double, low word first, into `words` (size 2 × x.size()): the uint data of
// glUniform2uiv/glUniform4uiv or of a GL_UNSIGNED_INT vertex attribute, on any host byte order.
inline void exact_words(std::span<const double> x, std::span<std::uint32_t> words) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const ExactWords w = exact_words(x[i]);
    words[2 * i] = w.lo;
    words[2 * i + 1] = w.hi;
  }
}

inline void exact_join(std::span<const std::uint32_t> words, std::span<double> x) {
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = exact_join({words[2 * i], words[2 * i + 1]});
}

}  // namespace doublet
