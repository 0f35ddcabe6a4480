// The drop-lo sabotage: demoting doubles to floats in the source text.
#include <gtest/gtest.h>

#include "verify/sabotage.hpp"

namespace doublet::verify {
namespace {

TEST(Sabotage, DemotesTypesAndLiteralSuffixesButNotComments) {
  EXPECT_EQ(demote_doubles("// a double here\ndouble x = 1.5lf; dvec3 v = dvec3(2.0LF); /* dvec2 */ doubled"),
            "// a double here\nfloat x = 1.5; vec3 v = vec3(2.0); /* dvec2 */ doubled");
}

TEST(Sabotage, NamesRoundTrip) {
  for (Sabotage s : {Sabotage::None, Sabotage::DropLo, Sabotage::DropGuard})
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
