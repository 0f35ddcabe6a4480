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
#include "exact_groups.hpp"

namespace doublet::runner::test::exact {
namespace {

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
      // On variables, where share-exact-calls writes dot, length, distance and normalize out as the
      // additions, products, square roots and divisions their rules perform, and runs a sum and a
      // difference through one site (src/lower/share_exact_calls.cpp).
      {"geometric on variables, shared", 9, 0,
       {{"dot3 of variables", "dot(a, b)"},
        {"length3 of a variable", "length(a)"},
        {"distance3 of variables", "distance(a, b)"},
        {"normalize3 of a variable .x", "normalize(a).x"},
        {"normalize3 of a variable .z", "normalize(a).z"},
        {"sum .y", "(a + b).y"},
        {"difference .z", "(a - b).z"},
        {"dot2 of a variable", "dot(p, p)"},
        {"normalize2 of a variable .y", "normalize(p).y"},
        {"dot4 of variables", "dot(q, c)"},
        {"length4 of a variable", "length(q)"},
        {"normalize4 of a variable .w", "normalize(q).w"},
        {"length1 of a variable", "length(x)"},
        {"normalize1 of a variable", "normalize(x)"},
        {"distance1 of variables", "distance(x, y)"},
        {"difference1", "x - y"}},
       "  dvec3 a = dvec3(d[0], d[1], d[2]);\n  dvec3 b = dvec3(d[3], d[4], d[5]);\n  dvec2 p = dvec2(d[6], d[7]);\n"
       "  dvec4 q = dvec4(d[0], d[3], d[6], d[8]);\n  dvec4 c = dvec4(d[5], d[7], d[1], d[2]);\n"
       "  double x = d[8];\n  double y = d[4];\n"},
  };
  return list;
}

class ExactBuiltins : public ::testing::TestWithParam<int> {};

TEST_P(ExactBuiltins, BitIdenticalToNativeFp64) { expect_bit_identical(groups()[size_t(GetParam())]); }

INSTANTIATE_TEST_SUITE_P(Groups, ExactBuiltins, ::testing::Range(0, int(groups().size())),
                         [](const ::testing::TestParamInfo<int>& info) { return group_test_name(groups(), info.param); });

// The same comparison sees each built-in family broken: another (mathematically equal) order of
// operations for mix, smoothstep, normalize and dot, ldexp without native's clamp, modf without
// its sign rule. Each edit must apply to the lowered text and change some results.
TEST(ExactBuiltinsSabotage, OtherOrdersAndRulesDiffer) {
  expect_sabotages_differ(groups(), {
      {"mix as x + a(y - x)", 0, "return ex_from_bits(ex_fma_bits(ex_bits(y), wa, rest));",
       "return ex_from_bits(ex_add_bits(ex_bits(x), ex_mul_bits(wa, ex_sub_bits(ex_bits(y), ex_bits(x)))));", {0}},
      {"smoothstep as (t t)(3 - 2t)", 0, "return ex_from_bits(ex_mul_first(t, ex_mul_first(t, s)));",
       "return ex_from_bits(ex_mul_first(ex_mul_first(t, t), s));", {3}},
      {"ldexp clamped to +-2100", 2, "int c = clamp(e, -2046, 2046);", "int c = clamp(e, -2100, 2100);", {0}},
      {"modf without the sign rule", 2, "  return negative ? ex_neg_bits(f) : f;", "  return f;", {4}},
      {"normalize as v * (1 / length)", 3, "uvec2 q = ex_div_bits(uvec2(a.lo[k], a.hi[k]), len);",
       "uvec2 q = ex_mul_bits(uvec2(a.lo[k], a.hi[k]), ex_div_bits(uvec2(0u, 0x3FF00000u), len));", {3}},
      {"dot3 summed from the last component", 3,
       "uvec2 s = ex_mul_first(uvec2(a.lo.x, a.hi.x), uvec2(b.lo.x, b.hi.x));\n  for (int k = 1; k < 3; ++k)",
       "uvec2 s = ex_mul_first(uvec2(a.lo.z, a.hi.z), uvec2(b.lo.z, b.hi.z));\n  for (int k = 1; k >= 0; --k)", {0}},
      {"the shared site adding where it subtracts", 6, "_n = 1;", "_n = 0;", {5, 6}},
      {"the shared site dropping its sign flip", 6, "uint sign = uint(n) << 31;", "uint sign = 0u;", {5, 6}},
  });
}

}  // namespace
}  // namespace doublet::runner::test::exact
