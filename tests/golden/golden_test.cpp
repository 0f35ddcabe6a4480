// Golden-file tests of doublet::lower.
//
//   cases/<name>.<vert|frag|comp|geom|tesc|tese>  input; an optional first line
//                                          `// targets: es100 es300 ...` picks the
//                                          targets (default: es300 es310 es320 glsl450 webgl2).
//                                          That line is removed before lowering: GLSL ES
//                                          allows nothing, not even a comment, before
//                                          #version (diagnostic lines shift by one).
//                                          An optional `// options: --mode M --mode-for N=M`
//                                          line (first, or after the targets line) sets
//                                          the precision modes; it is removed too.
//   expected/<name>.<stage>.<target>.glsl  expected output, one per target
//   expected/<name>.<stage>.wgsl           the same for target wgsl
//   expected/<name>.<stage>.<target>.errors  instead, for a case the target refuses: the
//                                          formatted diagnostics (each file:line:col: error:);
//                                          create it empty, then update
//
// For every case and target (one test each) the harness lowers the case with
// the library and compares the result with the expected file byte for byte.
// Independently of the compiler under test, every expected GLSL file is compiled
// with glslang for the target's version and profile and must contain no
// double/dvec/dmat token; expected WGSL must have no f64 (WGSL has none): a real
// WGSL front end, Chromium's WebGPU, compiles it in tests/wgsl/wgsl_browser_test.cpp.
//
// DOUBLET_UPDATE_GOLDEN=1 writes the expected files instead of comparing:
//   DOUBLET_UPDATE_GOLDEN=1 ctest --test-dir build -R '^golden\.'
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include "doublet/doublet.hpp"

namespace {
namespace fs = std::filesystem;

// DOUBLET_GOLDEN_DIR (environment) points the binary at another copy of the
// cases/expected tree, e.g. to try an update without touching the source tree:
//   DOUBLET_GOLDEN_DIR=/tmp/golden DOUBLET_UPDATE_GOLDEN=1 build/tests/golden/golden_tests
// (CTest's test list is always the one of the source tree.)
fs::path golden_dir() {
  const char* env = std::getenv("DOUBLET_GOLDEN_DIR");
  return env != nullptr && *env != '\0' ? fs::path(env) : fs::path(DOUBLET_GOLDEN_DIR);
}
const fs::path kGoldenDir = golden_dir();
const fs::path kCasesDir = kGoldenDir / "cases";
const fs::path kExpectedDir = kGoldenDir / "expected";
const std::vector<std::string> kDefaultTargets = {"es300", "es310", "es320", "glsl450", "webgl2"};

// The harness's own view of each target: deliberately not taken from the
// library, so that validation does not trust the code under test.
struct TargetInfo {
  doublet::Target target;
  int version;  // 0: WGSL
  bool es;
};
const std::map<std::string, TargetInfo> kTargets = {
    {"es100", {doublet::Target::Es100, 100, true}},
    {"es300", {doublet::Target::Es300, 300, true}},
    {"es310", {doublet::Target::Es310, 310, true}},
    {"es320", {doublet::Target::Es320, 320, true}},
    {"glsl330", {doublet::Target::Glsl330, 330, false}},
    {"glsl450", {doublet::Target::Glsl450, 450, false}},
    {"webgl2", {doublet::Target::Webgl2, 300, true}},  // GLSL ES 3.00 text
    {"wgsl", {doublet::Target::Wgsl, 0, false}},
};

struct StageInfo {
  doublet::Stage stage;
  EShLanguage language;
};
const std::map<std::string, StageInfo> kStages = {
    {"vert", {doublet::Stage::Vertex, EShLangVertex}},
    {"frag", {doublet::Stage::Fragment, EShLangFragment}},
    {"comp", {doublet::Stage::Compute, EShLangCompute}},
    {"geom", {doublet::Stage::Geometry, EShLangGeometry}},
    {"tesc", {doublet::Stage::TessControl, EShLangTessControl}},
    {"tese", {doublet::Stage::TessEvaluation, EShLangTessEvaluation}},
};

struct GoldenParam {
  std::string name;    // case name: file name without the stage extension
  std::string stage;   // "vert" | "frag" | "comp"
  std::string target;  // as written in the targets line (may be unknown)

