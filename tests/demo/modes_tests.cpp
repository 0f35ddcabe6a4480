#include <gtest/gtest.h>

#include "demo/modes.hpp"

namespace doublet::demo {

TEST(DemoModes, DemotionRewritesOnlyDoubleSpellings) {
  EXPECT_EQ(demote_doubles("uniform dvec3 eye; double s = 2.0lf * 1e3LF; dmat4 m; doubled x;"),
            "uniform vec3 eye; float s = 2.0 * 1e3; mat4 m; doubled x;");
}

TEST(DemoModes, UnimplementedPrecisionModesAreRejected) {
  std::vector<Mode> modes;
  std::string error;
  EXPECT_FALSE(parse_modes({"fp32", "rte"}, &modes, &error));
  EXPECT_NE(error.find("unknown mode 'rte'"), std::string::npos);
  EXPECT_FALSE(parse_modes({"df64-fast"}, &modes, &error));
  ASSERT_TRUE(parse_modes({}, &modes, &error));
  EXPECT_EQ(modes, all_modes());
}

}  // namespace doublet::demo
