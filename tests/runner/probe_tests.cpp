// The driver probes of docs/numerics.md#measured-driver-facts as assertions: what Mesa's optimizers
// do to Knuth's TwoSum.
#include <cmath>
#include <random>

#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kPairs = 4096;

// Pairs whose TwoSum error term is mostly non-zero: |b| = |a|·2^-k, k in [0, 30), random signs.
std::vector<float> make_pairs() {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> mant(1.0f, 2.0f);
  std::vector<float> ab(2 * kPairs);
  for (uint32_t i = 0; i < kPairs; ++i) {
    const float a = std::ldexp(mant(rng), int(rng() % 40) - 20) * (rng() & 1 ? -1.0f : 1.0f);
    const float b = std::ldexp(mant(rng), int(std::ilogb(a)) - int(rng() % 30)) * (rng() & 1 ? -1.0f : 1.0f);
    ab[2 * i] = a;
    ab[2 * i + 1] = b;
  }
  return ab;
}

struct TwoSum {
  float s, e;
};
TwoSum host_two_sum(float a, float b) {  // plain IEEE float arithmetic on the host (SSE, no fast-math)
  const float s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// Runs `body` (which sets s and e from a and b) over all pairs; returns (s, e) per pair.
std::vector<float> run_two_sum(Backend backend, const std::string& header, const std::string& body,
                               std::string* device) {
  ComputeJob job;
  job.glsl = header + R"(
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec2 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { vec2 se[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  float a = ab[i].x, b = ab[i].y;
)" + body + R"(
  se[i] = vec2(s, e);
}
)";
  job.buffers = {to_bytes(make_pairs()), std::vector<uint8_t>(kPairs * 8)};
  job.groups_x = kPairs / 64;
  ComputeResult r = run_compute(backend, job);
  EXPECT_TRUE(r.ok) << backend_name(backend) << ": " << r.error;
  *device = r.device;
  return r.ok ? from_bytes<float>(r.buffers[1]) : std::vector<float>();
}

// Counts pairs whose driver result differs bitwise from the host TwoSum; prints the first few.
int count_inexact(const std::vector<float>& se) {
  const std::vector<float> ab = make_pairs();
  int bad = 0;
  for (uint32_t i = 0; i < kPairs; ++i) {
    const TwoSum want = host_two_sum(ab[2 * i], ab[2 * i + 1]);
    if (bits<uint32_t>(se[2 * i]) != bits<uint32_t>(want.s) || bits<uint32_t>(se[2 * i + 1]) != bits<uint32_t>(want.e)) {
      if (++bad <= 3)
        ADD_FAILURE() << std::hexfloat << "a=" << ab[2 * i] << " b=" << ab[2 * i + 1] << ": got s=" << se[2 * i]
                      << " e=" << se[2 * i + 1] << ", host s=" << want.s << " e=" << want.e;
    }
  }
  return bad;
}

const char* kUnprotected = R"(
  float s = a + b;
  float bb = s - a;
  float e = (a - (s - bb)) + (b - bb);)";

// Every step's result plus a uniform the host never sets (GL initialises it to 0).
const char* kZeroGuard = R"(
  float s = (a + b) + g;
  float bb = (s - a) + g;
  float t = (s - bb) + g;
  float u = (a - t) + g;
  float v = (b - bb) + g;
  float e = (u + v) + g;)";

const char* kPrecise = R"(
  precise float s = a + b;
  precise float bb = s - a;
  precise float e = (a - (s - bb)) + (b - bb);)";

class ProbeTest : public ::testing::TestWithParam<Backend> {};

TEST(ProbeInputs, HostErrorTermsAreMostlyNonZero) {
  const std::vector<float> ab = make_pairs();
  uint32_t nonzero = 0;
  for (uint32_t i = 0; i < kPairs; ++i) nonzero += host_two_sum(ab[2 * i], ab[2 * i + 1]).e != 0.0f;
  EXPECT_GT(nonzero, kPairs * 3 / 4) << "inputs too easy: an all-zero e would prove nothing";
}

// The hazard: without protection Mesa's inexact algebra folds e to 0; float-float becomes float.
TEST_P(ProbeTest, UnprotectedTwoSumErrorTermIsDeleted) {
  REQUIRE_BACKEND(GetParam());
  std::string device;
  std::vector<float> se = run_two_sum(GetParam(), "#version 310 es", kUnprotected, &device);
  ASSERT_EQ(se.size(), 2 * kPairs);
  const std::vector<float> ab = make_pairs();
  uint32_t zero = 0, s_exact = 0;
  for (uint32_t i = 0; i < kPairs; ++i) {
    zero += se[2 * i + 1] == 0.0f;
    s_exact += se[2 * i] == ab[2 * i] + ab[2 * i + 1];
  }
  std::cout << "[ probe ] " << device << ": unprotected TwoSum e==0 for " << zero << "/" << kPairs << "\n";
  EXPECT_EQ(s_exact, kPairs);
  EXPECT_EQ(zero, kPairs) << "the driver no longer deletes the unprotected TwoSum error term: update docs/numerics.md#measured-driver-facts";
}

TEST_P(ProbeTest, ZeroUniformGuardKeepsTwoSumExact) {
  REQUIRE_BACKEND(GetParam());
  std::string device;
  std::vector<float> se =
      run_two_sum(GetParam(), "#version 310 es\nuniform float g;", kZeroGuard, &device);
  ASSERT_EQ(se.size(), 2 * kPairs);
  EXPECT_EQ(count_inexact(se), 0) << device;
}

TEST_P(ProbeTest, PreciseKeepsTwoSumExact) {
  REQUIRE_BACKEND(GetParam());
  std::string device;
  std::vector<float> se = run_two_sum(GetParam(), "#version 320 es", kPrecise, &device);
  ASSERT_EQ(se.size(), 2 * kPairs);
  EXPECT_EQ(count_inexact(se), 0) << device;
}

INSTANTIATE_TEST_SUITE_P(Backends, ProbeTest, ::testing::Values(Backend::Vulkan, Backend::Gles), backend_param_name);

}  // namespace
}  // namespace doublet::runner::test