  std::string case_file() const { return name + "." + stage; }
  std::string expected_file() const { return name + "." + stage + (target == "wgsl" ? ".wgsl" : "." + target + ".glsl"); }
  std::string errors_file() const { return name + "." + stage + "." + target + ".errors"; }
};

// Short form for test listings (instead of a byte dump).
void PrintTo(const GoldenParam& p, std::ostream* os) { *os << p.expected_file(); }

bool update_mode() {
  const char* v = std::getenv("DOUBLET_UPDATE_GOLDEN");
  return v != nullptr && std::string(v) == "1";
}

std::optional<std::string> read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  if (!f) return std::nullopt;
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

const std::regex& targets_line_re() {
  static const std::regex re(R"(^\s*//\s*targets\s*:(.*)$)");
  return re;
}

std::string first_line(const std::string& source) {
  std::string line = source.substr(0, source.find('\n'));
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

// An optional `// options: --mode MODE --mode-for NAME=MODE ...` line, first or right after
// the targets line: the precision modes the case is lowered with (docs/modes.md).
const std::regex& options_line_re() {
  static const std::regex re(R"(^\s*//\s*options\s*:(.*)$)");
  return re;
}

// The source handed to the compiler: without the targets and options lines.
std::string case_source_for_lowering(std::string source) {
  for (int header = 0; header < 2; ++header) {
    std::string line = first_line(source);
    if (!std::regex_match(line, targets_line_re()) && !std::regex_match(line, options_line_re())) break;
    size_t nl = source.find('\n');
    source = nl == std::string::npos ? std::string() : source.substr(nl + 1);
  }
  return source;
}

// Applies the options line, if any. Returns a description of a malformed line, or "".
std::string apply_case_options(const std::string& source, doublet::Options& options) {
  std::istringstream lines(source);
  std::string line;
  for (int header = 0; header < 2 && std::getline(lines, line); ++header) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::smatch m;
    if (!std::regex_match(line, m, options_line_re())) continue;
    std::istringstream words(m[1].str());
    for (std::string flag, value; words >> flag;) {
      if (!(words >> value)) return "option '" + flag + "' needs a value";
      if (flag == "--mode") {
        auto mode = doublet::parse_mode(value);
        if (!mode) return "unknown mode '" + value + "'";
        options.mode = *mode;
      } else if (flag == "--mode-for") {
        size_t eq = value.find('=');
        auto mode = eq == std::string::npos ? std::nullopt : doublet::parse_mode(value.substr(eq + 1));
        if (!mode) return "--mode-for needs NAME=MODE, got '" + value + "'";
        options.mode_for.emplace_back(value.substr(0, eq), *mode);
      } else {
        return "unknown option '" + flag + "' (known: --mode, --mode-for)";
      }
    }
  }
  return "";
}

// Targets from a `// targets: a b c` first line, else the defaults.
std::vector<std::string> case_targets(const std::string& source) {
  std::string first = first_line(source);
  std::smatch m;
  if (!std::regex_match(first, m, targets_line_re())) return kDefaultTargets;
  std::vector<std::string> targets;
  std::istringstream words(std::regex_replace(m[1].str(), std::regex(","), " "));
  for (std::string w; words >> w;)
    if (std::find(targets.begin(), targets.end(), w) == targets.end()) targets.push_back(w);
  return targets;
}

// (name, stage) of every case file, sorted.
std::vector<std::pair<std::string, std::string>> case_files() {
  std::vector<std::pair<std::string, std::string>> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kCasesDir, ec)) {
    if (!e.is_regular_file()) continue;
    std::string ext = e.path().extension().string();
    if (ext.size() < 2 || !kStages.count(ext.substr(1))) continue;
    files.emplace_back(e.path().stem().string(), ext.substr(1));
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<GoldenParam> discover() {
  std::vector<GoldenParam> params;
  for (const auto& [name, stage] : case_files()) {
    std::string source = read_file(kCasesDir / (name + "." + stage)).value_or("");
    for (const std::string& t : case_targets(source)) params.push_back({name, stage, t});
  }
  return params;
}

std::string param_name(const ::testing::TestParamInfo<GoldenParam>& info) {
  std::string s = info.param.name + "_" + info.param.stage + "_" + info.param.target;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

std::string strip_comments(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size();) {
    if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      size_t end = s.find("*/", i + 2);
      i = end == std::string::npos ? s.size() : end + 2;
      out += ' ';
    } else {
      out += s[i++];
    }
  }
  return out;
}

