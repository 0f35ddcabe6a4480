// Mode exact's shared call sites (src/lower/share_exact_calls.cpp): a shader whose runs of
// statements call the same operations many times (a pure user function twice per step, dvec3 and
// double products and sums, which share one site through ex_each_mul, a loop body, the argument of
// a function that writes the buffer, which ends a run) becomes loops
// that execute one call per iteration. Lowered
// to ES 3.10 and run on lavapipe and Mesa GLES, it must store the same 64 bits per result as the
// original shader on native fp64 (lavapipe; `precise` keeps native's products uncontracted), and a
// loop cut one iteration short must be seen.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kInvocations = 1u << 16;
constexpr uint32_t kInputs = 4, kResults = 8;

const char* kSource = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uvec2 x[]; };
layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };
double cube(double t) { precise double c = t * t * t; return c; }
void store(uint k, double value) { r[k] = unpackDouble2x32(value); }
dvec3 pull(dvec3 p, double gm) {
  precise double d = length(p);
  precise dvec3 g = -gm * p / (d * d * d);
  return g;
}
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = packDouble2x32(x[4u * i]), b = packDouble2x32(x[4u * i + 1u]);
  double c = packDouble2x32(x[4u * i + 2u]), e = packDouble2x32(x[4u * i + 3u]);
  precise dvec3 p = dvec3(a, b, c);
  precise dvec3 v = dvec3(b, c, e);
  precise dvec3 acc = pull(p, 3.986004418e14lf);
  precise dvec3 p2 = p + v * e + acc * (0.5lf * e * e);
  precise dvec3 v2 = v + (acc + pull(p2, 3.986004418e14lf)) * (0.5lf * e);
  precise double s = cube(a) + cube(b) * c;
  precise double q = a > b ? a * b : b * c;
  for (int k = 0; k < 3; ++k) {
    s = s * a + b;
    q = q * b + s * c;
  }
  uint o = 8u * i;
  r[o] = unpackDouble2x32(p2.x);
  r[o + 1u] = unpackDouble2x32(p2.y);
  r[o + 2u] = unpackDouble2x32(p2.z);
  r[o + 3u] = unpackDouble2x32(v2.x);
  r[o + 4u] = unpackDouble2x32(v2.y);
  r[o + 5u] = unpackDouble2x32(v2.z);
  precise double t = s * c;
  precise double u = t * q + s * a;
  store(o + 6u, u * b);
  r[o + 7u] = unpackDouble2x32(q);
}
)";

bool is_nan(uint64_t x) { return (x & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

// Doubles of either sign between 2^-30 and 2^30 (products and cubes stay finite and normal), and
// now and then a zero, an infinity or a NaN.
std::vector<uint64_t> make_inputs() {
  std::mt19937_64 rng(2312);
  const uint64_t specials[] = {0, 0x7FF0000000000000ull, 0x7FF8000000000000ull, 0x3FF0000000000000ull};
  std::vector<uint64_t> in(size_t(kInvocations) * kInputs);
  for (auto& x : in) {
    x = rng() % 64 == 0 ? specials[rng() % 4] : ((993 + rng() % 61) << 52) | (rng() >> 12);
    if (rng() & 1) x |= 0x8000000000000000ull;
  }
  return in;
}

std::vector<uint64_t> run(Backend backend, const std::string& glsl, const std::vector<uint64_t>& in) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = {to_bytes(in), std::vector<uint8_t>(size_t(kInvocations) * kResults * 8)};
  job.groups_x = kInvocations / 64;
  ComputeResult res = run_compute(backend, job);
  EXPECT_TRUE(res.ok) << backend_name(backend) << ": " << res.error;
  return res.ok ? from_bytes<uint64_t>(res.buffers[1]) : std::vector<uint64_t>{};
}

// Results that differ from native's bits (both NaN excused: which NaN operand native passes on
// depends on its instruction order).
uint32_t differing(const std::vector<uint64_t>& got, const std::vector<uint64_t>& native) {
  uint32_t n = 0;
  for (size_t k = 0; k < got.size(); ++k) n += got[k] != native[k] && !(is_nan(got[k]) && is_nan(native[k]));
  return n;
}

Result lowered_source() {
  Options options;
  options.stage = Stage::Compute;
  options.target = Target::Es310;
  options.mode = Mode::Exact;
  return lower(kSource, options);
}

TEST(ExactSharedCalls, SharedCallSitesBitIdenticalToNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const Result lowered = lowered_source();
  ASSERT_TRUE(lowered.ok);
  // The case this test is for: pull() and cube() each called from one shared site, and loops over runs.
  const std::string& text = lowered.output;
  const std::regex loop(R"(for \(int ex_pc\d+ = 0)");
  const auto loops = std::distance(std::sregex_iterator(text.begin(), text.end(), loop), std::sregex_iterator());
  EXPECT_GE(loops, 3) << text;
  EXPECT_NE(text.find("= pull(ex_k"), std::string::npos) << text;
  EXPECT_NE(text.find("= cube(ex_k"), std::string::npos) << text;
  EXPECT_NE(text.find("= ex_each_mul(ex_k"), std::string::npos) << text;  // double and dvec3 products: one site
  // store() writes the buffer: its argument's product is the run's last call, the call follows the loop.
  EXPECT_TRUE(std::regex_search(text, std::regex(R"(\n *store\(o \+ 6u, ex_c\d+_\d+\);)"))) << text;
  const std::vector<uint64_t> in = make_inputs();
  const std::vector<uint64_t> native = run(Backend::Vulkan, kSource, in);
  ASSERT_EQ(native.size(), size_t(kInvocations) * kResults);
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const std::vector<uint64_t> got = run(backend, text, in);
    ASSERT_EQ(got.size(), native.size());
    const uint32_t n = differing(got, native);
    std::printf("[ exact ] shared call sites on %s: %u of %zu results differ from native fp64\n", backend_name(backend), n,
                native.size());
    EXPECT_EQ(n, 0u) << backend_name(backend);
  }
}

// The comparison sees a shared loop that stops one call early (its last call's result is then
// another call's, or nothing).
TEST(ExactSharedCalls, LoopCutShortDiffers) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const Result lowered = lowered_source();
  ASSERT_TRUE(lowered.ok);
  std::smatch m;
  const std::regex bound(R"(ex_pc(\d+) < (\d+);)");
  ASSERT_TRUE(std::regex_search(lowered.output, m, bound)) << lowered.output;
  std::string sabotaged = lowered.output;
  sabotaged.replace(size_t(m.position(0)), size_t(m.length(0)),
                    "ex_pc" + m[1].str() + " < " + std::to_string(std::stoi(m[2].str()) - 1) + ";");
  const std::vector<uint64_t> in = make_inputs();
  const std::vector<uint64_t> native = run(Backend::Vulkan, kSource, in), got = run(Backend::Vulkan, sabotaged, in);
  ASSERT_EQ(got.size(), native.size());
  const uint32_t n = differing(got, native);
  std::printf("[ exact ] a shared loop cut one call short: %u results differ\n", n);
  EXPECT_GT(n, 0u);
}

}  // namespace
}  // namespace doublet::runner::test
