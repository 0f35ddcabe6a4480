// `doublet lower --mode exact`: a whole fp64 compute shader (literals, dvec2 arithmetic and
// swizzles, compound assignment, ++, comparisons, conversions, the common built-ins) lowered to
// ES 3.10 and run on lavapipe and Mesa GLES must store the same 64 bits per result as the
// original shader on native fp64 (lavapipe), for 2^18 input pairs of the exact_ops_test kinds.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "test_util.hpp"
#include "verify/sabotage.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kPairs = 1u << 18;
constexpr uint32_t kResults = 24;  // results per pair (r[kResults * i + k])

const char* kSource = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uvec4 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };
double twice_plus(double x, double y) { return x + x + y; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  uint o = 24u * i;
  double a = packDouble2x32(ab[i].xy), b = packDouble2x32(ab[i].zw);
  r[o + 0u] = unpackDouble2x32(a + b);
  r[o + 1u] = unpackDouble2x32(a - b * 3.0);
  r[o + 2u] = unpackDouble2x32(a * b / 0.1lf);
  r[o + 3u] = unpackDouble2x32(floor(a));
  r[o + 4u] = unpackDouble2x32(ceil(a));
  r[o + 5u] = unpackDouble2x32(trunc(a));
  r[o + 6u] = unpackDouble2x32(roundEven(a));
  r[o + 7u] = unpackDouble2x32(round(a));
  r[o + 8u] = unpackDouble2x32(fract(a));
  r[o + 9u] = unpackDouble2x32(mod(a, b));
  r[o + 10u] = unpackDouble2x32(min(a, b));
  r[o + 11u] = unpackDouble2x32(max(a, b));
  r[o + 12u] = unpackDouble2x32(sign(a));
  r[o + 13u] = unpackDouble2x32(-abs(a));
  r[o + 14u] = uvec2(floatBitsToUint(float(a)), 0u);
  r[o + 15u] = unpackDouble2x32(double(uintBitsToFloat(ab[i].y)));
  r[o + 16u] = uvec2(uint(a < b) | uint(a <= b) << 1 | uint(a > b) << 2 | uint(a >= b) << 3 | uint(a == b) << 4 |
                     uint(a != b) << 5, uint(isnan(a)) | uint(isinf(a)) << 1);
  dvec2 v = dvec2(a, b);
  v = v * v.yx + dvec2(1.0, -2.0);
  v.x += b;
  r[o + 17u] = unpackDouble2x32(v.x);
  r[o + 18u] = unpackDouble2x32(v.y);
  r[o + 19u] = uvec2(abs(a) < 2147483648.0 ? uint(int(a)) : 0u, 0u);
  r[o + 20u] = uvec2(a >= 0.0 && a < 4294967296.0 ? uint(a) : 0u, 0u);
  double c = sqrt(abs(b));
  c++;  // one addition: in a longer chain Mesa may reassociate the native side's constant
  r[o + 21u] = unpackDouble2x32(twice_plus(a, c));
  r[o + 22u] = unpackDouble2x32(double(int(ab[i].x)) + double(ab[i].w));
  r[o + 23u] = unpackDouble2x32(double(a < b) - clamp(a, -1.0, 1.0));
}
)";

const char* kResultNames[kResults] = {"a+b", "a-b*3", "a*b/0.1", "floor", "ceil", "trunc", "roundEven", "round",
                                      "fract", "mod", "min", "max", "sign", "-abs", "float(a)", "double(float)",
                                      "comparisons", "dvec2 x", "dvec2 y", "int(a)", "uint(a)", "call, sqrt, ++",
                                      "double(int)+double(uint)", "double(bool)-clamp"};

