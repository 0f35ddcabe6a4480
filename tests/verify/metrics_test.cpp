// Correct bits, classes and order statistics of verify's metrics; input generation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "doublet/split.hpp"
#include "verify/inputs.hpp"
#include "verify/metrics.hpp"

namespace doublet::verify {
namespace {

TEST(CorrectBits, RelativeErrorInBits) {
  double rel = 0;
  EXPECT_EQ(correct_bits(1.0, 1.0, 1e-38, &rel), kMaxBits);
  EXPECT_DOUBLE_EQ(correct_bits(1.0 + 0x1p-40, 1.0, 1e-38, &rel), 40.0);
  EXPECT_DOUBLE_EQ(rel, 0x1p-40);
  EXPECT_DOUBLE_EQ(correct_bits(-8.0 * (1 + 0x1p-30), -8.0, 1e-38, &rel), 30.0);
}

TEST(CorrectBits, AbsoluteFloorNearZero) {
  double rel = 0;
  // |want| = 0 below the floor 2^-20: error 2^-50 counts as 2^-50 / 2^-20.
  EXPECT_DOUBLE_EQ(correct_bits(0x1p-50, 0.0, 0x1p-20, &rel), 30.0);
}

TEST(CorrectBits, NonFiniteMismatchScoresZero) {
  double rel = 0;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  EXPECT_EQ(correct_bits(inf, 1.0, 1e-38, &rel), 0.0);
  EXPECT_EQ(correct_bits(nan, nan, 1e-38, &rel), kMaxBits);
  EXPECT_EQ(correct_bits(-inf, -inf, 1e-38, &rel), kMaxBits);
}

TEST(Stats, MinP1MedianAndClassMismatches) {
  StatsBuilder b("r", "double", 1e-38);
  for (int i = 0; i < 99; ++i) b.add(1.0 + 0x1p-50, 1.0, static_cast<uint64_t>(i));
  b.add(1.0 + 0x1p-20, 1.0, 99);
  b.add(-0.0, 0.0, 100);  // same value, different class
  const OutputStats s = b.finish();
  EXPECT_EQ(s.samples, 101u);
  EXPECT_DOUBLE_EQ(s.min_bits, 20.0);
  EXPECT_EQ(s.worst_sample, 99u);
  EXPECT_DOUBLE_EQ(s.median_rel_err, 0x1p-50);
  EXPECT_DOUBLE_EQ(s.max_rel_err, 0x1p-20);
  EXPECT_EQ(s.class_mismatches, 1u);
  EXPECT_DOUBLE_EQ(s.p1_bits, 50.0);
}

TEST(Inputs, DoublesAreFloatFloatExactAndInRange) {
  InputGenerator gen(5);
  InputSpec range;
  range.lo = 0.5;
  range.hi = 2.0;
  for (int i = 0; i < 1000; ++i) {
    const double x = gen.next(range, true, static_cast<uint64_t>(i));
    EXPECT_EQ(join(split(x)), x);
    EXPECT_GE(x, 0.5);
    EXPECT_LE(x, 2.0);
    const double f = gen.next(InputSpec{}, false, static_cast<uint64_t>(i));
    EXPECT_EQ(static_cast<double>(static_cast<float>(f)), f);
  }
}

TEST(Inputs, ValuesAreCycledExactly) {
  InputGenerator gen(5);
  InputSpec spec;
  spec.values = {0.1, -3.0};
  EXPECT_EQ(gen.next(spec, true, 0), join(split(0.1)));
  EXPECT_EQ(gen.next(spec, true, 3), -3.0);
}

}  // namespace
}  // namespace doublet::verify
