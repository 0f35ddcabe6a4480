// Mode `exact` (rules/exact.glsl): every operation must give the same 64 bits as native fp64 on
// lavapipe, on lavapipe and on Mesa GLES (llvmpipe), for 2^20 inputs per operation: random bit
// patterns, an exponent grid around the subnormal/normal/overflow boundaries, short significands
// (exact ties for rounding) and every special class (±0, ±subnormal min/max, ±normal min/max,
// ±Inf, NaN). The native run is itself checked against the host's IEEE arithmetic.
// Sabotages (no ties-to-even; no sticky bit) must make the count of differing results nonzero.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "rules/rule_library.hpp"
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kCount = 1u << 20;  // inputs per operation

struct Op {
  const char* name;
  int arity;
  const char* exact_expr;   // over uvec2 a, b (rules/exact.glsl)
  const char* native_expr;  // over double a, b
  std::function<double(double, double)> host;
};

const std::vector<Op>& ops() {
  static const std::vector<Op> list = {
      {"add", 2, "ex_add_bits(a, b)", "a + b", [](double a, double b) { return a + b; }},
      {"sub", 2, "ex_sub_bits(a, b)", "a - b", [](double a, double b) { return a - b; }},
      {"mul", 2, "ex_mul_bits(a, b)", "a * b", [](double a, double b) { return a * b; }},
      {"div", 2, "ex_div_bits(a, b)", "a / b", [](double a, double b) { return a / b; }},
      {"sqrt", 1, "ex_sqrt_bits(a)", "sqrt(a)", [](double a, double) { return std::sqrt(a); }},
  };
  return list;
}

// The special classes every operation must meet, each with both signs.
std::vector<uint64_t> special_patterns() {
  const uint64_t mags[] = {
      0,                      // zero
      1,                      // smallest subnormal
      0x000FFFFFFFFFFFFFull,  // largest subnormal
      0x0010000000000000ull,  // smallest normal
      0x7FEFFFFFFFFFFFFFull,  // largest normal
      0x7FF0000000000000ull,  // infinity
      0x7FF8000000000000ull,  // quiet NaN
      0x7FF0000000000001ull,  // signalling NaN
      0x3FF0000000000000ull,  // 1
      0x0008000000000000ull,  // subnormal 2^-1023
      0x3CA0000000000000ull,  // 2^-53
  };
  std::vector<uint64_t> out;
  for (uint64_t m : mags) {
    out.push_back(m);
    out.push_back(m | 0x8000000000000000ull);
  }
  return out;
}

// Input pairs (a, b) as bit patterns; the same for every operation.
std::vector<uint64_t> make_inputs() {
  std::mt19937_64 rng(20261124);
  const std::vector<uint64_t> specials = special_patterns();
  auto random_sign = [&](uint64_t m) { return (rng() & 1) ? m | 0x8000000000000000ull : m; };
  // Exponent field near a boundary: 0-3 (subnormal/min normal), 1020-1026 (around 1), 2043-2047.
  auto grid_exponent = [&]() -> uint64_t {
    switch (rng() % 4) {
      case 0: return rng() % 4;
      case 1: return 1020 + rng() % 7;
      case 2: return 2043 + rng() % 5;
      default: return rng() % 2048;
    }
  };
  std::vector<uint64_t> ab(2 * size_t(kCount));
  for (uint32_t i = 0; i < kCount; ++i) {
    uint64_t a = 0, b = 0;
    switch (i % 6) {
      case 0:  // random bit patterns
        a = rng(), b = rng();
        break;
      case 1:  // exponent grid with random significands
        a = random_sign((grid_exponent() << 52) | (rng() >> 12));
        b = random_sign((grid_exponent() << 52) | (rng() >> 12));
        break;
      case 2: {  // short significands: exact products and sums land on ties
        const uint64_t ea = rng() % 2047, eb = (ea + 2047 - 60 + rng() % 120) % 2047;
        a = random_sign((ea << 52) | ((rng() >> 34) << 22));
        b = random_sign((eb << 52) | ((rng() >> 38) << 26));
        break;
      }
      case 3: {  // nearby magnitudes: cancellation, results near the subnormal range
        const uint64_t e = rng() % 60;
        a = random_sign((e << 52) | (rng() >> 12));
        b = random_sign(((e + rng() % 3) << 52) | (rng() >> 12));
        break;
      }
      case 4: {  // a / 2^j or a * 2^-j exactly halfway between two subnormals (a's significand odd)
        const uint64_t j = 1 + rng() % 60;
        a = random_sign((j << 52) | (rng() >> 12) | 1);
        b = random_sign((rng() & 1) ? (j + 1023) << 52 : (1023 - j) << 52);
        break;
      }
      default:  // a special value against anything
        a = specials[rng() % specials.size()];
        b = (rng() & 1) ? specials[rng() % specials.size()] : rng();
        if (rng() & 1) std::swap(a, b);
        break;
    }
    ab[2 * i] = a, ab[2 * i + 1] = b;
  }
  return ab;
}

