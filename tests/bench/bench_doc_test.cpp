// The kernels' flop counts are copied from docs/rules.md; this keeps them from drifting.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bench/kernels.hpp"
#include "rules/rule_library.hpp"

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The last cell of the first docs/rules.md table row for `function` whose widths cell is `widths`.
int documented_flops(const std::string& doc, const std::string& function, const std::string& widths) {
  std::istringstream in(doc);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `" + function + "` | " + widths + " |", 0) != 0) continue;
    const size_t end = line.find_last_of('|');
    const size_t start = line.find_last_of('|', end - 1);
    return std::stoi(line.substr(start + 1, end - start - 1));
  }
  return -1;
}

TEST(BenchDocs, KernelFlopsMatchRulesTable) {
  const std::string doc = read(std::string(DOUBLET_DOCS) + "/rules.md");
  ASSERT_FALSE(doc.empty());
  const std::pair<const char*, std::pair<const char*, const char*>> rows[] = {
      {"add", {"df_add", "1-4"}},   {"sub", {"df_sub", "1-4"}},     {"mul", {"df_mul", "1-4"}},
      {"div", {"df_div", "1-4"}},   {"sqrt", {"df_sqrt", "1-4"}},   {"dot3", {"df_dot", "3"}}};
  // length3 is df_length at width 3, whose row gives the W = 4 count first ("210 (...; 160 for
  // W = 3)"): the kernel takes the width-3 figure from the rule header.
  for (const auto& [op, row] : rows) {
    const doublet::bench::Kernel* k = doublet::bench::find_kernel(op);
    ASSERT_NE(k, nullptr) << op;
    EXPECT_EQ(k->rule_flops, documented_flops(doc, row.first, row.second)) << op;
  }
  EXPECT_EQ(doublet::bench::find_kernel("mat4")->rule_flops, 4 * documented_flops(doc, "df_dot", "4"));
  const doublet::bench::Kernel* length3 = doublet::bench::find_kernel("length3");
  ASSERT_NE(length3, nullptr);
  bool found = false;
  for (const auto& info : doublet::rules::RuleLibrary::builtin().info())
    if (info.name == "df_length" && info.widths.size() > 1) {
      found = true;
      const std::string n = std::to_string(length3->rule_flops);
      EXPECT_TRUE(info.flops.find(n + " for W = 3") != std::string::npos || info.flops.rfind(n, 0) == 0) << info.flops;
    }
  EXPECT_TRUE(found);
}

}  // namespace
