// Subcommands of the `doublet` executable. Each add_*_command registers a CLI11
// subcommand on the top-level app and returns the function that runs it once
// the command line has been parsed.
#pragma once

#include <functional>
#include <string_view>

namespace CLI {
class App;
}

namespace doublet::cli {

// Process exit codes shared by all subcommands.
enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,     // bad command line (unknown option/target, missing -S for stdin, ...)
  kExitInput = 2,     // unreadable/unwritable file or an error diagnostic from the compiler
  kExitInternal = 3,  // a bug: an unexpected exception escaped
};

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

// Prints "doublet <cmd>: error: <message>" plus a --help hint to stderr and
// returns kExitUsage. For usage problems found after CLI11 has parsed.
int usage_error(const CLI::App& command, std::string_view message);

Command add_lower_command(CLI::App& app);
Command add_verify_command(CLI::App& app);  // verify_command.cpp
Command add_bench_command(CLI::App& app);   // bench_command.cpp
Command add_demo_command(CLI::App& app);    // demo_command.cpp
Command add_plan_command(CLI::App& app);    // plan_command.cpp

}  // namespace doublet::cli