bool is_nan(uint64_t x) { return (x & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

// Native lavapipe is not IEEE for fp64 trunc, roundEven and round on some CPUs: on the AVX2
// machines of 2026-11-26 it returns x unchanged for 2^24 < |x| < 2^52 and +0 for x in (-1, 0)
// (docs/extremes.md, "Native fp64 is not the oracle for rounding to an integer"). There the host's
// IEEE 754 result decides: a difference is excused only where the lowered result is the host's and
// native's is not. GLSL leaves round's direction at halves to the implementation: either tie rule.
bool native_rounding_is_not_ieee(uint32_t result, uint64_t a, uint64_t got, uint64_t native) {
  if (result != 5 && result != 6 && result != 7) return false;
  const double x = std::bit_cast<double>(a);
  std::vector<double> ieee;
  if (result == 5) ieee = {std::trunc(x)};
  if (result == 6) ieee = {std::nearbyint(x)};  // the default rounding mode: ties to even
  if (result == 7) ieee = {std::nearbyint(x), std::round(x)};
  bool got_ieee = false, native_ieee = false;
  for (double r : ieee) {
    got_ieee = got_ieee || got == std::bit_cast<uint64_t>(r);
    native_ieee = native_ieee || native == std::bit_cast<uint64_t>(r);
  }
  return got_ieee && !native_ieee;
}

std::vector<uint64_t> make_pairs() {
  std::mt19937_64 rng(115);
  const uint64_t specials[] = {0, 1, 0x000FFFFFFFFFFFFFull, 0x0010000000000000ull, 0x7FEFFFFFFFFFFFFFull,
                               0x7FF0000000000000ull, 0x7FF8000000000000ull, 0x3FF0000000000000ull,
                               0x3FE0000000000000ull, 0x4004000000000000ull, 0x4330000000000000ull};
  std::vector<uint64_t> ab(2 * size_t(kPairs));
  for (auto& x : ab) {
    switch (rng() % 4) {
      case 0: x = rng(); break;
      case 1: x = ((1000 + rng() % 90) << 52) | (rng() >> 12); break;  // 2^-23 .. 2^66: integers and fractions
      case 2: x = ((1023 + rng() % 53) << 52) | ((rng() >> 12) & ~((1ull << (rng() % 53)) - 1)); break;  // halves
      default: x = specials[rng() % 11]; break;
    }
    if (rng() & 1) x |= 0x8000000000000000ull;
  }
  return ab;
}

Result lower_exact(const std::string& source, Target target = Target::Es310) {
  Options options;
  options.stage = Stage::Compute;
  options.target = target;
  options.mode = Mode::Exact;
  return lower(source, options);
}

std::vector<uint64_t> run(Backend backend, const std::string& glsl, const std::vector<uint64_t>& ab) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = {to_bytes(ab), std::vector<uint8_t>(size_t(kPairs) * kResults * 8)};
  job.groups_x = kPairs / 64;
  ComputeResult res = run_compute(backend, job);
  EXPECT_TRUE(res.ok) << backend_name(backend) << ": " << res.error;
  return res.ok ? from_bytes<uint64_t>(res.buffers[1]) : std::vector<uint64_t>{};
}

TEST(ExactLowering, WholeShaderBitIdenticalToNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  Options options;
  options.stage = Stage::Compute;
  options.target = Target::Es310;
  options.mode = Mode::Exact;
  Result lowered = lower(kSource, options);
  std::string diagnostics;
  for (const Diagnostic& d : lowered.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  ASSERT_TRUE(lowered.ok) << diagnostics;
  EXPECT_EQ(diagnostics, "");
  const std::string code = std::regex_replace(lowered.output, std::regex("//[^\n]*"), "");
  EXPECT_FALSE(std::regex_search(code, std::regex(R"(\b(double|dvec[234])\b)"))) << "a double survived";
  const std::vector<uint64_t> ab = make_pairs();
  const std::vector<uint64_t> native = run(Backend::Vulkan, kSource, ab);
  ASSERT_EQ(native.size(), size_t(kPairs) * kResults);
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const std::vector<uint64_t> got = run(backend, lowered.output, ab);
    ASSERT_EQ(got.size(), native.size());
    uint32_t total = 0, nan_payloads = 0, native_not_ieee = 0;
    for (uint32_t k = 0; k < kResults; ++k) {
      uint32_t differing = 0, first = 0;
      for (uint32_t i = 0; i < kPairs; ++i) {
        const uint64_t g = got[size_t(i) * kResults + k], n = native[size_t(i) * kResults + k];
        if (g == n) continue;
        if (native_rounding_is_not_ieee(k, ab[2 * size_t(i)], g, n)) {
          ++native_not_ieee;
          continue;
        }
        if (k != 14 && k != 16 && k != 19 && k != 20 && is_nan(g) && is_nan(n)) {
          ++nan_payloads;  // both NaN: which NaN operand native passes on depends on its instruction order
          continue;
        }
        if (differing++ == 0) first = i;
      }
      total += differing;
      if (differing)
        std::printf("[ exact ] %s %-26s %u of %u differ; first a=%016llx b=%016llx got %016llx want %016llx\n",
                    backend_name(backend), kResultNames[k], differing, kPairs, (unsigned long long)ab[2 * first],
                    (unsigned long long)ab[2 * first + 1], (unsigned long long)got[size_t(first) * kResults + k],
                    (unsigned long long)native[size_t(first) * kResults + k]);
    }
    std::cout << "[ exact ] lowered shader on " << backend_name(backend) << ": " << total << " of "
              << kPairs * kResults << " results differ from native fp64; " << nan_payloads
              << " NaN results carry another NaN's payload or sign; " << native_not_ieee
              << " trunc/round results are IEEE 754's where native's are not\n";
    EXPECT_EQ(total, 0u) << backend_name(backend);
  }
}

// The same comparison must see the arithmetic broken: ties rounded away from zero instead of to
// even, edited into the lowered text.
TEST(ExactLowering, SabotagedRoundingDiffers) {
  REQUIRE_BACKEND(Backend::Vulkan);
  Result lowered = lower_exact(kSource);
  ASSERT_TRUE(lowered.ok);
  std::string sabotaged = lowered.output;
  ASSERT_TRUE(::doublet::verify::apply_output_sabotage(::doublet::verify::Sabotage::TiesAway, &sabotaged));  // `verify --sabotage ties-away`'s edit
  const std::vector<uint64_t> ab = make_pairs();
  const std::vector<uint64_t> native = run(Backend::Vulkan, kSource, ab), got = run(Backend::Vulkan, sabotaged, ab);
  ASSERT_EQ(got.size(), native.size());
  uint32_t differing = 0;
  for (size_t i = 0; i < got.size(); ++i) differing += got[i] != native[i] && !(is_nan(got[i]) && is_nan(native[i]));
  std::cout << "[ exact ] lowered shader with ties away from zero: " << differing << " results differ\n";
  EXPECT_GT(differing, 0u);
}

// A vertex shader: double inputs arrive as uvec2 words (low, high: the raw bytes of a host double),
// the double output leaves as a flat uvec2; run in both drivers' vertex stage against the host's IEEE arithmetic.
TEST(ExactLowering, VertexStageWordsBitIdenticalToIeee) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const char* source = "#version 450\nin double a;\nin double b;\nflat out double r;\n"
                       "void main() { r = a * b + a / b; gl_Position = vec4(0.0); }\n";
  Options options;
  options.stage = Stage::Vertex;
  options.target = Target::Es300;
  options.mode = Mode::Exact;
  Result lowered = lower(source, options);
  ASSERT_TRUE(lowered.ok);
  ASSERT_EQ(lowered.manifest.variables.size(), 3u);
  EXPECT_EQ(lowered.manifest.variables[0].lowered_type, "uvec2");
  EXPECT_EQ(lowered.manifest.variables[0].encoding, "binary64-words");
  EXPECT_NE(lowered.output.find("flat out uvec2 r;"), std::string::npos) << lowered.output;
  constexpr uint32_t kCount = 4096;
  const std::vector<uint64_t> ab = make_pairs();
  GraphicsJob native_job, exact_job;
  native_job.glsl = source;
  exact_job.glsl = lowered.output;
  native_job.count = exact_job.count = kCount;
  for (int k = 0; k < 2; ++k) {
    const std::string name = k == 0 ? "a" : "b";
    std::vector<double>& values = native_job.inputs[name];
    std::vector<double>& words = exact_job.inputs[name];
    for (uint32_t i = 0; i < kCount; ++i) {
      const uint64_t w = ab[2 * i + k];
      values.push_back(bits<double>(w));
      words.push_back(double(w & 0xFFFFFFFFu));
      words.push_back(double(w >> 32));
    }
  }
  // The reference is the host's IEEE binary64 (two roundings, no fused multiply-add): native fp64 in
  // lavapipe's vertex stage differs from it on 257 of these 4096 (e.g. -max subnormal * DBL_MAX gives -0,
  // as if the subnormal operand were zero), which mode exact does not.
  std::vector<uint64_t> want(kCount);
  for (uint32_t i = 0; i < kCount; ++i) {
    volatile double a = bits<double>(ab[2 * i]), b = bits<double>(ab[2 * i + 1]);
    volatile double product = a * b, quotient = a / b;
    want[i] = bits<uint64_t>(double(product + quotient));
  }
  const GraphicsResult native = run_graphics(Backend::Vulkan, native_job);
  ASSERT_TRUE(native.ok) << native.error;
  uint32_t native_differing = 0;
  for (uint32_t i = 0; i < kCount; ++i) {
    const uint64_t n = bits<uint64_t>(native.outputs.at("r")[i]);
    native_differing += n != want[i] && !(is_nan(n) && is_nan(want[i]));
  }
  std::cout << "[ exact ] native fp64 vertex stage (lavapipe) vs host IEEE: " << native_differing << " of " << kCount
            << " differ\n";
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const GraphicsResult got = run_graphics(backend, exact_job);
    ASSERT_TRUE(got.ok) << backend_name(backend) << ": " << got.error;
    uint32_t differing = 0, nan_payloads = 0;
    for (uint32_t i = 0; i < kCount; ++i) {
      const std::vector<double>& r = got.outputs.at("r");
      const uint64_t have = (uint64_t(r[2 * i + 1]) << 32) | uint64_t(r[2 * i]);
      if (have == want[i]) continue;
      if (is_nan(have) && is_nan(want[i])) {
        ++nan_payloads;
      } else if (differing++ == 0) {
        std::printf("[ exact ] first: a=%016llx b=%016llx got %016llx want %016llx\n", (unsigned long long)ab[2 * i],
                    (unsigned long long)ab[2 * i + 1], (unsigned long long)have, (unsigned long long)want[i]);
      }
    }
    std::cout << "[ exact ] vertex stage on " << backend_name(backend) << " vs host IEEE: " << differing << " of "
              << kCount << " differ (" << nan_payloads << " NaN payloads apart)\n";
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
}