// integer_functions: the "@variant integer-functions" chunks (umulExtended, findMSB), as es310+ gets.
std::string exact_library(const std::vector<std::string>& names, bool integer_functions = false) {
  rules::EmitRequest req;
  for (const auto& n : names) req.used.push_back({n, 1});
  req.guard = rules::GuardStyle::None;
  req.es_version = 310;
  req.integer_functions = integer_functions;
  rules::EmitResult r = rules::RuleLibrary::builtin().emit(req);
  EXPECT_TRUE(r.ok) << r.error;
  return r.text;
}

const char* kHeader = R"(layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uvec4 ab[]; };
layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };
)";

std::string exact_shader(const Op& op, const std::string& library) {
  return std::string("#version 310 es\n") + kHeader + library +
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  uvec2 a = ab[i].xy, b = ab[i].zw;\n  r[i] = " +
         op.exact_expr + ";\n}\n";
}

std::string native_shader(const Op& op) {
  return std::string("#version 450\n") + kHeader +
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n"
         "  double a = packDouble2x32(ab[i].xy), b = packDouble2x32(ab[i].zw);\n"
         "  r[i] = unpackDouble2x32(" + op.native_expr + ");\n}\n";
}

std::vector<uint64_t> run(Backend backend, const std::string& glsl, const std::vector<uint64_t>& ab) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = {to_bytes(ab), std::vector<uint8_t>(size_t(kCount) * 8)};
  job.groups_x = kCount / 64;
  ComputeResult res = run_compute(backend, job);
  EXPECT_TRUE(res.ok) << backend_name(backend) << ": " << res.error;
  if (!res.ok) return {};
  return from_bytes<uint64_t>(res.buffers[1]);
}

bool is_nan(uint64_t x) { return (x & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

struct Diff {
  uint32_t differing = 0;     // results whose 64 bits differ
  uint32_t nan_payload = 0;   // of which both are NaN (payload or sign of the NaN differs)
  uint64_t first_a = 0, first_b = 0, first_got = 0, first_want = 0;
};

Diff compare(const std::vector<uint64_t>& got, const std::vector<uint64_t>& want, const std::vector<uint64_t>& ab) {
  Diff d;
  for (uint32_t i = 0; i < kCount && i < got.size() && i < want.size(); ++i) {
    if (got[i] == want[i]) continue;
    if (d.differing++ == 0) d.first_a = ab[2 * i], d.first_b = ab[2 * i + 1], d.first_got = got[i], d.first_want = want[i];
    if (is_nan(got[i]) && is_nan(want[i])) ++d.nan_payload;
  }
  return d;
}

std::string describe(const Diff& d) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%u differ (%u NaN vs NaN); first a=%016llx b=%016llx got %016llx want %016llx",
                d.differing, d.nan_payload, (unsigned long long)d.first_a, (unsigned long long)d.first_b,
                (unsigned long long)d.first_got, (unsigned long long)d.first_want);
  return buf;
}

std::vector<uint64_t> host_results(const Op& op, const std::vector<uint64_t>& ab) {
  std::vector<uint64_t> out(kCount);
  for (uint32_t i = 0; i < kCount; ++i)
    out[i] = std::bit_cast<uint64_t>(op.host(std::bit_cast<double>(ab[2 * i]), std::bit_cast<double>(ab[2 * i + 1])));
  return out;
}

class ExactOps : public ::testing::TestWithParam<int> {};

TEST_P(ExactOps, BitIdenticalToNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const Op& op = ops()[GetParam()];
  static const std::vector<uint64_t> ab = make_inputs();
  const std::vector<uint64_t> native = run(Backend::Vulkan, native_shader(op), ab);
  ASSERT_EQ(native.size(), kCount);
  const Diff native_vs_host = compare(native, host_results(op, ab), ab);
  std::cout << "[ exact ] " << op.name << ": native lavapipe vs host IEEE: " << describe(native_vs_host) << "\n";
  // The ES 3.00 functions, and the integer-functions variants es310/es320/glsl450 get.
  for (bool integer_functions : {false, true}) {
    const std::string library = exact_library({std::string("ex_") + op.name + "_bits"}, integer_functions);
    const std::string path = integer_functions ? " (integer functions)" : "";
    for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
      const Diff d = compare(run(backend, exact_shader(op, library), ab), native, ab);
      std::cout << "[ exact ] " << op.name << path << " on " << backend_name(backend) << " vs native: " << describe(d) << "\n";
      RecordProperty(std::string(op.name) + (integer_functions ? "_intfn_" : "_") + backend_name(backend) + "_differing",
                     int(d.differing));
      EXPECT_EQ(d.differing, 0u) << op.name << path << " on " << backend_name(backend) << ": " << describe(d);
    }
  }
}

