// Native fp64 on lavapipe: the reference the lowered float-float code gets compared with.
#include <cmath>
#include <random>

#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kN = 1u << 15;

// Distance in units in the last place between two finite doubles of any sign.
uint64_t ulp_distance(double x, double y) {
  auto ordered = [](double d) {
    const int64_t i = bits<int64_t>(d);
    return i < 0 ? INT64_MIN - i : i;  // maps the float line monotonically onto int64
  };
  const int64_t a = ordered(x), b = ordered(y);
  return a > b ? uint64_t(a) - uint64_t(b) : uint64_t(b) - uint64_t(a);
}

struct OpStats {
  uint32_t mismatches = 0;
  uint64_t max_ulp = 0;
  double worst_input = 0;
};

TEST(VulkanFp64, NativeDoubleOpsAgainstHost) {
  REQUIRE_BACKEND(Backend::Vulkan);
  // Full 52-bit random significands, exponents in [-100, 100]: no overflow, no subnormal results.
  std::mt19937_64 rng(7);
  std::vector<double> ab(2 * kN);
  for (double& x : ab) {
    const double m = 1.0 + double(rng() >> 12) * 0x1p-52;
    x = std::ldexp(m, int(rng() % 201) - 100) * (rng() & 1 ? -1.0 : 1.0);
  }
  ComputeJob job;
  job.glsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec2 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { double r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = ab[i].x, b = ab[i].y;
  r[4u * i + 0u] = a + b;
  r[4u * i + 1u] = a * b;
  r[4u * i + 2u] = a / b;
  r[4u * i + 3u] = sqrt(abs(a));
}
)";
  job.buffers = {to_bytes(ab), std::vector<uint8_t>(kN * 4 * sizeof(double))};
  job.groups_x = kN / 64;
  RUN_OK(res, Backend::Vulkan, job);
  const std::vector<double> r = from_bytes<double>(res.buffers[1]);

  const char* names[4] = {"add", "mul", "div", "sqrt"};
  OpStats stats[4];
  for (uint32_t i = 0; i < kN; ++i) {
    const double a = ab[2 * i], b = ab[2 * i + 1];
    const double want[4] = {a + b, a * b, a / b, std::sqrt(std::fabs(a))};
    for (int op = 0; op < 4; ++op) {
      const double got = r[4 * i + op];
      if (bits<uint64_t>(got) == bits<uint64_t>(want[op])) continue;
      OpStats& s = stats[op];
      ++s.mismatches;
      if (uint64_t u = ulp_distance(got, want[op]); u > s.max_ulp) {
        s.max_ulp = u;
        s.worst_input = op == 3 ? a : b;
      }
    }
  }
  for (int op = 0; op < 4; ++op) {
    std::cout << "[ fp64 ] " << res.device << " " << names[op] << ": " << stats[op].mismatches << "/" << kN
              << " differ from correctly rounded, max " << stats[op].max_ulp << " ulp\n";
    RecordProperty(std::string("fp64_") + names[op] + "_mismatches", int(stats[op].mismatches));
  }
  EXPECT_EQ(stats[0].mismatches, 0u) << "double add must be correctly rounded";
  EXPECT_EQ(stats[1].mismatches, 0u) << "double mul must be correctly rounded";
  // Measured on Mesa 22.3.6 lavapipe (LLVM 15): div and sqrt are correctly rounded too. The lowered
  // code is compared with this native result, so a driver that stops rounding them correctly must
  // be noticed here rather than show up as a mystery in the numeric tests.
  EXPECT_EQ(stats[2].mismatches, 0u) << "double div no longer correctly rounded: max " << stats[2].max_ulp << " ulp";
  EXPECT_EQ(stats[3].mismatches, 0u) << "double sqrt no longer correctly rounded: max " << stats[3].max_ulp << " ulp";
}

}  // namespace
}  // namespace doublet::runner::test
