// Mode exact's double matrices (dmat2-4, dmatCxR): constructors, + - * / with matrices, vectors and
// scalars, matrixCompMult, outerProduct, transpose, determinant, inverse, ==, conversions, columns
// and elements, bit for bit against native fp64 on lavapipe: a shader written with doubles run
// natively and, lowered with --mode exact --target es310, on lavapipe and Mesa GLES, 2^20 inputs
// per result. Native's order (spirv_to_nir's products and expansions as Mesa's optimizer leaves
// them) was measured with candidate orders; src/lower/matrix_helpers_exact.cpp repeats it.
// Sabotages (edits of the lowered text) must make results differ.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "exact_groups.hpp"

namespace doublet::runner::test::exact {
namespace {

const std::vector<Group>& groups() {
  static const std::vector<Group> list = {
      {"dmat3 arithmetic", 22, 0,
       {{"m * v .x", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) * dvec3(d[18], d[19], d[20])).x"},
        {"m * v .z", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) * dvec3(d[18], d[19], d[20])).z"},
        {"v * m .y", "(dvec3(d[18], d[19], d[20]) * dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8])).y"},
        {"m * k [1].y", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) * dmat3(d[9], d[10], d[11], d[12], d[13], d[14], d[15], d[16], d[17]))[1].y"},
        {"m * k [2].x", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) * dmat3(d[9], d[10], d[11], d[12], d[13], d[14], d[15], d[16], d[17]))[2].x"},
        {"s * m [0].y", "(d[21] * dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]))[0].y"},
        {"m * s [1].z", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) * d[21])[1].z"},
        {"m / s [2].y", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) / d[21])[2].y"},
        {"m + k [0].x", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) + dmat3(d[9], d[10], d[11], d[12], d[13], d[14], d[15], d[16], d[17]))[0].x"},
        {"m - k [1].y", "(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]) - dmat3(d[9], d[10], d[11], d[12], d[13], d[14], d[15], d[16], d[17]))[1].y"},
        {"matrixCompMult [2].z", "matrixCompMult(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]), dmat3(d[9], d[10], d[11], d[12], d[13], d[14], d[15], d[16], d[17]))[2].z"},
        {"-m [1].x", "(-dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]))[1].x"},
        {"outerProduct [2].y", "outerProduct(dvec3(d[18], d[19], d[20]), dvec3(d[9], d[10], d[11]))[2].y"},
        {"transpose [0].z", "transpose(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]))[0].z"}}},
      {"determinant", 29, 0,
       {{"determinant dmat2", "determinant(dmat2(d[0], d[1], d[2], d[3]))"},
        {"determinant dmat3", "determinant(dmat3(d[4], d[5], d[6], d[7], d[8], d[9], d[10], d[11], d[12]))"},
        {"determinant dmat4", "determinant(dmat4(d[13], d[14], d[15], d[16], d[17], d[18], d[19], d[20], d[21], d[22], d[23], d[24], d[25], d[26], d[27], d[28]))"}}},
      {"inverse", 29, 0,
       {{"inverse dmat2 [0][1]", "i2[0][1]"},
        {"inverse dmat2 [1][1]", "i2[1][1]"},
        {"inverse dmat3 [2][1]", "i3[2][1]"},
        {"inverse dmat3 [1][1]", "i3[1][1]"},
        {"inverse dmat4 [1][2]", "i4[1][2]"},
        {"inverse dmat4 [3][3]", "i4[3][3]"},
        {"inverse dmat4 [0][1]", "i4[0][1]"}},
       "  dmat2 i2 = inverse(dmat2(d[0], d[1], d[2], d[3]));\n  dmat3 i3 = inverse(dmat3(d[4], d[5], d[6], d[7], d[8], d[9], d[10], d[11], d[12]));\n"
       "  dmat4 i4 = inverse(dmat4(d[13], d[14], d[15], d[16], d[17], d[18], d[19], d[20], d[21], d[22], d[23], d[24], d[25], d[26], d[27], d[28]));\n"},
      {"non-square, constructors, comparisons", 15, 0,
       {{"dmat2x3 * dvec2 .z", "(dmat2x3(d[0], d[1], d[2], d[3], d[4], d[5]) * dvec2(d[12], d[13])).z"},
        {"dvec3 * dmat2x3 .y", "(dvec3(d[12], d[13], d[14]) * dmat2x3(d[0], d[1], d[2], d[3], d[4], d[5])).y"},
        {"dmat2x3 * dmat3x2 [2][1]", "(dmat2x3(d[0], d[1], d[2], d[3], d[4], d[5]) * dmat3x2(d[6], d[7], d[8], d[9], d[10], d[11]))[2][1]"},
        {"dmat4x3 * dvec4 .y", "(dmat4x3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8], d[9], d[10], d[11]) * dvec4(d[12], d[13], d[14], d[6])).y"},
        {"transpose(dmat4x3) [3].z", "transpose(dmat4x3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8], d[9], d[10], d[11]))[2].w"},
        {"dmat4(dmat2x3) [1][2]", "dmat4(dmat2x3(d[0], d[1], d[2], d[3], d[4], d[5]))[1][2]"},
        {"dmat4(dmat2x3) [3][3]", "dmat4(dmat2x3(d[0], d[1], d[2], d[3], d[4], d[5]))[3][3]"},
        {"dmat3(double) [1][1]", "dmat3(d[3])[1][1]"},
        {"dmat3(double) [1][0]", "dmat3(d[3])[1][0]"},
        {"dmat2(mat2) [1][0]", "dmat2(mat2(vec2(d[0]), vec2(d[1])))[1][0]"},
        {"mat3(dmat3) [2][2] bits", "int:floatBitsToInt(mat3(dmat3(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]))[2][2])"},
        {"==, != (bits)", "int:int(dmat2(d[0], d[1], d[2], d[3]) == dmat2(d[4], d[5], d[6], d[7])) + 2 * int(dmat2(d[0], d[1], d[2], d[3]) != dmat2(d[0], d[1], d[2], d[4]))"},
        {"constant dmat3 * v .y", "(dmat3(0.1lf, 2.0lf, -3.5lf, 1e300lf, 5.0lf, 6.0lf, 7.0lf, 8.0lf, 1e-310lf) * dvec3(d[12], d[13], d[14])).y"}}},
  };
  return list;
}

