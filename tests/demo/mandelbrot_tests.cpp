// The deep-zoom demo at 1e-12 per pixel, small: df64 matches native fp64, fp32 does not.
#include <gtest/gtest.h>

#include "demo/mandelbrot.hpp"

namespace doublet::demo {

TEST(DemoMandelbrot, Df64MatchesNativeAtDeepZoomAndFp32DoesNot) {
  MandelbrotOptions o;
  o.zooms = {1e-12};
  o.width = o.height = 64;
  o.max_iterations = 500;
  const MandelbrotResult r = run_mandelbrot(o);
  ASSERT_TRUE(r.ok) << r.error;
  const auto& modes = r.views.at(0).modes;
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_EQ(modes[0].mode, Mode::Fp32);
  EXPECT_LT(modes[0].equal_to_native, 0.99);
  EXPECT_EQ(modes[1].mode, Mode::Df64);
  EXPECT_GE(modes[1].equal_to_native, 0.99);
}

}  // namespace doublet::demo
