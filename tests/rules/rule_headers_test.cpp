// The documentation contract: every emitted function states its algorithm, source, error bound
// and flop count; every rule file cites its sources; docs/rules.md agrees with the headers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "emitted_glsl.hpp"
#include "rules/rule_library.hpp"

namespace doublet::rules {
namespace {

std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string field(const std::string& header, const std::string& key) {
  std::smatch m;
  if (std::regex_search(header, m, std::regex("(^|\\n)// " + key + ": *([^\\n]*)"))) return m[2];
  return {};
}

const std::regex kYear(R"(\b(19|20)\d\d\b)");
const std::regex kBound(R"(^(exact|0\.5 ulp.*|.*u\^2.*)$)");

// Parses the header of every function in every emitted instance.
TEST(RuleHeaders, EveryEmittedFunctionStatesBoundAndSource) {
  const RuleLibrary& lib = RuleLibrary::builtin();
  int checked = 0;
  for (const auto& ref : lib.all())
    for (bool integer_eft : {false, true}) {  // df64-int's replacements (rules/int.glsl) too
    EmitRequest req;
    req.used = {ref};
    req.integer_eft = integer_eft;
    EmitResult r = lib.emit(req);
    ASSERT_TRUE(r.ok) << r.error;
    for (const auto& f : test::split_functions(r.text)) {
      SCOPED_TRACE(f.signature);
      const std::string algorithm = field(f.header, "Algorithm"), source = field(f.header, "Source"),
                        bound = field(f.header, "Bound"), flops = field(f.header, "Flops");
      EXPECT_FALSE(algorithm.empty()) << "no 'Algorithm:' line in\n" << f.header;
      EXPECT_TRUE(std::regex_search(source, kYear)) << "'Source:' cites no year: " << source;
      EXPECT_TRUE(std::regex_match(bound, kBound)) << "'Bound:' is not 'exact' or in u^2: " << bound;
      EXPECT_TRUE(std::regex_search(flops, std::regex(R"(^\d+)"))) << "'Flops:' is not a count: " << flops;
      ++checked;
    }
    }
  EXPECT_GT(checked, 500);
}

TEST(RuleHeaders, EmittedTextIsAscii) {
  for (const auto& ref : RuleLibrary::builtin().all()) {
    EmitRequest req;
    req.used = {ref};
    const std::string text = RuleLibrary::builtin().emit(req).text;
    for (unsigned char c : text) ASSERT_LT(c, 0x80) << ref.name;
  }
}

TEST(RuleHeaders, EveryRuleFileCitesSources) {
  const std::filesystem::path dir = std::filesystem::path(DOUBLET_SOURCE_DIR) / "rules";
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".glsl") continue;
    ++files;
    const std::string text = read_file(e.path());
    const std::string header = text.substr(0, text.find("\n\n"));
    SCOPED_TRACE(e.path().filename().string());
    EXPECT_EQ(header.rfind("// rules/" + e.path().filename().string(), 0), 0u) << "first line names the file";
    EXPECT_NE(header.find("Sources:"), std::string::npos);
    EXPECT_TRUE(std::regex_search(header, kYear));
  }
  EXPECT_GE(files, 7);
}

std::string widths_text(const std::vector<int>& w) {
  if (w.size() > 1 && w.back() - w.front() + 1 == static_cast<int>(w.size()))
    return std::to_string(w.front()) + "-" + std::to_string(w.back());
  std::string s;
  for (int x : w) s += (s.empty() ? "" : " ") + std::to_string(x);
  return s;
}

// docs/rules.md has a row per chunk: | `name` | widths | ... | bound | flops |, with the header's
// exact Bound text and the Flops count, so the table cannot drift from the rules.
TEST(RuleHeaders, DocsTableMatchesHeaders) {
  const std::string doc = read_file(std::filesystem::path(DOUBLET_SOURCE_DIR) / "docs" / "rules.md");
  ASSERT_FALSE(doc.empty());
  std::vector<std::string> rows;
  std::istringstream in(doc);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `", 0) == 0) rows.push_back(line);
  for (const auto& info : RuleLibrary::builtin().info()) {
    SCOPED_TRACE(info.name + " widths " + widths_text(info.widths));
    const std::string variant = info.variant.empty()                  ? ""
                                : info.variant == "int"               ? " (df64-int)"
                                : info.variant == "integer-functions" ? " (integer functions)"
                                                                      : " (bit casts)";
    const std::string key = "| `" + info.name + "`" + variant + " | " + widths_text(info.widths) + " |";
    const std::string* row = nullptr;
    for (const auto& r : rows)
      if (r.rfind(key, 0) == 0) row = &r;
    ASSERT_NE(row, nullptr) << "docs/rules.md has no row starting with " << key;
    EXPECT_NE(row->find("| " + info.bound + " |"), std::string::npos) << *row << "\nbound: " << info.bound;
    std::smatch m;
    std::regex_search(info.flops, m, std::regex(R"(^\d+)"));
    EXPECT_NE(row->find("| " + m.str() + " |"), std::string::npos) << *row << "\nflops: " << info.flops;
  }
}

}  // namespace
}  // namespace doublet::rules
