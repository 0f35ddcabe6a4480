// Writes the reference vectors for js/test/host.test.mjs: for each input double, what the C++ host
// helpers (include/doublet/split.hpp) make of it: split()'s hi and lo as float bit patterns, the
// bulk split()'s, and exact_words()' two words (low first). Inputs travel as their binary64 words,
// since JSON numbers cannot hold -0, NaN or Inf; "text" (%.17g) lets the test cross-check them.
// Usage: host_vectors OUT.json
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "doublet/split.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUT.json\n", argv[0]);
    return 2;
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double flt_max = FLT_MAX;
  const double flt_max_half_ulp = std::ldexp(1.0, 103);  // FLT_MAX + this is the tie to Inf
  std::vector<double> x = {
      0.0, -0.0, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
      std::numeric_limits<double>::min(), 1e-310, -1e-310,            // double subnormals / min
      1e300, -1e300, 1e-300, -1e-300, 1e-40, -1e-40, 1e-45, 0x1p-150,  // beyond / in float's subnormals
      0x1p-149, 0x1.8p-149, FLT_MIN, FLT_MIN * 0.75, -FLT_TRUE_MIN,
      flt_max, -flt_max, std::nextafter(flt_max, inf), std::nextafter(flt_max, 0.0),
      flt_max + flt_max_half_ulp, -(flt_max + flt_max_half_ulp),       // the tie: rounds to Inf
      std::nextafter(flt_max + flt_max_half_ulp, 0.0),                 // just below it: FLT_MAX
      flt_max + 2 * flt_max_half_ulp, std::numeric_limits<double>::max(),
      1.0, -1.0, 0.1, -0.1, 1.0 / 3, 3.141592653589793, -2.718281828459045, 1e10, 123456789.123456789,
      1 + 0x1p-24,             // tie: rounds to even (down), lo = +2^-24
      1 + 3 * 0x1p-24,         // tie: rounds to even (up), lo < 0
      1 + 0x1p-24 + 0x1p-40,   // above the tie: hi rounds up, lo < 0
      1 - 0x1p-25 - 0x1p-50,   // just below 1: hi = 1, lo < 0
      -(1 + 0x1p-24 + 0x1p-40), 0x1.ffffffp0, 0x1.fffffffffffffp1023 / 0x1p900,
  };
  // Random values over many decades (about 1e-50 .. 1e50, past float's range on both ends),
  // random signs and full 53-bit significands; fixed seed so the file is reproducible.
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> decade(-50.0, 50.0), mantissa(1.0, 10.0);
  for (int i = 0; i < 400; ++i) {
    double v = mantissa(rng) * std::pow(10.0, std::floor(decade(rng)));
    x.push_back((rng() & 1) ? -v : v);
  }

  std::vector<float> bulk_hi(x.size()), bulk_lo(x.size());
  doublet::split(std::span<const double>(x), std::span<float>(bulk_hi), std::span<float>(bulk_lo));

  std::FILE* out = std::fopen(argv[1], "w");
  if (!out) {
    std::perror(argv[1]);
    return 1;
  }
  std::fprintf(out, "{\"vectors\": [\n");
  for (std::size_t i = 0; i < x.size(); ++i) {
    const doublet::FloatPair p = doublet::split(x[i]);
    const doublet::ExactWords w = doublet::exact_words(x[i]);
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x[i]);
    std::fprintf(out,
                 "  {\"words\": [%u, %u], \"text\": \"%s\", \"hi\": %u, \"lo\": %u, \"bulk_hi\": %u, "
                 "\"bulk_lo\": %u, \"join\": [%u, %u]}%s\n",
                 w.lo, w.hi, text, std::bit_cast<std::uint32_t>(p.hi), std::bit_cast<std::uint32_t>(p.lo),
                 std::bit_cast<std::uint32_t>(bulk_hi[i]), std::bit_cast<std::uint32_t>(bulk_lo[i]),
                 doublet::exact_words(doublet::join(p)).lo, doublet::exact_words(doublet::join(p)).hi,
                 i + 1 < x.size() ? "," : "");
  }
  std::fprintf(out, "]}\n");
  return std::fclose(out) == 0 ? 0 : 1;
}
