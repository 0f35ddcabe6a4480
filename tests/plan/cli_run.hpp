// Runs the doublet CLI with stdout and stderr captured together (plan tests), through the
// CLI tests' process runner (tests/cli/test_support.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "test_support.hpp"

namespace plan_test {

using ::doublet::cli_test::read_file;
using ::doublet::cli_test::write_file;

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr, interleaved as the program wrote them
};

// `args` is split by the shell, like a command line typed in a terminal.
inline CliRun run_doublet(const std::string& args) {
  const auto r = ::doublet::cli_test::run_process(
      "/bin/sh", {"-c", std::string(DOUBLET_CLI_PATH) + " " + args + " 2>&1"}, std::filesystem::current_path());
  return {r.exit_code, r.out};
}

const std::string kScenes = DOUBLET_SCENES;

}  // namespace plan_test
