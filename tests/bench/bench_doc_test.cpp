// The kernels' flop counts are copied from docs/rules.md; this keeps them from drifting.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "bench/kernels.hpp"

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
      {"div", {"df_div", "1-4"}},   {"sqrt", {"df_sqrt", "1-4"}},   {"dot3", {"df_dot", "3"}},
      {"length3", {"df_length", "2-4"}}};
  for (const auto& [op, row] : rows) {
    const doublet::bench::Kernel* k = doublet::bench::find_kernel(op);
    ASSERT_NE(k, nullptr) << op;
    EXPECT_EQ(k->rule_flops, documented_flops(doc, row.first, row.second)) << op;
  }
  EXPECT_EQ(doublet::bench::find_kernel("mat4")->rule_flops, 4 * documented_flops(doc, "df_dot", "4"));
}

}  // namespace
