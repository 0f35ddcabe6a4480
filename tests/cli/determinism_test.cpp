// `doublet lower` in batch mode writes byte-identical shaders and manifests, and the same
// diagnostics, with -j1 and -j4, for every golden case and example shader and several
// targets (docs/robustness.md "Determinism"; the in-process side is
// tests/embedding/determinism_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "test_support.hpp"

namespace doublet::cli_test {
namespace {
namespace fs = std::filesystem;

bool is_shader(const fs::path& p) {
  for (const char* ext : {".vert", ".frag", ".comp"}) {
    std::string name = p.filename().string();
    if (name.ends_with(ext) || name.ends_with(std::string(ext) + ".glsl")) return true;
  }
  return false;
}

// The corpus as batches: one per directory, since --out-dir names outputs by file name.
std::map<std::string, std::vector<std::string>> batches() {
  std::map<std::string, std::vector<std::string>> out;
  const fs::path root = DOUBLET_SOURCE_DIR;
  for (const char* dir : {"tests/golden/cases", "examples"})
    for (const auto& e : fs::recursive_directory_iterator(root / dir))
      if (e.is_regular_file() && is_shader(e.path()))
        out[e.path().parent_path().lexically_relative(root).string()].push_back(
            e.path().lexically_relative(root).string());
  for (auto& [dir, files] : out) std::sort(files.begin(), files.end());
  return out;
}

// Every file under `dir`, by relative name.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[e.path().lexically_relative(dir).string()] = read_file(e.path());
  return out;
}

TEST(CliDeterminism, OneAndFourJobsWriteTheSameBytes) {
  ScratchDir scratch;
  const auto corpus = batches();
  size_t inputs = 0;
  for (const auto& [dir, files] : corpus) inputs += files.size();
  ASSERT_GE(inputs, 20u) << "the corpus is unexpectedly small";
  std::map<std::string, std::string> results[2];
  for (const char* target : {"es300", "es310", "glsl450"}) {
    int batch = 0;
    for (const auto& [dir, files] : corpus) {
      ++batch;
      for (int run = 0; run < 2; ++run) {
        const std::string jobs = run == 0 ? "1" : "4";
        const fs::path out = scratch / ("j" + jobs) / target / std::to_string(batch);
        std::vector<std::string> args{"lower", "--target", target, "--out-dir", out.string(), "-j", jobs,
                                      "-I", "examples/cmake-consumer/shaders/include"};
        args.insert(args.end(), files.begin(), files.end());
        ProcessResult r = run_process(DOUBLET_CLI_PATH, args, DOUBLET_SOURCE_DIR);
        const std::string key = std::string(target) + " " + dir;
        results[run][key + " status"] = std::to_string(r.exit_code);
        results[run][key + " stderr"] = r.err;
        if (fs::exists(out))
          for (const auto& [name, text] : contents(out)) results[run][key + "/" + name] = text;
      }
    }
  }
  size_t shaders = 0;
  for (const auto& [name, text] : results[0]) shaders += name.ends_with(".json");
  EXPECT_GE(shaders, 40u) << "too few shaders lowered to prove anything";
  ASSERT_EQ(results[0].size(), results[1].size());
  for (const auto& [name, text] : results[0]) {
    auto other = results[1].find(name);
    ASSERT_NE(other, results[1].end()) << name << " only written with -j1";
    EXPECT_EQ(text, other->second) << name << " differs between -j1 and -j4";
  }
}

}  // namespace
}  // namespace doublet::cli_test