// OpenGL counts a vertex input's dvec3 as one location, so sources place the next one right after
// it (examples/scenes/orbit_step.vert); mode exact's second part (X_z) then goes past every
// declaration instead of onto the neighbour's location (glslang refused the lowered shader:
// "overlapping use of location 1", an internal error). Run: words in, IEEE result out, 0 differ.
TEST(ExactLowering, AdjacentDvec3InputsGetDistinctLocations) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const char* source = "#version 450\nlayout(location = 0) in dvec3 p;\nlayout(location = 1) in dvec3 v;\n"
                       "flat out dvec3 r;\nvoid main() { r = p + v * 3.0lf; gl_Position = vec4(0.0); }\n";
  Options options;
  options.stage = Stage::Vertex;
  options.target = Target::Es300;
  options.mode = Mode::Exact;
  Result lowered = lower(source, options);
  ASSERT_TRUE(lowered.ok) << (lowered.diagnostics.empty() ? "" : format_diagnostic(lowered.diagnostics[0]));
  EXPECT_NE(lowered.output.find("layout(location = 0) in uvec4 p_xy;"), std::string::npos) << lowered.output;
  EXPECT_NE(lowered.output.find("layout(location = 1) in uvec4 v_xy;"), std::string::npos) << lowered.output;
  EXPECT_NE(lowered.output.find("layout(location = 2) in uvec2 v_z;"), std::string::npos) << lowered.output;
  EXPECT_NE(lowered.output.find("layout(location = 3) in uvec2 p_z;"), std::string::npos) << lowered.output;
  constexpr uint32_t kCount = 1024;
  const std::vector<uint64_t> words = make_pairs();
  GraphicsJob job;
  job.glsl = lowered.output;
  job.count = kCount;
  std::vector<uint64_t> want(3 * kCount);
  auto feed = [&](const std::string& name, uint64_t w) {
    job.inputs[name].push_back(double(w & 0xFFFFFFFFu));
    job.inputs[name].push_back(double(w >> 32));
  };
  for (uint32_t i = 0; i < kCount; ++i)
    for (uint32_t c = 0; c < 3; ++c) {
      const uint64_t pw = words[(6 * i + c) % words.size()], vw = words[(6 * i + 3 + c) % words.size()];
      feed(c < 2 ? "p_xy" : "p_z", pw);
      feed(c < 2 ? "v_xy" : "v_z", vw);
      volatile double product = bits<double>(vw) * 3.0;
      want[3 * i + c] = bits<uint64_t>(double(bits<double>(pw) + product));
    }
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const GraphicsResult got = run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << backend_name(backend) << ": " << got.error;
    uint32_t differing = 0;
    for (uint32_t i = 0; i < kCount; ++i)
      for (uint32_t c = 0; c < 3; ++c) {
        const std::vector<double>& r = got.outputs.at(c < 2 ? "r_xy" : "r_z");
        const size_t at = c < 2 ? 4 * i + 2 * c : 2 * i;
        const uint64_t have = (uint64_t(r[at + 1]) << 32) | uint64_t(r[at]);
        differing += have != want[3 * i + c] && !(is_nan(have) && is_nan(want[3 * i + c]));
      }
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
}

