// Scene and plan files: what parses, and where errors point (line:col counted by hand).
#include <gtest/gtest.h>

#include "plan/planner.hpp"
#include "plan/scene.hpp"

namespace {

using namespace doublet;
using namespace doublet::plan;

Diagnostic scene_error(const std::string& text) {
  Scene s;
  Diagnostic d;
  EXPECT_FALSE(parse_scene(text, "s.json", &s, &d));
  return d;
}

TEST(PlanScene, ParsesRangesRelationsAndOutputs) {
  Scene s;
  Diagnostic d;
  ASSERT_TRUE(parse_scene(R"({"inputs": {"p": {"min": [-1, -2, 3], "max": [1, 2, "4"]}, "e": {"abs_max": 5}},
    "relations": [{"difference": ["p", "e"], "abs_max": 1e4}],
    "outputs": {"gl_Position": {"abs_error": 1e-3}}})", "s.json", &s, &d)) << format_diagnostic(d);
  ASSERT_EQ(s.inputs["p"].components.size(), 3u);
  EXPECT_EQ(s.inputs["p"].components[1].lo, -2);
  EXPECT_EQ(s.inputs["p"].components[2].hi, 4);
  EXPECT_EQ(s.inputs["e"].component(2).lo, -5);
  ASSERT_EQ(s.relations.size(), 1u);
  EXPECT_EQ(s.relations[0].a, "p");
  EXPECT_EQ(s.relations[0].abs_max, 1e4);
  EXPECT_EQ(s.outputs["gl_Position"].abs_error, 1e-3);
}

TEST(PlanScene, InvalidJsonPointsAtTheCharacter) {
  const Diagnostic d = scene_error("{\n  \"inputs\": {,\n}");
  EXPECT_EQ(d.file, "s.json");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 14);  // the stray ','
  EXPECT_NE(format_diagnostic(d).find("s.json:2:14: error: scene is not valid JSON"), std::string::npos);
}

TEST(PlanScene, SemanticErrorsPointAtTheValue) {
  // Line 3, column 23: the value of "abs_errr".
  Diagnostic d = scene_error("{\n  \"outputs\": {\n    \"r\": {\"abs_errr\": 1}}\n}");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 23);
  EXPECT_NE(d.message.find("unknown field 'abs_errr'"), std::string::npos);

  d = scene_error("{\"inputs\": {\"x\": {\"min\": 2, \"max\": 1}}, \"outputs\": {\"r\": {\"abs_error\": 1}}}");
  EXPECT_EQ(d.column, 18);  // the object of "x"
  EXPECT_NE(d.message.find("min is greater than max"), std::string::npos);

  d = scene_error("{\"inputs\": {\"x\": {\"abs_max\": 1}},\n\"relations\": [{\"difference\": [\"x\", \"y\"], \"abs_max\": 1}],"
                  " \"outputs\": {\"r\": {\"abs_error\": 1}}}");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 30);  // the difference array
  EXPECT_NE(d.message.find("'y' is not among the scene's inputs"), std::string::npos);

  d = scene_error("{\"outputs\": {\"r\": {\"abs_error\": -1}}}");
  EXPECT_NE(d.message.find("positive"), std::string::npos);
  d = scene_error("{\"inputs\": {}}");
  EXPECT_NE(d.message.find("no outputs"), std::string::npos);
  d = scene_error("[1, 2]");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.column, 1);
}

TEST(PlanFile, RoundTripsAndRejectsBadModes) {
  PlanOutcome p;
  p.mode_for = {{"main.rel", Mode::Fp32}, {"helper", Mode::Rte}};
  Options o;
  Diagnostic d;
  ASSERT_TRUE(load_plan(plan_to_json(p), "p.json", &o, &d)) << format_diagnostic(d);
  EXPECT_EQ(o.mode, Mode::Df64);
  ASSERT_EQ(o.mode_for.size(), 2u);
  EXPECT_EQ(o.mode_for[0].first, "main.rel");
  EXPECT_EQ(o.mode_for[0].second, Mode::Fp32);
  EXPECT_EQ(o.mode_for[1].second, Mode::Rte);

  Options bad;
  EXPECT_FALSE(load_plan("{\"version\": 1,\n \"mode_for\": {\"x\": \"fp64\"}}", "p.json", &bad, &d));
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 20);  // "fp64"
  EXPECT_FALSE(load_plan("{\"version\": 2}", "p.json", &bad, &d));
  EXPECT_NE(d.message.find("version must be 1"), std::string::npos);
  EXPECT_FALSE(load_plan("{\"version\": 1,", "p.json", &bad, &d));
  EXPECT_NE(d.message.find("not valid JSON"), std::string::npos);
}

}  // namespace