// A sabotage is a text replacement in the emitted library; each must change some results of
// every operation it concerns (so the inputs above really exercise ties, sticky bits and
// subnormal results).
struct Sabotage {
  const char* name;
  std::vector<std::pair<std::string, std::string>> edits;
  std::vector<const char*> ops;
  bool integer_functions = false;  // sabotage the "@variant integer-functions" chunks
};

TEST(ExactSabotage, EachSabotageMakesResultsDiffer) {
  REQUIRE_BACKEND(Backend::Vulkan);
  static const std::vector<uint64_t> ab = make_inputs();
  const std::vector<Sabotage> sabotages = {
      {"ties-away (no ties-to-even)", {{"uint tie = roundBits == 0x200u ? 0xFFFFFFFEu : 0xFFFFFFFFu;", "uint tie = 0xFFFFFFFFu;"}}, {"add", "sub", "mul", "div"}},
      {"no sticky bit",
       {{"uint jam = lost ? 1u : 0u;", "uint jam = 0u;"},
        {"uint sticky = any(bvec2(p00.x != 0u, (w1 & 0x3FFu) != 0u)) ? 1u : 0u;", "uint sticky = 0u;"},
        {"uint remainderBit = (qr.z | qr.w) != 0u ? 1u : 0u;", "uint remainderBit = 0u;"},
        {"uint rootRemainderBit = (qr.z | qr.w) != 0u ? 1u : 0u;", "uint rootRemainderBit = 0u;"}},
       {"add", "sub", "mul", "div", "sqrt"}},
      {"flush subnormal results to zero", {{"uvec2 t = ex_shr_jam64(sig, shift);", "uvec2 t = ex_sel64(tiny, uvec2(0u), sig);"}}, {"add", "sub", "mul", "div"}},
      // The square root's digits are float estimates: taking them unchecked must show.
      {"root digits not corrected upwards", {{"bool digitTooSmall = ex_lt64(ex_shl64(q, 1), r);", "bool digitTooSmall = false;"}}, {"sqrt"}},
      {"root digits not corrected downwards", {{"bool digitTooLarge = r.y >= 0x80000000u;", "bool digitTooLarge = false;"}}, {"sqrt"}},
      {"first root digits not corrected downwards", {{"bool rootTooLarge = rem.y >= 0x80000000u;", "bool rootTooLarge = false;"}}, {"sqrt"}},
      {"quotient digits not corrected upwards", {{"bool quotientTooSmall = !ex_lt64(r, mb);", "bool quotientTooSmall = false;"}}, {"div"}},
      {"quotient digits not corrected downwards", {{"bool quotientTooLarge = r.y >= 0x80000000u;", "bool quotientTooLarge = false;"}}, {"div"}},
      {"umulExtended's high word dropped", {{"return uvec2(lo, hi);", "return uvec2(lo, 0u);"}}, {"mul", "sqrt"}, true},
      {"findMSB off by one", {{"return 31 - findMSB(x);", "return 30 - findMSB(x);"}}, {"add", "mul", "sqrt"}, true},
  };
  std::map<std::string, std::vector<uint64_t>> native;  // per operation: the same for every sabotage
  for (const Sabotage& sab : sabotages) {
    for (const char* name : sab.ops) {
      const Op& op = *std::find_if(ops().begin(), ops().end(), [&](const Op& o) { return std::string(o.name) == name; });
      std::string library = exact_library({std::string("ex_") + op.name + "_bits"}, sab.integer_functions);
      for (const auto& [from, to] : sab.edits) {
        const size_t at = library.find(from);
        if (at != std::string::npos) library.replace(at, from.size(), to);
      }
      if (sab.integer_functions || std::string(sab.name).find("digits") != std::string::npos)  // its text must be there
        EXPECT_NE(library.find(sab.edits[0].second), std::string::npos) << sab.name << " did not apply to " << op.name;
      if (!native.count(name)) native[name] = run(Backend::Vulkan, native_shader(op), ab);
      const Diff d = compare(run(Backend::Vulkan, exact_shader(op, library), ab), native[name], ab);
      std::cout << "[ exact ] sabotage '" << sab.name << "', " << op.name << ": " << d.differing << " of " << kCount
                << " differ\n";
      EXPECT_GT(d.differing, 0u) << sab.name << " left " << op.name << " bit-identical";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Ops, ExactOps, ::testing::Range(0, int(ops().size())),
                         [](const ::testing::TestParamInfo<int>& info) { return std::string(ops()[info.param].name); });

}  // namespace
}  // namespace doublet::runner::test
