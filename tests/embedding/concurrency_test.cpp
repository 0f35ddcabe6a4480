// doublet::lower from many threads at once gives byte-identical results to sequential
// runs (glslang is initialised once; nothing else is shared), and no exception escapes
// for any shader of the test corpus.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

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

// Every shader under tests/golden/cases and examples/, for several targets: successes
// and failures (e.g. compute for es300) both count, their diagnostics are compared too.
std::vector<Case> corpus() {
  std::vector<Case> cases;
  const fs::path root = DOUBLET_SOURCE_DIR;
  for (const char* dir : {"tests/golden/cases", "examples"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / dir)) {
      auto stage = doublet::stage_from_path(entry.path().string());
      if (!entry.is_regular_file() || !stage) continue;
      for (doublet::Target t : {doublet::Target::Es300, doublet::Target::Es310, doublet::Target::Es320,
                                doublet::Target::Glsl450}) {
        Case c;
        c.name = entry.path().lexically_relative(root).string() + " → " + std::string(doublet::to_string(t));
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

// Everything a Result says, as one string.
std::string fingerprint(const doublet::Result& r) {
  std::string s = r.ok ? "ok\n" : "failed\n";
  s += r.output + "\n--manifest--\n" + (r.ok ? r.manifest.to_json() : std::string());
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  for (const auto& f : r.included_files) s += "included " + f + "\n";
  return s;
}

std::string lower_without_throwing(const Case& c) {
  try {
    return fingerprint(doublet::lower(c.source, c.options));
  } catch (...) {
    return "EXCEPTION ESCAPED";
  }
}

TEST(Concurrency, EightThreadsGiveTheSequentialResults) {
  const std::vector<Case> cases = corpus();
  ASSERT_GE(cases.size(), 40u) << "the corpus is unexpectedly small";
  std::vector<std::string> expected;
  int successes = 0;
  for (const Case& c : cases) {
    expected.push_back(lower_without_throwing(c));
    ASSERT_NE(expected.back(), "EXCEPTION ESCAPED") << c.name;
    successes += expected.back().starts_with("ok");
  }
  ASSERT_GE(successes, 20) << "too few shaders lowered to prove anything";

  // Each thread lowers the whole corpus, starting at a different place, so the same
  // shader is lowered by several threads at the same moment.
  constexpr int kThreads = 8;
  std::vector<std::vector<std::string>> got(kThreads, std::vector<std::string>(cases.size()));
  {
    std::vector<std::jthread> threads;
    for (int t = 0; t < kThreads; ++t)
      threads.emplace_back([&, t] {
        for (size_t k = 0; k < cases.size(); ++k) {
          size_t i = (k + t * cases.size() / kThreads) % cases.size();
          got[t][i] = lower_without_throwing(cases[i]);
        }
      });
  }
  for (int t = 0; t < kThreads; ++t)
    for (size_t i = 0; i < cases.size(); ++i)
      EXPECT_EQ(got[t][i], expected[i]) << "thread " << t << ", " << cases[i].name;
}

}  // namespace
