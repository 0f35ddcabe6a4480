// --range and --spec parsing.
#include <gtest/gtest.h>

#include "verify/spec.hpp"

namespace doublet::verify {
namespace {

TEST(Range, ParsesDecimalAndHexBounds) {
  std::string name;
  InputSpec in;
  ASSERT_EQ(parse_range("x=-0x1p-3:2.5e1", &name, &in), "");
  EXPECT_EQ(name, "x");
  EXPECT_EQ(*in.lo, -0.125);
  EXPECT_EQ(*in.hi, 25.0);
}

TEST(Range, RejectsMalformedAndEmptyRanges) {
  std::string name;
  InputSpec in;
  EXPECT_NE(parse_range("x", &name, &in), "");
  EXPECT_NE(parse_range("=1:2", &name, &in), "");
  EXPECT_NE(parse_range("x=1:abc", &name, &in), "");
  EXPECT_NE(parse_range("x=2:1", &name, &in), "");
}

TEST(Spec, ReadsEveryField) {
  Spec spec;
  ASSERT_EQ(parse_spec(R"({"array_length": 8, "groups": [2, 3],
      "inputs": {"a": {"range": ["0x1p-4", 2]}, "b": {"values": [1, "-0x1.8p0"], "elements_per_invocation": 2}},
      "outputs": {"r": {"min_bits": 40, "abs_floor": 1e-30, "join": "hi_lo", "elements_per_invocation": 4}}})",
                       &spec),
            "");
  EXPECT_EQ(spec.array_length, 8u);
  EXPECT_EQ(spec.groups[0], 2u);
  EXPECT_EQ(spec.groups[1], 3u);
  EXPECT_EQ(spec.groups[2], 1u);
  EXPECT_EQ(*spec.inputs["a"].lo, 0.0625);
  EXPECT_EQ(spec.inputs["b"].values, (std::vector<double>{1.0, -1.5}));
  EXPECT_EQ(spec.inputs["b"].elements_per_invocation, 2u);
  EXPECT_EQ(*spec.outputs["r"].min_bits, 40.0);
  EXPECT_EQ(*spec.outputs["r"].abs_floor, 1e-30);
  EXPECT_TRUE(spec.outputs["r"].join_hi_lo);
  EXPECT_EQ(spec.outputs["r"].elements_per_invocation, 4u);
}

TEST(Spec, RejectsUnknownFieldsAndBadValues) {
  Spec spec;
  EXPECT_NE(parse_spec("not json", &spec), "");
  EXPECT_NE(parse_spec(R"({"sampels": 3})", &spec), "");
  EXPECT_NE(parse_spec(R"({"inputs": {"a": {"range": [2, 1]}}})", &spec), "");
  EXPECT_NE(parse_spec(R"({"inputs": {"a": {"values": []}}})", &spec), "");
  EXPECT_NE(parse_spec(R"({"outputs": {"r": {"join": "lo_hi"}}})", &spec), "");
  EXPECT_NE(parse_spec(R"({"groups": [0]})", &spec), "");
}

}  // namespace
}  // namespace doublet::verify
