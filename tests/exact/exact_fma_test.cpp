// Mode exact's fma(a, b, c) (rules/exact.glsl ex_fma_bits) against native fp64 fma on lavapipe,
// run on lavapipe and on Mesa GLES, 2^20 operand triples: random patterns, exponent grid, every
// special class, and the cases where one rounding differs from two: c cancelling the rounded
// product, c far below a product that lies exactly halfway between two doubles, products beyond
// DBL_MAX that c brings back, subnormal results. What native fma is (fused or a*b+c rounded twice)
// is measured against the host's std::fma and its two-rounding a*b+c, and printed.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "exact_harness.hpp"

namespace doublet::runner::test::exact {
namespace {

constexpr uint32_t kTriples = 1u << 20;

std::vector<uint64_t> make_triples() {
  Operands op(20261125);
  auto& rng = op.rng();
  std::vector<uint64_t> abc;
  abc.reserve(3 * size_t(kTriples));
  for (uint32_t i = 0; i < kTriples; ++i) {
    uint64_t a = 0, b = 0, c = 0;
    switch (i % 8) {
      case 0: a = rng(), b = rng(), c = rng(); break;
      case 1: a = op.grid(), b = op.grid(), c = op.grid(); break;
      case 2: {  // short significands: sums of exact products land on ties
        const uint64_t ea = 700 + rng() % 640, eb = 700 + rng() % 640, ec = ea + eb - 1023 - 60 + rng() % 120;
        a = op.short_sig(ea, int(rng() % 27)), b = op.short_sig(eb, int(rng() % 27)), c = op.short_sig(ec, int(rng() % 53));
        break;
      }
      case 3: {  // c cancels the rounded product: the fused result is the product's rounding error
        a = op.short_sig(900 + rng() % 240, 52), b = op.short_sig(900 + rng() % 240, 52);
        const double p = dbl(a) * dbl(b);
        c = pat(-p) + (rng() % 5) - 2;
        break;
      }
      case 4: {  // 27-bit odd significands: a 54-bit product, exactly halfway; c far below tips it
        const uint64_t ea = 900 + rng() % 240, eb = 900 + rng() % 240;
        a = op.random_sign((ea << 52) | ((rng() >> 38) << 26) | (1ull << 26));
        b = op.random_sign((eb << 52) | ((rng() >> 38) << 26) | (1ull << 26));
        const int64_t ec = int64_t(ea + eb) - 1023 - 54 - int64_t(rng() % 70);
        c = ec >= 1 ? op.random_sign((uint64_t(ec) << 52) | (rng() >> 12)) : op.random_sign(rng() >> 12);
        break;
      }
      case 5: {  // products just beyond DBL_MAX, c brings them back (or not)
        a = op.short_sig(1023 + 512 + rng() % 2, 52), b = op.short_sig(1023 + 511 - rng() % 2, 52);
        c = (rng() & 1) ? op.short_sig(2046 - rng() % 60, 52) : op.special();
        break;
      }
      case 6: {  // subnormal and near-subnormal results
        const uint64_t ea = 1 + rng() % 1022, eb = 1023 - ea + 1 + rng() % 60;
        a = op.short_sig(ea, 52), b = op.short_sig(eb > 1023 + 60 ? 1023 : 1023 - (eb % 60), 52);
        c = op.random_sign((rng() % 3) << 52 | (rng() >> 12));
        break;
      }
      default:  // a special value in one or two places
        a = op.any(), b = op.any(), c = op.any();
        if (rng() & 1) a = op.special();
        if (rng() & 1) b = op.special();
        if (rng() & 1) c = op.special();
        break;
    }
    abc.insert(abc.end(), {a, b, c});
  }
  return abc;
}

const std::vector<uint64_t>& triples() {
  static const std::vector<uint64_t> v = make_triples();
  return v;
}

std::string native_fma_shader() {
  return words_shader("#version 450\n", 3, 1,
                      "  r[i] = unpackDouble2x32(fma(packDouble2x32(w[0]), packDouble2x32(w[1]), packDouble2x32(w[2])));\n");
}

std::string exact_fma_shader(const std::string& library) {
  return words_shader("#version 310 es\n" + library, 3, 1, "  r[i] = ex_fma_bits(w[0], w[1], w[2]);\n");
}

std::vector<uint64_t> host(bool fused) {
  const auto& abc = triples();
  std::vector<uint64_t> out(kTriples);
  for (uint32_t i = 0; i < kTriples; ++i) {
    const double a = dbl(abc[3 * i]), b = dbl(abc[3 * i + 1]), c = dbl(abc[3 * i + 2]);
    if (fused) {
      out[i] = pat(std::fma(a, b, c));
    } else {
      volatile double p = a * b;  // rounded once here, then once in the sum
      out[i] = pat(p + c);
    }
  }
  return out;
}

std::vector<uint64_t> non_nan_differences(const std::vector<uint64_t>& x, const std::vector<uint64_t>& y) {
  std::vector<uint64_t> at;
  for (size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i] != y[i] && !(is_nan(x[i]) && is_nan(y[i]))) at.push_back(i);
  return at;
}

// What native fma on lavapipe is: its results against a single rounding (std::fma) and against
// two (a*b rounded, then + c). Measured: two roundings (Mesa 22.3.6, LLVM 15). The contract of
// mode exact is native's bits, so ex_fma_bits rounds twice too; this test says when that changes.
TEST(ExactFma, NativeFmaOnLavapipeRoundsTwice) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const std::vector<uint64_t> native = run_words(Backend::Vulkan, native_fma_shader(), triples(), 3, 1);
  ASSERT_EQ(native.size(), kTriples);
  const auto vs_fused = non_nan_differences(native, host(true)), vs_unfused = non_nan_differences(native, host(false));
  std::cout << "[ exact ] native fma on lavapipe vs host std::fma (one rounding): " << vs_fused.size() << " of "
            << kTriples << " differ (NaN payloads apart); vs a*b+c rounded twice: " << vs_unfused.size() << "\n";
  EXPECT_EQ(vs_unfused.size(), 0u);
  EXPECT_GT(vs_fused.size(), 0u) << "the inputs do not tell one rounding from two";
}

