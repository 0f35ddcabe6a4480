// Host split helpers: exactness against long double, range reporting, bulk forms.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "doublet/split.hpp"

namespace {

TEST(Split, HiIsTheNearestFloatAndLoTheExactRest) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> e(-100, 100);
  for (int i = 0; i < 100000; ++i) {
    double x = std::exp2(e(rng)) * (i % 2 ? -1 : 1);
    doublet::FloatPair p = doublet::split(x);
    EXPECT_EQ(p.hi, static_cast<float>(x));
    // x - hi is exact in double; lo rounds it once, so |x - (hi+lo)| <= ulp(lo)/2 ~ 2^-48 |x|.
    long double err = static_cast<long double>(x) - (static_cast<long double>(p.hi) + p.lo);
    EXPECT_LE(std::fabs(static_cast<double>(err)), std::ldexp(std::fabs(x), -47)) << x;
  }
}

TEST(Split, ReportsValuesOutsideFloatFloatRange) {
  doublet::FloatPair p;
  EXPECT_EQ(doublet::split_checked(1e100, p), doublet::SplitStatus::Overflow);
  EXPECT_EQ(doublet::split_checked(1e-300, p), doublet::SplitStatus::Underflow);
  EXPECT_EQ(doublet::split_checked(0.5, p), doublet::SplitStatus::Exact);
  EXPECT_EQ(doublet::split_checked(0.1, p), doublet::SplitStatus::Rounded);  // 53 bits do not fit in 48
  EXPECT_EQ(doublet::split_checked(1.0 + std::ldexp(1.0, -40), p), doublet::SplitStatus::Exact);
  EXPECT_EQ(doublet::join(p), 1.0 + std::ldexp(1.0, -40));
}

TEST(Split, InfinityKeepsLoZero) {
  doublet::FloatPair p = doublet::split(std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isinf(p.hi));
  EXPECT_EQ(p.lo, 0.0f);
  EXPECT_TRUE(std::isinf(doublet::join(p)));
}

TEST(Split, BulkAndInterleavedMatchScalar) {
  std::vector<double> x = {42164137.0, -0.1, 3.986004418e14, 1e-5, 6378137.25};
  std::vector<float> hi(x.size()), lo(x.size());
  doublet::split(x, hi, lo);
  std::vector<double> back(x.size());
  doublet::join(hi, lo, back);
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(hi[i], doublet::split(x[i]).hi);
    EXPECT_EQ(lo[i], doublet::split(x[i]).lo);
    EXPECT_EQ(back[i], doublet::join(doublet::split(x[i])));
  }
  std::vector<double> positions = {1, 2, 3, 4.5, 5.5, 6.5};  // two dvec3
  std::vector<float> interleaved(2 * 7, -1.0f);               // stride 7: hi.xyz lo.xyz + 1 spare
  doublet::split_interleaved(positions, 3, interleaved, 7);
  EXPECT_EQ(interleaved[0], 1.0f);
  EXPECT_EQ(interleaved[3], 0.0f);   // lo of 1.0
  EXPECT_EQ(interleaved[7], 4.5f);
  EXPECT_EQ(interleaved[6], -1.0f);  // spare untouched
}

}  // namespace
