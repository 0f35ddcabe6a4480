// A small sweep (every 16th binade pair plus all other families) against MPFR: every op within its
// proven bound on both drivers, and outside it under each sabotage. The full sweep is documented in
// docs/accuracy.md.
#include <gtest/gtest.h>

#include <filesystem>

#include "verify/sweep.hpp"

namespace doublet::verify {
namespace {

std::vector<OpSweep> small_sweep(runner::Backend backend, Sabotage sabotage, const std::string& heatmaps = "") {
  SweepOptions o;
  o.ops = sweep_ops();
  o.backend = backend;
  o.grid_step = 16;
  o.sabotage = sabotage;
  o.heatmap_dir = heatmaps;
  std::string error;
  std::vector<OpSweep> s = sweep(o, &error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(s.size(), sweep_ops().size());
  return s;
}

class Sweep : public ::testing::TestWithParam<runner::Backend> {};

TEST_P(Sweep, EveryOpWithinItsBoundAndHeatmapsWritten) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                     ("doublet_sweep_test_" + std::string(runner::backend_name(GetParam())));
  const std::vector<OpSweep> s = small_sweep(GetParam(), Sabotage::None, dir.string());
  std::printf("%s", format_sweep(s).c_str());
  for (const OpSweep& o : s) {
    EXPECT_TRUE(o.within_bound) << o.op << ": " << o.in_range_max_err_u2 << " u^2 > " << o.bound_u2;
    EXPECT_GE(o.in_range_min_bits, 44.0) << o.op;
    EXPECT_GT(std::filesystem::file_size(o.heatmap), 100u) << o.heatmap;
  }
  std::filesystem::remove_all(dir);
}

TEST_P(Sweep, SabotageLeavesTheBound) {
  for (Sabotage sabotage : {Sabotage::DropGuard, Sabotage::DropLo})
    for (const OpSweep& o : small_sweep(GetParam(), sabotage))
      EXPECT_FALSE(o.within_bound) << o.op << " under " << to_string(sabotage) << " stayed within " << o.bound;
}

INSTANTIATE_TEST_SUITE_P(Backends, Sweep, ::testing::Values(runner::Backend::Vulkan, runner::Backend::Gles),
                         [](const auto& info) { return std::string(runner::backend_name(info.param)); });

}  // namespace
}  // namespace doublet::verify
