// Pass tests: GLSL in → the pipeline run up to one pass → the IR printed as it is then (with the
// diagnostics so far), compared with an expected file; and the same with that pass left out, which
// must differ — each test is shown to fail when its pass is disabled.
//
//   cases/<pass>.<vert|frag|comp>   first line: `// target: T [mode: M]`
//   expected/<pass>.<stage>.txt     the recorded result
//
// DOUBLET_UPDATE_GOLDEN=1 writes the expected files instead of comparing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "file_text.hpp"

namespace {
namespace fs = std::filesystem;
const fs::path kDir = DOUBLET_PASS_DIR;

// The value after `key:` on the case's first line, or "".
std::string header_value(const std::string& source, const std::string& key) {
  const std::string first = source.substr(0, source.find('\n'));
  const size_t at = first.find(key + ":");
  if (at == std::string::npos) return "";
  std::istringstream rest(first.substr(at + key.size() + 1));
  std::string value;
  rest >> value;
  return value;
}

struct Case {
  std::string pass, file;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const auto& e : fs::directory_iterator(kDir / "cases")) {
    const std::string file = e.path().filename().string();
    out.push_back({file.substr(0, file.rfind('.')), file});
  }
  std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) { return a.file < b.file; });
  return out;
}

// What a lowering stopped after `pass` records: the text, then every diagnostic.
std::string record(const Case& c, bool skip_the_pass) {
  std::string source = doublet::test::file_text(kDir / "cases" / c.file);
  doublet::Options o;
  o.stage = doublet::stage_from_path(c.file);
  o.target = *doublet::parse_target(header_value(source, "target"));
  if (const std::string mode = header_value(source, "mode"); !mode.empty()) o.mode = *doublet::parse_mode(mode);
  source = source.substr(source.find('\n') + 1);  // ES allows nothing before #version
  o.file_name = "cases/" + c.file;
  o.stop_after = c.pass;
  o.check_ir = true;
  if (skip_the_pass) o.skip_passes = {c.pass};
  const doublet::Result r = doublet::lower(source, o);
  std::string out = r.ok ? r.output : "// (no output)\n";
  for (const auto& d : r.diagnostics) out += "// " + doublet::format_diagnostic(d) + "\n";
  return out;
}

class PassTest : public ::testing::TestWithParam<Case> {};

TEST_P(PassTest, StopsAfterThePassWithTheExpectedIr) {
  const Case& c = GetParam();
  const fs::path expected = kDir / "expected" / (c.file + ".txt");
  const std::string got = record(c, false);
  const char* update = std::getenv("DOUBLET_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(expected, std::ios::binary) << got;
    GTEST_SKIP() << "updated " << expected;
  }
  ASSERT_TRUE(fs::exists(expected)) << "no expected file: run with DOUBLET_UPDATE_GOLDEN=1";
  EXPECT_EQ(got, doublet::test::file_text(expected));
}

TEST_P(PassTest, WithoutThePassTheResultDiffers) {
  const Case& c = GetParam();
  const fs::path expected = kDir / "expected" / (c.file + ".txt");
  ASSERT_TRUE(fs::exists(expected));
  EXPECT_NE(record(c, true), doublet::test::file_text(expected)) << "the case does not exercise pass '" << c.pass << "'";
}

INSTANTIATE_TEST_SUITE_P(Passes, PassTest, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.file;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(PassTable, EveryPassHasACase) {
  std::vector<std::string> covered;
  for (const Case& c : cases()) covered.push_back(c.pass);
  for (std::string_view pass : doublet::pass_names())
    EXPECT_NE(std::find(covered.begin(), covered.end(), std::string(pass)), covered.end())
        << "pass '" << pass << "' has no case in tests/passes/cases";
  for (const std::string& pass : covered) {
    const auto names = doublet::pass_names();
    EXPECT_NE(std::find(names.begin(), names.end(), pass), names.end()) << "case for an unknown pass '" << pass << "'";
  }
}

TEST(PassTable, AnUnknownPassNameIsRefused) {
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.stop_after = "no-such-pass";
  const doublet::Result r = doublet::lower("#version 300 es\nvoid main() {}\n", o);
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("no pass has that name"), std::string::npos) << r.diagnostics[0].message;
  EXPECT_NE(r.diagnostics[0].message.find("lower-doubles"), std::string::npos) << r.diagnostics[0].message;
}

}  // namespace
