// doublet_lower_shaders(... EMBED) used inside this tree (see CMakeLists.txt): the
// generated header holds the lowered source and the manifest as constants.
#include <gtest/gtest.h>

#include <string>

#include "doublet/pack.hpp"
#include "globe_rte.vert.hpp"
#include "orbit_step.comp.hpp"

namespace {

TEST(EmbeddedHeader, HoldsLoweredSourceAndManifest) {
  namespace orbit = embedded_test::orbit_step_comp;
  EXPECT_EQ(orbit::stage, "comp");
  EXPECT_EQ(orbit::target, "es310");
  EXPECT_TRUE(orbit::source.starts_with("#version 310 es")) << orbit::source.substr(0, 80);
  EXPECT_NE(orbit::source.find("dt_hi"), std::string_view::npos);
  std::string error;
  auto manifest = doublet::pack::parse_manifest(orbit::manifest, &error);
  ASSERT_TRUE(manifest) << error;
  ASSERT_NE(manifest->find("mu"), nullptr);
  EXPECT_EQ(manifest->find("mu")->lowered_names, (std::vector<std::string>{"mu_hi", "mu_lo"}));
}

TEST(EmbeddedHeader, EachShaderHasItsOwnNamespace) {
  namespace globe = embedded_test::globe_rte_vert;
  EXPECT_EQ(globe::stage, "vert");
  auto manifest = doublet::pack::parse_manifest(globe::manifest);
  ASSERT_TRUE(manifest);
  EXPECT_TRUE(manifest->find("position")->split);
}

}  // namespace