class ExactMatrices : public ::testing::TestWithParam<int> {};

TEST_P(ExactMatrices, BitIdenticalToNativeFp64) { expect_bit_identical(groups()[size_t(GetParam())]); }

INSTANTIATE_TEST_SUITE_P(Groups, ExactMatrices, ::testing::Range(0, int(groups().size())),
                         [](const ::testing::TestParamInfo<int>& info) { return group_test_name(groups(), info.param); });

// Another order of the same formulas must show: a matrix-vector product summed from the first
// column (as older Mesa did), the 3x3 determinant summed without Mesa's reassociation, the 4x4
// one as spirv_to_nir writes it, (p0 - p1) + (p2 - p3), and an inverse with one sign of its adjugate lost.
TEST(ExactMatricesSabotage, OtherOrdersDiffer) {
  expect_sabotages_differ(groups(), {
      {"m * v from the first column", 0,
       "uvec2 s = ex_mul_first(uvec2(m.lo[2][i], m.hi[2][i]), uvec2(v.lo[2], v.hi[2]));\n"
       "    for (int t = 1; t >= 0; --t) s = ex_fma_bits(uvec2(m.lo[t][i], m.hi[t][i]), uvec2(v.lo[t], v.hi[t]), s);",
       "uvec2 s = ex_mul_bits(uvec2(m.lo[0][i], m.hi[0][i]), uvec2(v.lo[0], v.hi[0]));\n"
       "    for (int t = 1; t < 3; ++t) s = ex_add_bits(s, ex_mul_bits(uvec2(m.lo[t][i], m.hi[t][i]), uvec2(v.lo[t], v.hi[t])));", {0}},
      {"det3 summed x + (y + z)", 1, "return ex_add_first(z, ex_sub_bits(x, y));", "return ex_sub_bits(x, ex_sub_bits(y, z));", {1}},
      {"det4 as (p0 - p1) + (p2 - p3)", 1, "uvec2 det = ex_sub_bits(ex_add_first(p[0], ex_sub_bits(p[2], p[3])), p[1]);",
       "uvec2 det = ex_add_first(ex_sub_bits(p[0], p[1]), ex_sub_bits(p[2], p[3]));", {2}},
      {"inverse with an odd cofactor not negated", 2, "odd ? ex_neg_bits(d) : inv", "odd ? d : inv", {0, 1}},
  });
}

}  // namespace
}  // namespace doublet::runner::test::exact
