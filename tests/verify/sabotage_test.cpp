// The drop-lo sabotage: demoting doubles to floats in the source text.
#include <gtest/gtest.h>

#include "frontend/demote.hpp"
#include "verify/sabotage.hpp"

namespace doublet::verify {
namespace {

// frontend::demote_doubles, shared by the drop-lo sabotage and the fp32 baselines of bench and demo.
TEST(Sabotage, DemotesTypesAndLiteralSuffixesButNotComments) {
  EXPECT_EQ(frontend::demote_doubles("// a double here\ndouble x = 1.5lf; dvec3 v = dvec3(2.0LF); /* dvec2 */ doubled"),
            "// a double here\nfloat x = 1.5; vec3 v = vec3(2.0); /* dvec2 */ doubled");
  EXPECT_EQ(frontend::demote_doubles("dmat4 m; dmat2x3 n; int doubled; float f = 1e-3; double s = 1e3LF; dvecx d;"),
            "mat4 m; mat2x3 n; int doubled; float f = 1e-3; float s = 1e3; dvecx d;");
}

// frontend::blank_precise: the recompilation of the user's text as the target (pipeline/validation.cpp).
TEST(Sabotage, BlanksPreciseKeepingColumnsButNotCommentsOrLongerNames) {
  EXPECT_EQ(frontend::blank_precise("precise float x; // precise\nfloat imprecise = 1.0; precise_x = 2;"),
            "        float x; // precise\nfloat imprecise = 1.0; precise_x = 2;");
}

TEST(Sabotage, NamesRoundTrip) {
  for (Sabotage s : {Sabotage::None, Sabotage::DropLo, Sabotage::DropGuard, Sabotage::TiesAway})
    EXPECT_EQ(parse_sabotage(to_string(s)), s);
  EXPECT_FALSE(parse_sabotage("drop-hi"));
}

TEST(Sabotage, DropGuardRemovesTheGuard) {
  std::string source = "x";
  Options o;
  apply_sabotage(Sabotage::DropGuard, &source, &o);
  EXPECT_EQ(o.guard, GuardKind::None);
  EXPECT_EQ(source, "x");
}

}  // namespace
}  // namespace doublet::verify
