// The --json schema: docs/verify.md holds an example report between "<!-- schema -->" markers; the
// JSON to_json() writes must have exactly its keys, recursively, with the same JSON types (null
// stands for "string or null" / "number or null"). Changing one without the other fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "verify/report.hpp"

namespace doublet::verify {
namespace {

nlohmann::json documented_example() {
  std::ifstream in(DOUBLET_VERIFY_DOC);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const std::string marker = "<!-- schema -->";
  const size_t a = doc.find(marker), b = doc.find(marker, a + 1);
  if (a == std::string::npos || b == std::string::npos) return nullptr;
  std::string block = doc.substr(a + marker.size(), b - a - marker.size());
  block = block.substr(block.find('{'), block.rfind('}') - block.find('{') + 1);
  return nlohmann::json::parse(block);
}

void same_shape(const nlohmann::json& doc, const nlohmann::json& got, const std::string& path) {
  if (doc.is_null() || got.is_null()) return;  // nullable fields: either form is fine
  ASSERT_EQ(doc.type_name(), std::string(got.type_name())) << path;
  if (doc.is_object()) {
    for (const auto& [k, v] : doc.items()) {
      ASSERT_TRUE(got.contains(k)) << "documented key missing from the output: " << path << "." << k;
      same_shape(v, got[k], path + "." + k);
    }
    for (const auto& [k, v] : got.items())
      EXPECT_TRUE(doc.contains(k)) << "undocumented key in the output: " << path << "." << k;
  } else if (doc.is_array() && !doc.empty() && !got.empty()) {
    same_shape(doc[0], got[0], path + "[0]");
  }
}

VerifyReport sample_report() {
  VerifyReport r;
  r.shader = "a.comp";
  r.stage = "comp";
  r.target = "es310";
  r.sabotage = "none";
  r.samples = 4;
  r.seed = 1;
  r.dispatches = 1;
  r.inputs = {"x[] (buffer vec4)"};
  r.notes = {"uniform 'k' is not a float/double scalar or vector: left at 0"};
  BackendRun run;
  run.backend = runner::Backend::Gles;
  run.driver = run.reference_driver = "llvmpipe";
  StatsBuilder b("r[].xy", "float hi+lo", 0x1p-126);
  b.add(1.0 + 0x1p-46, 1.0, 0);
  OutputStats o = b.finish();
  o.worst_input = "x[0]=(0x1p+0)";
  o.min_bits_required = 44;
  run.outputs.push_back(o);
  r.runs.push_back(run);
  return r;
}

TEST(JsonSchema, OutputMatchesTheDocumentedExample) {
  const nlohmann::json doc = documented_example();
  ASSERT_FALSE(doc.is_null()) << "no <!-- schema --> example in " << DOUBLET_VERIFY_DOC;
  const nlohmann::json got = nlohmann::json::parse(to_json(sample_report()));
  same_shape(doc, got, "$");
  EXPECT_EQ(got["schema"], kJsonSchema);
  EXPECT_EQ(got["runs"][0]["outputs"][0]["min_bits"], 46.0);
  EXPECT_EQ(got["runs"][0]["outputs"][0]["passed"], true);
  EXPECT_EQ(got["passed"], true);
}

TEST(JsonSchema, InputErrorsAreReported) {
  VerifyReport r;
  r.input_error = "no input named 'q'";
  const nlohmann::json got = nlohmann::json::parse(to_json(r));
  EXPECT_EQ(got["error"], "no input named 'q'");
  EXPECT_EQ(got["passed"], false);
  EXPECT_TRUE(got["runs"].empty());
}

}  // namespace
}  // namespace doublet::verify