// What mode exact refuses, each with a clear diagnostic (never an internal error).
TEST(ExactLowering, RefusalsAreDiagnosed) {
  auto first_error = [](const Result& r) {
    for (const Diagnostic& d : r.diagnostics)
      if (d.severity == Severity::Error) return format_diagnostic(d);
    return std::string("(no error)");
  };
  const char* plain = "#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { double x; };\n"
                      "void main() { x = x * 2.0; }\n";
  Options options;
  options.stage = Stage::Vertex;
  options.target = Target::Es100;
  options.mode = Mode::Exact;
  Result es100 = lower("#version 450\nin double a;\nvoid main() { gl_Position = vec4(float(a)); }\n", options);
  EXPECT_FALSE(es100.ok);
  EXPECT_NE(first_error(es100).find("--mode exact needs 32-bit integers"), std::string::npos) << first_error(es100);

  Result matrix = lower_exact("#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, row_major, binding = 0) buffer B { dmat2 m; };\n"
                              "void main() { m = m * m; }\n");
  EXPECT_FALSE(matrix.ok);
  EXPECT_NE(first_error(matrix).find(":3:"), std::string::npos) << first_error(matrix);
  EXPECT_NE(first_error(matrix).find("a double matrix in an interface ('m') with layout(row_major) is not supported by --mode exact"),
            std::string::npos)
      << first_error(matrix);

  Result pragma = lower_exact(std::string("#version 450\n#pragma doublet mode(fp32)\n") + (plain + 13));
  EXPECT_FALSE(pragma.ok);
  EXPECT_NE(first_error(pragma).find("<stdin>:2:"), std::string::npos) << first_error(pragma);

  Options per_name;
  per_name.stage = Stage::Compute;
  per_name.target = Target::Es310;
  per_name.mode = Mode::Df64;
  per_name.mode_for = {{"main", Mode::Exact}};
  Result named = lower(plain, per_name);
  EXPECT_FALSE(named.ok);
  // Exact per function exists (docs/modes.md, "Exact functions"), but not for main: the whole shader is --mode exact.
  EXPECT_NE(first_error(named).find("main cannot be exact alone: use --mode exact for the whole shader"), std::string::npos)
      << first_error(named);

  Result unsupported = lower_exact("#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { double x; };\n"
                                   "void main() { dvec2 v = dvec2(x); x = modf(x, v.y) + v.x; }\n");
  EXPECT_FALSE(unsupported.ok);
  EXPECT_NE(first_error(unsupported).find("<stdin>:4:"), std::string::npos) << first_error(unsupported);
  EXPECT_EQ(first_error(unsupported).find("internal error"), std::string::npos) << first_error(unsupported);

  Result ok = lower_exact(plain);
  EXPECT_TRUE(ok.ok) << first_error(ok);
}

}  // namespace
}  // namespace doublet::runner::test
