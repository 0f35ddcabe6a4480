// Shared by the mode-exact driver tests: binary64 input patterns (random, exponent grid, ties,
// cancellation, subnormal results, every special class), a compute-shader runner that reads and
// writes bit patterns, and the comparison that counts differing results.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "rules/rule_library.hpp"
#include "test_util.hpp"

namespace doublet::runner::test::exact {

constexpr uint64_t kSign = 0x8000000000000000ull;

inline bool is_nan(uint64_t x) { return (x & ~kSign) > 0x7FF0000000000000ull; }
inline double dbl(uint64_t x) { return std::bit_cast<double>(x); }
inline uint64_t pat(double x) { return std::bit_cast<uint64_t>(x); }

// The special classes every operation must meet, each with both signs.
inline std::vector<uint64_t> special_patterns() {
  const uint64_t mags[] = {
      0,                      // zero
      1,                      // smallest subnormal
      0x000FFFFFFFFFFFFFull,  // largest subnormal
      0x0010000000000000ull,  // smallest normal
      0x7FEFFFFFFFFFFFFFull,  // largest normal
      0x7FF0000000000000ull,  // infinity
      0x7FF8000000000000ull,  // quiet NaN
      0x7FF0000000000001ull,  // signalling NaN
      0x3FF0000000000000ull,  // 1
      0x3FE0000000000000ull,  // 0.5
      0x0008000000000000ull,  // subnormal 2^-1023
      0x3CA0000000000000ull,  // 2^-53
  };
  std::vector<uint64_t> out;
  for (uint64_t m : mags) {
    out.push_back(m);
    out.push_back(m | kSign);
  }
  return out;
}

// One operand from the general families: random pattern, exponent grid (subnormal, around 1,
// overflow), short significand (exact products and sums land on ties), special value.
class Operands {
 public:
  explicit Operands(uint64_t seed) : rng_(seed), specials_(special_patterns()) {}
  uint64_t operator()() { return rng_(); }
  uint64_t random_sign(uint64_t m) { return (rng_() & 1) ? m | kSign : m; }
  uint64_t special() { return specials_[rng_() % specials_.size()]; }
  uint64_t grid_exponent() {
    switch (rng_() % 4) {
      case 0: return rng_() % 4;
      case 1: return 1020 + rng_() % 7;
      case 2: return 2043 + rng_() % 5;
      default: return rng_() % 2048;
    }
  }
  uint64_t grid() { return random_sign((grid_exponent() << 52) | (rng_() >> 12)); }
  // Exponent field e (kept in 1..2046), at most `bits` significand bits below the leading one.
  uint64_t short_sig(uint64_t e, int bits) {
    e = std::min<uint64_t>(std::max<uint64_t>(e, 1), 2046);
    const uint64_t frac = bits <= 0 ? 0 : (rng_() >> (64 - bits)) << (52 - bits);
    return random_sign((e << 52) | frac);
  }
  uint64_t any() {
    switch (rng_() % 4) {
      case 0: return rng_();
      case 1: return grid();
      case 2: return short_sig(rng_() % 2047, int(rng_() % 53));
      default: return special();
    }
  }
  std::mt19937_64& rng() { return rng_; }

 private:
  std::mt19937_64 rng_;
  std::vector<uint64_t> specials_;
};

// The rules/exact.glsl functions `names` (width 1) and their dependencies, for ES 3.10.
inline std::string exact_library(const std::vector<std::string>& names) {
  rules::EmitRequest req;
  for (const auto& n : names) req.used.push_back({n, 1});
  req.guard = rules::GuardStyle::None;
  req.exact_words = true;
  req.integer_eft = true;
  req.es_version = 310;
  rules::EmitResult r = rules::RuleLibrary::builtin().emit(req);
  EXPECT_TRUE(r.ok) << r.error;
  return r.text;
}

// A compute shader reading `arity` binary64 patterns per invocation from buffer 0 (uvec2 each,
// low word first) and writing `results` uvec2 per invocation to buffer 1. `body` sees `uint i`,
// `uvec2 w[arity]` (the input words) and assigns r[results * i + k].
inline std::string words_shader(const std::string& version_and_extras, int arity, int results, const std::string& body) {
  return version_and_extras + "layout(local_size_x = 64) in;\n"
         "layout(std430, binding = 0) readonly buffer In { uvec2 ab[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };\n" +
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  uvec2 w[" + std::to_string(arity) + "];\n" +
         "  for (int k = 0; k < " + std::to_string(arity) + "; ++k) w[k] = ab[" + std::to_string(arity) +
         "u * i + uint(k)];\n" + body + "}\n";
}

// Runs `glsl` over `inputs` (arity patterns per invocation); `results` patterns out per invocation.
inline std::vector<uint64_t> run_words(Backend backend, const std::string& glsl, const std::vector<uint64_t>& inputs,
                                       int arity, int results) {
  const size_t n = inputs.size() / size_t(arity);
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = {to_bytes(inputs), std::vector<uint8_t>(n * size_t(results) * 8)};
  job.groups_x = uint32_t(n / 64);
  ComputeResult res = run_compute(backend, job);
  EXPECT_TRUE(res.ok) << backend_name(backend) << ": " << res.error;
  if (!res.ok) return {};
  return from_bytes<uint64_t>(res.buffers[1]);
}

struct Diff {
  uint64_t differing = 0;    // results whose 64 bits differ
  uint64_t nan_payload = 0;  // of which both are NaN (payload or sign of the NaN differs)
  size_t first = 0;          // index of the first differing result
};

inline Diff compare(const std::vector<uint64_t>& got, const std::vector<uint64_t>& want) {
  Diff d;
  EXPECT_EQ(got.size(), want.size());
  for (size_t i = 0; i < got.size() && i < want.size(); ++i) {
    if (got[i] == want[i]) continue;
    if (d.differing++ == 0) d.first = i;
    if (is_nan(got[i]) && is_nan(want[i])) ++d.nan_payload;
  }
  return d;
}

// "N differ (M NaN vs NaN); first: inputs ... got ... want ..." for result index d.first.
inline std::string describe(const Diff& d, const std::vector<uint64_t>& got, const std::vector<uint64_t>& want,
                            const std::vector<uint64_t>& inputs, int arity, int results) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%llu differ (%llu NaN vs NaN)", (unsigned long long)d.differing,
                (unsigned long long)d.nan_payload);
  std::string s = buf;
  if (!d.differing) return s;
  const size_t invocation = d.first / size_t(results);
  s += "; first: inputs";
  for (int k = 0; k < arity; ++k) {
    std::snprintf(buf, sizeof buf, " %016llx", (unsigned long long)inputs[invocation * size_t(arity) + size_t(k)]);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, " result %zu got %016llx want %016llx", d.first % size_t(results),
                (unsigned long long)got[d.first], (unsigned long long)want[d.first]);
  return s + buf;
}

}  // namespace doublet::runner::test::exact
