// The jitter demo at a small size on llvmpipe (fp32, df64) and lavapipe (native fp64).
#include <gtest/gtest.h>

#include "demo/jitter.hpp"

namespace doublet::demo {

JitterModeResult wobble(Mode mode) {
  JitterOptions o;
  o.modes = {mode};
  o.frames = 24;
  o.width = 160;
  o.height = 120;
  const JitterResult r = run_jitter(o);
  EXPECT_TRUE(r.ok) << r.error;
  return r.ok ? r.modes.at(0) : JitterModeResult{};
}

TEST(DemoJitter, Fp32ShakesByPixelsAtGeostationaryDistance) {
  EXPECT_GE(wobble(Mode::Fp32).max_wobble_px, 1.0);
}

TEST(DemoJitter, Df64StaysBelowOneHundredthOfAPixel) {
  const JitterModeResult m = wobble(Mode::Df64);
  EXPECT_GT(m.max_wobble_px, 0.0);  // measured, not skipped
  EXPECT_LT(m.max_wobble_px, 0.01);
}

TEST(DemoJitter, NativeFp64StaysBelowOneHundredthOfAPixel) {
  EXPECT_LT(wobble(Mode::Native).max_wobble_px, 0.01);
}

}  // namespace doublet::demo
