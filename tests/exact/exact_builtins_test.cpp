// Mode exact's common and geometric built-ins (mix, step, smoothstep, inversesqrt, ldexp, frexp,
// modf, dot, length, distance, normalize, cross, faceforward, reflect, refract) bit for bit
// against native fp64 on lavapipe: a shader written with doubles is run natively and, lowered
// with --mode exact --target es310, on lavapipe and on Mesa GLES, for 2^20 inputs per built-in
// (moderate magnitudes, random patterns, the exponent grid, short significands, every special
// class). Native's order of operations, its NaN choices and its quirks (ldexp's two products,
// frexp of subnormals) were measured with candidate orders and are what rules/exact.glsl repeats.
// Sabotages (edits of the lowered text) must make results differ.
#include <gtest/gtest.h>

#include <iostream>
#include <regex>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "exact_harness.hpp"

namespace doublet::runner::test::exact {
namespace {

constexpr uint32_t kInvocations = 1u << 20;

// One shader: `doubles` inputs d[k], `ints` inputs n[k], and one output per entry of `results`
// (a double expression, or an int one when it starts with "int:").
struct Group {
  const char* name;
  int doubles, ints;
  std::vector<std::pair<const char*, std::string>> results;  // {name, GLSL expression}
  std::string prelude = "";  // statements before the results (out arguments)
};

const std::vector<Group>& groups() {
  static const std::vector<Group> list = {
      {"common", 3, 1,
       {{"mix", "mix(d[0], d[1], d[2])"},
        {"mix(bool)", "mix(d[0], d[1], (n[0] & 1) != 0)"},
        {"step", "step(d[0], d[1])"},
        {"smoothstep", "smoothstep(d[0], d[1], d[2])"},
        {"inversesqrt", "inversesqrt(d[0])"}}},
      {"common dvec3, scalar operand", 7, 0,
       {{"mix dvec3 .x", "mix(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]), d[6]).x"},
        {"mix dvec3 .z", "mix(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]), d[6]).z"},
        {"step dvec3 .y", "step(d[6], dvec3(d[0], d[1], d[2])).y"},
        {"smoothstep dvec3 .x", "smoothstep(d[3], d[4], dvec3(d[0], d[1], d[2])).x"},
        {"smoothstep dvec3 .z", "smoothstep(d[3], d[4], dvec3(d[0], d[1], d[2])).z"},
        {"mix(bvec3) .y", "mix(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]), lessThan(dvec3(d[0], d[1], d[2]), dvec3(d[6]))).y"}}},
      {"ldexp, frexp, modf", 2, 2,
       {{"ldexp", "ldexp(d[0], n[0])"},
        {"ldexp dvec2 .y", "ldexp(dvec2(d[0], d[1]), ivec2(n[0], n[1])).y"},
        {"frexp m", "fm"},
        {"frexp e", "int:fe"},
        {"modf f", "mf"},
        {"modf i", "mi"},
        {"modf dvec2 f.y", "vf.y"},
        {"modf dvec2 i.x", "vi.x"},
        {"frexp dvec2 m.y", "vm.y"},
        {"frexp dvec2 e.y", "int:ve.y"}},
       "  int fe; double fm = frexp(d[0], fe);\n  double mi; double mf = modf(d[0], mi);\n"
       "  dvec2 vi; dvec2 vf = modf(dvec2(d[0], d[1]), vi);\n  ivec2 ve; dvec2 vm = frexp(dvec2(d[1], d[0]), ve);\n"},
      {"geometric dvec3", 7, 0,
       {{"dot3", "dot(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]))"},
        {"length3", "length(dvec3(d[0], d[1], d[2]))"},
        {"distance3", "distance(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]))"},
        {"normalize3 .y", "normalize(dvec3(d[0], d[1], d[2])).y"},
        {"cross .x", "cross(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5])).x"},
        {"cross .y", "cross(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5])).y"},
        {"cross .z", "cross(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5])).z"},
        {"faceforward3 .x", "faceforward(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]), dvec3(d[6], d[1], d[3])).x"},
        {"reflect3 .z", "reflect(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5])).z"},
        {"refract3 .y", "refract(dvec3(d[0], d[1], d[2]), dvec3(d[3], d[4], d[5]), d[6]).y"}}},
      {"geometric dvec2, dvec4", 9, 0,
       {{"dot2", "dot(dvec2(d[0], d[1]), dvec2(d[2], d[3]))"},
        {"length2", "length(dvec2(d[0], d[1]))"},
        {"normalize2 .x", "normalize(dvec2(d[0], d[1])).x"},
        {"dot4", "dot(dvec4(d[0], d[1], d[2], d[3]), dvec4(d[4], d[5], d[6], d[7]))"},
        {"length4", "length(dvec4(d[0], d[1], d[2], d[3]))"},
        {"distance4", "distance(dvec4(d[0], d[1], d[2], d[3]), dvec4(d[4], d[5], d[6], d[7]))"},
        {"normalize4 .w", "normalize(dvec4(d[0], d[1], d[2], d[3])).w"},
        {"reflect4 .y", "reflect(dvec4(d[0], d[1], d[2], d[3]), dvec4(d[4], d[5], d[6], d[7])).y"},
        {"refract2 .x", "refract(dvec2(d[0], d[1]), dvec2(d[2], d[3]), d[8]).x"}}},
      {"geometric double", 3, 0,
       {{"dot1", "dot(d[0], d[1])"},
        {"length1", "length(d[0])"},
        {"distance1", "distance(d[0], d[1])"},
        {"normalize1", "normalize(d[0])"},
        {"faceforward1", "faceforward(d[0], d[1], d[2])"},
        {"reflect1", "reflect(d[0], d[1])"},
        {"refract1", "refract(d[0], d[1], d[2])"}}},
  };
  return list;
}

std::string source(const Group& g) {
  const int arity = g.doubles + g.ints, results = int(g.results.size());
  std::string body = "  double d[" + std::to_string(g.doubles) + "];\n  for (int k = 0; k < " +
                     std::to_string(g.doubles) + "; ++k) d[k] = packDouble2x32(w[k]);\n";
  if (g.ints) {
    body += "  int n[" + std::to_string(g.ints) + "];\n";
    for (int k = 0; k < g.ints; ++k)
      body += "  n[" + std::to_string(k) + "] = int(w[" + std::to_string(g.doubles + k) + "].x);\n";
  }
  body += g.prelude;
  for (int k = 0; k < results; ++k) {
    const std::string& e = g.results[size_t(k)].second;
    const std::string at = "r[" + std::to_string(results) + "u * i + " + std::to_string(k) + "u] = ";
    body += e.rfind("int:", 0) == 0 ? "  " + at + "uvec2(uint(" + e.substr(4) + "), 0u);\n"
                                    : "  " + at + "unpackDouble2x32(" + e + ");\n";
  }
  return words_shader("#version 450\n", arity, results, body);
}

// Per double: half moderate magnitudes (2^-10..2^10, full significands), the rest random
// patterns, the exponent grid, short significands near 1 (ties) and special values; per int: an
// exponent for ldexp (within +-2200, half of them within +-60).
std::vector<uint64_t> inputs(const Group& g) {
  Operands op(20261127);
  auto& rng = op.rng();
  std::vector<uint64_t> v;
  v.reserve(size_t(kInvocations) * size_t(g.doubles + g.ints));
  for (uint32_t i = 0; i < kInvocations; ++i) {
    for (int k = 0; k < g.doubles; ++k) {
      switch (rng() % 10) {
        case 0: v.push_back(op.special()); break;
        case 1: v.push_back(rng()); break;
        case 2: v.push_back(op.grid()); break;
        case 3: v.push_back(op.short_sig(1020 + rng() % 6, int(rng() % 12))); break;
        default: v.push_back(op.random_sign(((1013 + rng() % 21) << 52) | (rng() >> 12))); break;
      }
    }
    for (int k = 0; k < g.ints; ++k) {
      const int32_t e = (rng() & 1) ? int32_t(rng() % 4401) - 2200 : int32_t(rng() % 121) - 60;
      v.push_back(uint64_t(uint32_t(e)));
    }
  }
  return v;
}

std::string lower_exact(const std::string& src) {
  Options options;
  options.stage = Stage::Compute;
  options.target = Target::Es310;
  options.mode = Mode::Exact;
  Result lowered = lower(src, options);
  std::string diagnostics;
  for (const Diagnostic& d : lowered.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  EXPECT_TRUE(lowered.ok) << diagnostics;
  EXPECT_EQ(diagnostics, "");
  return lowered.output;
}

// Differing results per output of the group (both NaN counted apart: GLSL leaves NaN undefined).
struct Count {
  uint64_t differing = 0, nan_payload = 0;
  std::string first;
};

std::vector<Count> compare_group(const Group& g, const std::vector<uint64_t>& in, const std::vector<uint64_t>& got,
                                 const std::vector<uint64_t>& want) {
  const size_t results = g.results.size(), arity = size_t(g.doubles + g.ints);
  std::vector<Count> c(results);
  for (size_t i = 0; i < got.size() && i < want.size(); ++i) {
    if (got[i] == want[i]) continue;
    Count& k = c[i % results];
    if (is_nan(got[i]) && is_nan(want[i])) {
      ++k.nan_payload;
      continue;
    }
    if (k.differing++ == 0) {
      char buf[64];
      k.first = "inputs";
      for (size_t a = 0; a < arity; ++a) {
        std::snprintf(buf, sizeof buf, " %016llx", (unsigned long long)in[(i / results) * arity + a]);
        k.first += buf;
      }
      std::snprintf(buf, sizeof buf, " got %016llx want %016llx", (unsigned long long)got[i], (unsigned long long)want[i]);
      k.first += buf;
    }
  }
  return c;
}

class ExactBuiltins : public ::testing::TestWithParam<int> {};

TEST_P(ExactBuiltins, BitIdenticalToNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const Group& g = groups()[size_t(GetParam())];
  const std::string native_src = source(g), exact_src = lower_exact(native_src);
  ASSERT_FALSE(exact_src.empty());
  const std::string code = std::regex_replace(exact_src, std::regex("//[^\n]*"), "");
  EXPECT_FALSE(std::regex_search(code, std::regex(R"(\b(double|dvec[234])\b)"))) << "a double survived";
  const std::vector<uint64_t> in = inputs(g);
  const int arity = g.doubles + g.ints, results = int(g.results.size());
  const std::vector<uint64_t> native = run_words(Backend::Vulkan, native_src, in, arity, results);
  ASSERT_EQ(native.size(), size_t(kInvocations) * size_t(results));
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const std::vector<uint64_t> got = run_words(backend, exact_src, in, arity, results);
    const std::vector<Count> c = compare_group(g, in, got, native);
    for (size_t k = 0; k < c.size(); ++k) {
      std::cout << "[ exact ] " << backend_name(backend) << " " << g.results[k].first << ": " << c[k].differing
                << " of " << kInvocations << " differ from native (" << c[k].nan_payload << " NaN payloads apart)"
                << (c[k].differing ? "; first " + c[k].first : "") << "\n";
      EXPECT_EQ(c[k].differing, 0u) << backend_name(backend) << " " << g.results[k].first << ": " << c[k].first;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Groups, ExactBuiltins, ::testing::Range(0, int(groups().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string n = groups()[size_t(info.param)].name;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

// The same comparison sees each built-in family broken: another (mathematically equal) order of
// operations for mix, smoothstep, normalize and dot, ldexp without native's clamp, modf without
// its sign rule. Each edit must apply to the lowered text and change some results.
TEST(ExactBuiltinsSabotage, OtherOrdersAndRulesDiffer) {
  REQUIRE_BACKEND(Backend::Vulkan);
  struct Sabotage {
    const char* name;
    int group;
    std::string from, to;
  };
  const std::vector<Sabotage> sabotages = {
      {"mix as x + a(y - x)", 0, "return ex_from_bits(ex_fma_bits(ex_bits(y), wa, rest));",
       "return ex_from_bits(ex_add_bits(ex_bits(x), ex_mul_bits(wa, ex_sub_bits(ex_bits(y), ex_bits(x)))));"},
      {"smoothstep as (t t)(3 - 2t)", 0, "return ex_from_bits(ex_mul_first(t, ex_mul_first(t, s)));",
       "return ex_from_bits(ex_mul_first(ex_mul_first(t, t), s));"},
      {"ldexp clamped to +-2100", 2, "int c = clamp(e, -2046, 2046);", "int c = clamp(e, -2100, 2100);"},
      {"modf without the sign rule", 2, "  return negative ? ex_neg_bits(f) : f;", "  return f;"},
      {"normalize as v * (1 / length)", 3, "uvec2 q = ex_div_bits(uvec2(a.lo[k], a.hi[k]), len);",
       "uvec2 q = ex_mul_bits(uvec2(a.lo[k], a.hi[k]), ex_div_bits(uvec2(0u, 0x3FF00000u), len));"},
      {"dot started from +0 (0 + p0 + p1 ...)", 3,
       "uvec2 s = ex_mul_first(uvec2(a.lo.x, a.hi.x), uvec2(b.lo.x, b.hi.x));\n  for (int k = 1;",
       "uvec2 s = uvec2(0u);\n  for (int k = 0;"},
  };
  for (const Sabotage& sab : sabotages) {
    const Group& g = groups()[size_t(sab.group)];
    const std::string native_src = source(g);
    std::string exact_src = lower_exact(native_src);
    const size_t at = exact_src.find(sab.from);
    ASSERT_NE(at, std::string::npos) << sab.name;
    exact_src.replace(at, sab.from.size(), sab.to);
    const std::vector<uint64_t> in = inputs(g);
    const int arity = g.doubles + g.ints, results = int(g.results.size());
    const std::vector<Count> c = compare_group(g, in, run_words(Backend::Vulkan, exact_src, in, arity, results),
                                               run_words(Backend::Vulkan, native_src, in, arity, results));
    uint64_t total = 0;
    for (const Count& k : c) total += k.differing;
    std::cout << "[ exact ] sabotage '" << sab.name << "': " << total << " results differ\n";
    EXPECT_GT(total, 0u) << sab.name;
  }
}

}  // namespace
}  // namespace doublet::runner::test::exact
