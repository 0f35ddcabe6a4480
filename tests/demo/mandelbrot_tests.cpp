// The deep-zoom demo at 1e-12 per pixel, default size: df64 matches native fp64, fp32 does not.
#include <gtest/gtest.h>

#include "demo/mandelbrot.hpp"

namespace doublet::demo {

TEST(DemoMandelbrot, Df64MatchesNativeAtDeepZoomAndFp32DoesNot) {
  MandelbrotOptions o;
  o.zooms = {1e-12};
  // The demo's own view and size (256x256, ~1 s): a smaller crop of it is only the minibrot's
  // chaotic core, where df64 and double part ways on ~3% of pixels.
  
  const MandelbrotResult r = run_mandelbrot(o);
  ASSERT_TRUE(r.ok) << r.error;
  const auto& modes = r.views.at(0).modes;
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_EQ(modes[0].mode, Mode::Fp32);
  EXPECT_LT(modes[0].equal_to_native, 0.99);
  EXPECT_EQ(modes[1].mode, Mode::Df64);
  EXPECT_GE(modes[1].equal_to_native, 0.99);
  EXPECT_GT(r.views[0].native_distinct_counts, 10);  // a real picture, not one flat colour
}

}  // namespace doublet::demo
