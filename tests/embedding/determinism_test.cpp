// Determinism of doublet::lower (docs/robustness.md "Determinism"): the same input gives
// byte-identical output and manifest whatever the thread count, the process locale (an
// embedding application may call setlocale / std::locale::global) or the path the shader
// is read from. The CLI side (-j1 vs -j4) is tests/cli/determinism_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <locale>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "doublet/doublet.hpp"

namespace {
namespace fs = std::filesystem;

struct Case {
  std::string name;
  std::string source;
  doublet::Options options;
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every golden case and example shader, for several targets (failures included: their
// diagnostics must be stable too).
std::vector<Case> corpus() {
  std::vector<Case> cases;
  const fs::path root = DOUBLET_SOURCE_DIR;
  for (const char* dir : {"tests/golden/cases", "examples"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
      auto stage = doublet::stage_from_path(entry.path().string());
      if (!entry.is_regular_file() || !stage) continue;
      for (doublet::Target t : {doublet::Target::Es100, doublet::Target::Es300, doublet::Target::Es310,
                                doublet::Target::Glsl330, doublet::Target::Glsl450, doublet::Target::Webgl2}) {
        Case c;
        c.name = entry.path().lexically_relative(root).string() + " -> " + std::string(doublet::to_string(t));
        c.source = read(entry.path());
        c.options.stage = stage;
        c.options.target = t;
        c.options.file_name = entry.path().string();
        c.options.include_dirs = {(root / "examples/cmake-consumer/shaders/include").string()};
        cases.push_back(std::move(c));
      }
    }
  }
  std::sort(cases.begin(), cases.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
  return cases;
}

std::string fingerprint(const doublet::Result& r) {
  std::string s = r.ok ? "ok\n" : "failed\n";
  s += r.output + "\n--manifest--\n" + (r.ok ? r.manifest.to_json() : std::string());
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

// Lowers every case on `threads` threads, each taking every threads-th case.
std::vector<std::string> lower_all(const std::vector<Case>& cases, int threads) {
  std::vector<std::string> out(cases.size());
  std::vector<std::jthread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (size_t i = static_cast<size_t>(t); i < cases.size(); i += static_cast<size_t>(threads))
        out[i] = fingerprint(doublet::lower(cases[i].source, cases[i].options));
    });
  pool.clear();  // joins
  return out;
}

// The reference: one thread, the classic "C" locale.
const std::vector<std::string>& reference() {
  static const std::vector<std::string> ref = lower_all(corpus(), 1);
  return ref;
}

// The first line where two texts differ, for a readable failure.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    bool more_a = static_cast<bool>(std::getline(x, la)), more_b = static_cast<bool>(std::getline(y, lb));
    if (!more_a && !more_b) return "identical";
    if (la != lb || more_a != more_b)
      return "line " + std::to_string(line) + ":\n  got:      " + la.substr(0, 300) + "\n  expected: " + lb.substr(0, 300);
  }
}

void expect_same(const std::vector<std::string>& got, const std::string& how) {
  const std::vector<Case> cases = corpus();
  ASSERT_EQ(got.size(), reference().size());
  for (size_t i = 0; i < got.size(); ++i)
    EXPECT_TRUE(got[i] == reference()[i]) << how << ": " << cases[i].name << " differs at "
                                          << first_difference(got[i], reference()[i]);
}

TEST(Determinism, CorpusLowersAndSucceedsOften) {
  const auto& ref = reference();
  ASSERT_GE(ref.size(), 100u) << "the corpus is unexpectedly small";
  size_t ok = std::count_if(ref.begin(), ref.end(), [](const std::string& s) { return s.starts_with("ok"); });
  EXPECT_GE(ok, 60u) << "too few shaders lowered to prove anything";
}

TEST(Determinism, OneAndEightThreadsAgree) {
  expect_same(lower_all(corpus(), 8), "8 threads");
  expect_same(lower_all(corpus(), 1), "1 thread, again");
}

// A C++ locale that writes 1234.5 as "1.234,5": what std::locale::global(std::locale("de_DE"))
// does to streams, available everywhere.
struct GermanPunct : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

TEST(Determinism, GlobalCppLocaleChangesNothing) {
  std::locale previous = std::locale::global(std::locale(std::locale::classic(), new GermanPunct));
  std::ostringstream probe;
  probe << 1234.5;
  std::vector<std::string> got = lower_all(corpus(), 4);
  std::locale::global(previous);
  ASSERT_EQ(probe.str(), "1.234,5") << "the test locale is not in effect";
  expect_same(got, "std::locale::global with ',' decimals and '.' grouping");
}

// Digit grouping would turn local_size_x = 1024 into "1.024" (no shader in the corpus is
// that wide).
TEST(Determinism, GroupingLocaleKeepsLargeNumbersWhole) {
  doublet::Options o;
  o.stage = doublet::Stage::Compute;
  o.target = doublet::Target::Es310;
  const std::string source =
      "#version 310 es\nlayout(local_size_x = 1024) in;\nlayout(std430, binding = 0) buffer B { double v[]; };\n"
      "void main() { v[gl_GlobalInvocationID.x] *= 12345678.0lf; }\n";
  doublet::Result classic = doublet::lower(source, o);
  std::locale previous = std::locale::global(std::locale(std::locale::classic(), new GermanPunct));
  doublet::Result german = doublet::lower(source, o);
  std::locale::global(previous);
  ASSERT_TRUE(classic.ok);
  EXPECT_NE(classic.output.find("local_size_x = 1024"), std::string::npos) << classic.output.substr(0, 400);
  EXPECT_EQ(german.output, classic.output) << first_difference(german.output, classic.output);
}

// The C locale (printf, strtod) of a German user: setlocale(LC_ALL, "de_DE.UTF-8"), compiled
// into a scratch LOCPATH with localedef when the system has none installed.
TEST(Determinism, CLocaleWithDecimalCommaChangesNothing) {
  const std::string saved = std::setlocale(LC_ALL, nullptr);
  const char* saved_locpath = std::getenv("LOCPATH");
  const std::string saved_locpath_value = saved_locpath ? saved_locpath : "";
  fs::path scratch;
  if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) {
    scratch = fs::temp_directory_path() / ("doublet-locale-" + std::to_string(::getpid()));
    fs::create_directories(scratch);
    std::string cmd = "localedef -i de_DE -f UTF-8 '" + (scratch / "de_DE.UTF-8").string() + "' >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == -1 || !fs::exists(scratch / "de_DE.UTF-8" / "LC_NUMERIC")) {
      fs::remove_all(scratch);
      GTEST_SKIP() << "no de_DE locale and localedef cannot build one (Debian: the locales package)";
    }
    ::setenv("LOCPATH", scratch.c_str(), 1);
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) {
      fs::remove_all(scratch);
      GTEST_SKIP() << "setlocale(de_DE.UTF-8) failed even with LOCPATH";
    }
  }
  char probe[32];
  std::snprintf(probe, sizeof probe, "%g", 0.5);
  std::vector<std::string> got = lower_all(corpus(), 4);
  std::setlocale(LC_ALL, saved.c_str());
  if (saved_locpath) ::setenv("LOCPATH", saved_locpath_value.c_str(), 1);
  else ::unsetenv("LOCPATH");
  if (!scratch.empty()) fs::remove_all(scratch);
  ASSERT_STREQ(probe, "0,5") << "the test locale is not in effect";
  expect_same(got, "setlocale(LC_ALL, \"de_DE.UTF-8\")");
}

// Another machine keeps the same shaders elsewhere: the output and manifest must not depend
// on the path (only diagnostics name the file).
TEST(Determinism, PathOfTheInputDoesNotReachTheOutput) {
  size_t compared = 0;
  for (const Case& c : corpus()) {
    Case moved = c;
    moved.options.file_name = "/elsewhere/on/another/machine/" + fs::path(c.options.file_name).filename().string();
    // Its #include "x" files would be there too; here they are found through -I.
    moved.options.include_dirs.push_back(fs::path(c.options.file_name).parent_path().string());
    doublet::Result a = doublet::lower(c.source, c.options), b = doublet::lower(moved.source, moved.options);
    EXPECT_EQ(a.ok, b.ok) << c.name;
    if (!a.ok || !b.ok) continue;
    EXPECT_EQ(a.output, b.output) << c.name;
    EXPECT_EQ(a.manifest.to_json(), b.manifest.to_json()) << c.name;
    ++compared;
  }
  EXPECT_GE(compared, 60u);
}

}  // namespace