class GlslangProcess : public ::testing::Environment {
 public:
  void SetUp() override { glslang::InitializeProcess(); }
  void TearDown() override { glslang::FinalizeProcess(); }
};
[[maybe_unused]] ::testing::Environment* const kGlslangEnv =
    ::testing::AddGlobalTestEnvironment(new GlslangProcess);

// Checks one expected file on its own terms: compiles with glslang for the
// target's version/profile, declares that version, has no double tokens.
// Mode native (an options line) keeps the doubles on purpose; every other mode removes them.
void validate_expected(const std::string& file, const std::string& text, const StageInfo& stage,
                       const TargetInfo& target, bool keeps_doubles = false) {
  SCOPED_TRACE("validating expected/" + file);

  if (target.version == 0) {  // WGSL
    EXPECT_EQ(text.find("f64"), std::string::npos) << "WGSL has no f64";
    return;
  }
  const std::string code = strip_comments(text);
  static const std::regex doubles(R"(\b(double|dvec[234]|dmat[234](x[234])?)\b)");
  std::smatch m;
  if (keeps_doubles)
    EXPECT_TRUE(std::regex_search(code, m, doubles)) << "mode native output has no double left";
  else
    EXPECT_FALSE(std::regex_search(code, m, doubles)) << "contains the token '" << m.str() << "'";

  // The #version directive must name exactly the target (GLSL ES 1.00 may omit it).
  static const std::regex version_re(R"((^|\n)[ \t]*#[ \t]*version[ \t]+(\d+)[ \t]*(\w*))");
  if (std::regex_search(code, m, version_re)) {
    EXPECT_EQ(std::stoi(m[2].str()), target.version) << "wrong #version";
    std::string profile = m[3].str();
    if (target.es && target.version >= 300)
      EXPECT_EQ(profile, "es") << "#version " << target.version << " needs 'es'";
    else if (target.es)
      EXPECT_EQ(profile, "") << "#version 100 takes no profile";
    else
      EXPECT_TRUE(profile.empty() || profile == "core") << "desktop targets are core profile";
  } else {
    EXPECT_EQ(target.version, 100) << "no #version directive";
  }

  glslang::TShader shader(stage.language);
  const char* strings[] = {text.c_str()};
  const char* names[] = {file.c_str()};
  shader.setStringsWithLengthsAndNames(strings, nullptr, names, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, stage.language, glslang::EShClientNone, 0);
  shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  const EProfile profile = target.es ? EEsProfile : ECoreProfile;
  // glslang's default table allows one atomic-counter binding; drivers offer 8 or more.
  TBuiltInResource limits = *GetDefaultResources();
  limits.maxAtomicCounterBindings = limits.maxCombinedAtomicCounterBuffers = 8;
  limits.maxVertexAtomicCounterBuffers = limits.maxFragmentAtomicCounterBuffers = 8;
  limits.maxComputeAtomicCounterBuffers = 8;
  const bool parsed = shader.parse(&limits, target.version, profile,
                                   /*forceDefaultVersionAndProfile=*/false,
                                   /*forwardCompatible=*/false, EShMsgDefault);
  EXPECT_TRUE(parsed) << "glslang rejects it:\n" << shader.getInfoLog() << shader.getInfoDebugLog();
}

class Golden : public ::testing::TestWithParam<GoldenParam> {};

