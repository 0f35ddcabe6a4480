// A user's shader is made self-contained (includes expanded) and desktop 4.50 for native fp64.
#include <gtest/gtest.h>

#include <cstdio>

#include "bench/user_shader.hpp"

namespace {
using namespace doublet::bench;

TEST(BenchUserShader, IncludesAreExpandedOnce) {
  std::string text, error;
  ASSERT_TRUE(expand_includes(std::string(DOUBLET_EXAMPLES) + "/shaders/orbit_step.comp", {}, &text, &error)) << error;
  EXPECT_EQ(text.find("#include"), std::string::npos);
  EXPECT_NE(text.find("double load_pair(vec2 p)"), std::string::npos);
  EXPECT_EQ(text.find("double load_pair(vec2 p)"), text.rfind("double load_pair(vec2 p)"));
}

TEST(BenchUserShader, MissingIncludeIsAnError) {
  std::string text, error;
  EXPECT_FALSE(expand_includes(std::string(DOUBLET_EXAMPLES) + "/no-such.comp", {}, &text, &error));
  EXPECT_NE(error.find("no-such.comp"), std::string::npos);
}

// An endless input (or one that includes /dev/zero) is refused at doublet's source limit, not read
// until memory runs out (it was read whole before).
TEST(BenchUserShader, EndlessInputsStopAtTheSourceLimit) {
  std::string text, error;
  EXPECT_FALSE(expand_includes("/dev/zero", {}, &text, &error));
  EXPECT_NE(error.find("64 MiB"), std::string::npos) << error;
  const std::string shader = ::testing::TempDir() + "includes_dev_zero.comp";
  FILE* f = std::fopen(shader.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs("#version 450\n#include \"/dev/zero\"\nvoid main() {}\n", f);
  std::fclose(f);
  error.clear();
  EXPECT_FALSE(expand_includes(shader, {}, &text, &error));
  EXPECT_NE(error.find("/dev/zero: "), std::string::npos) << error;
  EXPECT_LE(text.size(), std::size_t{64} << 20);
}

TEST(BenchUserShader, VersionBecomesDesktop450) {
  EXPECT_EQ(as_desktop_450("// c\n#version 310 es\nvoid main() {}\n"), "// c\n#version 450\nvoid main() {}\n");
  EXPECT_EQ(as_desktop_450("void main() {}\n"), "void main() {}\n");
}

}  // namespace