TEST(ExactFma, BitIdenticalToNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const std::vector<uint64_t> native = run_words(Backend::Vulkan, native_fma_shader(), triples(), 3, 1);
  ASSERT_EQ(native.size(), kTriples);
  const std::string shader = exact_fma_shader(exact_library({"ex_fma_bits"}));
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const std::vector<uint64_t> got = run_words(backend, shader, triples(), 3, 1);
    const Diff d = compare(got, native);
    std::cout << "[ exact ] fma on " << backend_name(backend) << " vs native: "
              << describe(d, got, native, triples(), 3, 1) << "\n";
    EXPECT_EQ(d.differing, 0u) << backend_name(backend);
  }
}

// The same comparison sees a broken fma: ties rounded away from zero, the sticky bit dropped, the
// product's rounding skipped (a single rounding, as IEEE fusedMultiplyAdd, which native is not).
TEST(ExactFma, SabotageMakesResultsDiffer) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const std::vector<uint64_t> native = run_words(Backend::Vulkan, native_fma_shader(), triples(), 3, 1);
  const std::string library = exact_library({"ex_fma_bits"});
  const std::vector<std::pair<const char*, std::pair<std::string, std::string>>> sabotages = {
      {"ties away from zero", {"uint tie = roundBits == 0x200u ? 0xFFFFFFFEu : 0xFFFFFFFFu;", "uint tie = 0xFFFFFFFFu;"}},
      {"no sticky bit", {"uint jam = lost ? 1u : 0u;", "uint jam = 0u;"}},
      {"product not rounded (truncated to 53 bits)",
       {"uvec2 sig = uvec2((w1 >> 10) | (w2 << 22) | sticky, ", "uvec2 sig = uvec2(((w1 >> 10) | (w2 << 22)) & 0xFFFFFC00u, "}},
  };
  for (const auto& [name, edit] : sabotages) {
    std::string sabotaged = library;
    const size_t at = sabotaged.find(edit.first);
    ASSERT_NE(at, std::string::npos) << name;
    sabotaged.replace(at, edit.first.size(), edit.second);
    const Diff d = compare(run_words(Backend::Vulkan, exact_fma_shader(sabotaged), triples(), 3, 1), native);
    std::cout << "[ exact ] fma sabotage '" << name << "': " << d.differing << " of " << kTriples << " differ\n";
    EXPECT_GT(d.differing, 0u) << name;
  }
}

}  // namespace
}  // namespace doublet::runner::test::exact
