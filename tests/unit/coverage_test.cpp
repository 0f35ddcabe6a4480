// docs/coverage.md cannot drift from the test suite: every "yes" cell is backed by a golden case
// that is lowered (and re-validated) for that target and contains the construct's probe text;
// every "diag" cell names a message the compiler emits and a unit test expects; every numeric
// check named exists; every fp64 built-in of GLSL 4.60 has a row.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
const fs::path kRoot = DOUBLET_SOURCE_DIR;
const char* kTargets[] = {"es100", "es300", "es310", "es320", "glsl330", "glsl450", "webgl2"};
constexpr int kTargetCount = 7;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::string unquote(std::string s) {
  s = trim(s);
  if (s.size() >= 2 && (s.front() == '`' || s.front() == '"')) s = s.substr(1, s.size() - 2);
  return s;
}

struct Row {
  std::string construct, probe;
  std::vector<std::string> cells;  // per kTargets
  std::vector<std::string> cases;
  std::string numeric, diagnostic;
};

std::vector<Row> rows() {
  std::vector<Row> out;
  std::istringstream in(read(kRoot / "docs" / "coverage.md"));
  bool table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| construct |", 0) == 0) {
      table = true;
      continue;
    }
    if (!table) continue;
    if (line.rfind("|", 0) != 0) break;  // the table ends at its first non-row line
    if (line.rfind("|---", 0) == 0) continue;
    std::vector<std::string> cols;
    // Split on " | " (cells never contain it; probes in backticks may contain '|' only as "||").
    size_t start = 2;
    for (size_t bar; (bar = line.find(" | ", start)) != std::string::npos; start = bar + 3)
      cols.push_back(line.substr(start, bar - start));
    cols.push_back(line.substr(start, line.rfind(" |") - start));
    EXPECT_EQ(cols.size(), 5u + kTargetCount) << line;
    if (cols.size() != 5u + kTargetCount) continue;
    Row r;
    r.construct = trim(cols[0]);
    r.probe = unquote(cols[1]);
    for (int t = 0; t < kTargetCount; ++t) r.cells.push_back(trim(cols[2 + t]));
    std::stringstream cases(cols[2 + kTargetCount]);
    for (std::string c; std::getline(cases, c, ',');)
      if (trim(c) != "-") r.cases.push_back(trim(c));
    r.numeric = unquote(cols[3 + kTargetCount]);
    r.diagnostic = unquote(cols[4 + kTargetCount]);
    out.push_back(r);
  }
  return out;
}

std::set<std::string> case_targets(const std::string& text) {
  std::set<std::string> out;
  std::string first = text.substr(0, text.find('\n'));
  const std::string key = "// targets:";
  if (first.rfind(key, 0) != 0) return {"es300", "es310", "es320", "glsl450", "webgl2"};  // the harness default
  std::stringstream s(first.substr(key.size()));
  for (std::string t; s >> t;) out.insert(t);
  return out;
}

std::string all_text(const fs::path& dir, const std::set<std::string>& extensions) {
  std::string text;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && extensions.count(e.path().extension().string())) text += read(e.path());
  return text;
}

TEST(Coverage, TableIsThere) { EXPECT_GE(rows().size(), 60u); }

TEST(Coverage, EveryYesIsAGoldenCaseForThatTarget) {
  for (const Row& r : rows()) {
    SCOPED_TRACE(r.construct);
    for (int t = 0; t < kTargetCount; ++t) {
      const std::string& cell = r.cells[t];
      EXPECT_TRUE(cell == "yes" || cell == "diag" || cell == "-") << "cell '" << cell << "'";
      if (cell != "yes") continue;
      bool found = false;
      for (const auto& c : r.cases) {
        fs::path path = kRoot / "tests" / "golden" / "cases" / c;
        ASSERT_TRUE(fs::exists(path)) << path;
        std::string text = read(path);
        if (case_targets(text).count(kTargets[t]) && text.find(r.probe) != std::string::npos) found = true;
      }
      EXPECT_TRUE(found) << "no golden case among the listed ones targets " << kTargets[t] << " and contains `"
                         << r.probe << "`";
    }
  }
}

TEST(Coverage, EveryDiagNamesAnEmittedAndTestedMessage) {
  const std::string sources = all_text(kRoot / "src", {".cpp", ".hpp"}) + all_text(kRoot / "rules", {".glsl"});
  const std::string tests = all_text(kRoot / "tests" / "unit", {".cpp"});
  for (const Row& r : rows()) {
    bool any_diag = false;
    for (const auto& c : r.cells) any_diag |= c == "diag";
    if (!any_diag) continue;
    SCOPED_TRACE(r.construct);
    ASSERT_NE(r.diagnostic, "-") << "a diag cell needs the message in the diagnostic column";
    EXPECT_NE(sources.find(r.diagnostic), std::string::npos) << "the compiler never says \"" << r.diagnostic << "\"";
    EXPECT_NE(tests.find(r.diagnostic), std::string::npos) << "no unit test expects \"" << r.diagnostic << "\"";
  }
}

TEST(Coverage, EveryNumericCheckExists) {
  const std::string numeric = read(kRoot / "tests" / "numeric" / "builtins_test.cpp") +
                              read(kRoot / "tests" / "numeric" / "accuracy_test.cpp");
  for (const Row& r : rows()) {
    if (r.numeric == "-") continue;
    SCOPED_TRACE(r.construct);
    EXPECT_NE(numeric.find("\"" + r.numeric + "\""), std::string::npos) << "no numeric check named " << r.numeric;
  }
}

TEST(Coverage, EveryFp64BuiltinHasARow) {
  std::set<std::string> probes;
  for (const Row& r : rows()) probes.insert(r.probe);
  for (const char* b : {"abs", "sign", "floor", "trunc", "round", "roundEven", "ceil", "fract", "mod", "modf", "min",
                        "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "fma", "frexp", "ldexp",
                        "packDouble2x32", "unpackDouble2x32", "length", "distance", "dot", "cross", "normalize",
                        "faceforward", "reflect", "refract", "matrixCompMult", "outerProduct", "transpose",
                        "determinant", "inverse", "lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual",
                        "equal", "notEqual", "any", "all", "sqrt", "inversesqrt"})
    EXPECT_TRUE(probes.count(std::string(b) + "(")) << b << " has no row";
}

}  // namespace
