#include <gtest/gtest.h>

#include "demo/modes.hpp"

namespace doublet::demo {

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
