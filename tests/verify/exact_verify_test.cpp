// verify --mode exact: the lowered shader must store native fp64's bits (fp64 evaluated as written:
// the native run's fp64 arithmetic is decorated NoContraction) for every output, on lavapipe and
// Mesa GLES; the verify test shaders and exact_words.comp show 0 differing results, and the
// ties-away and drop-lo sabotages make some differ.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "verify/report.hpp"
#include "verify/verify.hpp"

namespace doublet::verify {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

VerifyReport run(const std::string& shader, const std::string& spec, Sabotage sabotage = Sabotage::None,
                 uint64_t samples = 512) {
  const std::string dir = DOUBLET_VERIFY_SHADERS;
  VerifyOptions o;
  o.lower.file_name = shader;
  o.lower.stage = stage_from_path(shader);
  o.lower.target = *o.lower.stage == Stage::Compute ? Target::Es310 : Target::Es300;
  o.lower.mode = Mode::Exact;
  o.samples = samples;
  o.sabotage = sabotage;
  if (!spec.empty()) EXPECT_EQ(parse_spec(read(dir + "/" + spec), &o.spec), "") << spec;
  return verify(read(dir + "/" + shader), o);
}

// Results whose bits differ, over both backends; -1 when something did not run.
long long differing(const VerifyReport& r) {
  if (!r.input_error.empty() || r.runs.size() != 2) return -1;
  long long n = 0;
  for (const BackendRun& run : r.runs) {
    if (!run.error.empty() || run.outputs.empty()) return -1;
    for (const OutputStats& o : run.outputs) {
      EXPECT_TRUE(o.require_identical) << o.name;
      n += static_cast<long long>(o.differing);
    }
  }
  return n;
}

struct Case {
  const char* shader;
  const char* spec;
};

class ExactVerify : public ::testing::TestWithParam<Case> {};

TEST_P(ExactVerify, NoResultDiffersFromNativeFp64) {
  const VerifyReport r = run(GetParam().shader, GetParam().spec);
  std::printf("%s", format_table(r).c_str());
  EXPECT_EQ(differing(r), 0) << format_table(r);
  EXPECT_TRUE(r.passed()) << format_table(r);
  EXPECT_EQ(r.mode, "exact");
}

INSTANTIATE_TEST_SUITE_P(Shaders, ExactVerify,
                         ::testing::Values(Case{"arith_pairs.comp", "arith_pairs.json"},
                                           Case{"uniform_pairs.comp", "uniform_pairs.json"},
                                           Case{"global_init.comp", "global_init.json"},
                                           Case{"lowering_forms.comp", "lowering_forms.json"},
                                           Case{"exact_words.comp", ""}, Case{"exact_words.comp", "exact_ties.json"},
                                           Case{"pairs.vert", "pairs.vert.json"}, Case{"pairs.frag", "pairs.frag.json"}),
                         [](const auto& info) {
                           std::string name = std::string(info.param.shader) + (*info.param.spec ? "_spec" : "");
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

// The same comparison fails when the rounding is broken: ties rounded away from zero (the spec's
// inputs hold exact ties), or the doubles demoted to float before lowering.
TEST(ExactVerifySabotage, TiesAwayAndDropLoDiffer) {
  const VerifyReport ties = run("exact_words.comp", "exact_ties.json", Sabotage::TiesAway);
  std::printf("%s", format_table(ties).c_str());
  EXPECT_GT(differing(ties), 0) << format_table(ties);
  EXPECT_FALSE(ties.passed());
  const VerifyReport demoted = run("exact_words.comp", "", Sabotage::DropLo);
  EXPECT_FALSE(demoted.passed()) << format_table(demoted);
}

// ties-away edits mode exact's rounding: with another mode there is nothing to break.
TEST(ExactVerifySabotage, TiesAwayNeedsModeExact) {
  VerifyOptions o;
  o.lower.file_name = "exact_words.comp";
  o.lower.stage = Stage::Compute;
  o.lower.target = Target::Es310;
  o.sabotage = Sabotage::TiesAway;
  const VerifyReport r = verify(read(std::string(DOUBLET_VERIFY_SHADERS) + "/exact_words.comp"), o);
  EXPECT_NE(r.input_error.find("ties-away"), std::string::npos) << r.input_error;
}

}  // namespace
}  // namespace doublet::verify