TEST_P(Golden, Matches) {
  const GoldenParam& p = GetParam();
  auto target_it = kTargets.find(p.target);
  ASSERT_NE(target_it, kTargets.end())
      << "cases/" << p.case_file() << ": unknown target '" << p.target << "' in the targets line";
  const TargetInfo& target = target_it->second;
  const StageInfo& stage = kStages.at(p.stage);

  std::optional<std::string> source = read_file(kCasesDir / p.case_file());
  ASSERT_TRUE(source) << "cannot read cases/" << p.case_file() << " (re-run cmake after removing a case)";

  doublet::Options options;
  options.stage = stage.stage;
  options.target = target.target;
  options.file_name = "cases/" + p.case_file();
  options.check_ir = true;  // the IR is checked after every pass (src/ir/check.hpp)
  options.include_dirs = {(kCasesDir / "include").string()};  // engine-style shared headers (#include "x.glsl")
  std::string bad_options = apply_case_options(*source, options);
  ASSERT_EQ(bad_options, "") << "cases/" << p.case_file() << ": bad options line";
  doublet::Result result = doublet::lower(case_source_for_lowering(*source), options);
  std::string diagnostics;
  for (const doublet::Diagnostic& d : result.diagnostics) diagnostics += doublet::format_diagnostic(d) + "\n";

  // A case the target refuses: the errors, each positioned, are the expected output (to add one,
  // create the empty .errors file, then update).
  const fs::path errors_path = kExpectedDir / p.errors_file();
  if (std::optional<std::string> errors = read_file(errors_path)) {
    std::string error_lines;
    for (const doublet::Diagnostic& d : result.diagnostics)
      if (d.severity == doublet::Severity::Error) error_lines += doublet::format_diagnostic(d) + "\n";
    EXPECT_FALSE(result.ok) << "expected the errors of expected/" << p.errors_file() << ", got output";
    if (update_mode()) {
      std::ofstream(errors_path, std::ios::binary | std::ios::trunc) << error_lines;
      return;
    }
    EXPECT_EQ(*errors, error_lines);
    std::istringstream lines(error_lines);
    for (std::string line; std::getline(lines, line);)
      EXPECT_TRUE(std::regex_search(line, std::regex(R"(^cases/[^:]+:\d+:\d+: error: )"))) << line;
    return;
  }
  EXPECT_TRUE(result.ok) << "doublet::lower failed:\n" << diagnostics;

  const fs::path expected_path = kExpectedDir / p.expected_file();
  std::optional<std::string> expected = read_file(expected_path);

  if (update_mode()) {
    ASSERT_TRUE(result.ok) << "not writing expected/" << p.expected_file();
    if (expected != result.output) {
      fs::create_directories(kExpectedDir);
      std::ofstream out(expected_path, std::ios::binary | std::ios::trunc);
      out << result.output;
      out.close();
      ASSERT_TRUE(out) << "cannot write " << expected_path;
      std::cout << "[golden] wrote expected/" << p.expected_file() << std::endl;
    } else {
      std::cout << "[golden] unchanged expected/" << p.expected_file() << std::endl;
    }
    validate_expected(p.expected_file(), result.output, stage, target, options.mode == doublet::Mode::Native);
    return;
  }

  ASSERT_TRUE(expected) << "missing expected/" << p.expected_file()
                        << "\n  create it with: DOUBLET_UPDATE_GOLDEN=1 ctest --test-dir build -R '^golden\\.'"
                        << "\n  (then review and commit it)";
  validate_expected(p.expected_file(), *expected, stage, target, options.mode == doublet::Mode::Native);
  if (result.ok) {
    EXPECT_EQ(*expected, result.output)
        << "output differs from expected/" << p.expected_file()
        << "\n  if the change is intended: DOUBLET_UPDATE_GOLDEN=1 ctest --test-dir build -R '^golden\\.'";
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, Golden, ::testing::ValuesIn(discover()), param_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Golden);

// Expected files must belong to an existing case and one of its targets.
TEST(GoldenFiles, NoOrphanedExpectedFiles) {
  std::set<std::string> wanted;
  for (const GoldenParam& p : discover()) wanted.insert({p.expected_file(), p.errors_file()});
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(kExpectedDir, ec)) {
    std::string name = e.path().filename().string();
    if (name.starts_with(".")) continue;
    EXPECT_TRUE(wanted.count(name)) << "expected/" << name
                                    << " has no case/target (stale? delete it, or fix the targets line)";
  }
}

// Test names are derived from case names; two cases must not collide.
TEST(GoldenFiles, TestNamesAreUnique) {
  std::map<std::string, std::string> seen;
  for (const GoldenParam& p : discover()) {
    std::string n = param_name(::testing::TestParamInfo<GoldenParam>(p, 0));
    auto [it, inserted] = seen.emplace(n, p.expected_file());
    EXPECT_TRUE(inserted) << p.expected_file() << " and " << it->second << " map to test name " << n;
  }
}

}  // namespace
