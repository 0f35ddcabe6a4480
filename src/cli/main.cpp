// doublet — command-line front end. See `doublet --help`.
#include <exception>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "gcc_style_args.hpp"
#include "standard_fds.hpp"

#ifndef DOUBLET_VERSION
#define DOUBLET_VERSION "unknown"
#endif

namespace doublet::cli {

int usage_error(const CLI::App& command, std::string_view message) {
  std::string path = command.get_name();
  for (const CLI::App* p = command.get_parent(); p != nullptr; p = p->get_parent())
    path = p->get_name() + " " + path;
  std::cerr << path << ": error: " << message << "\nRun with --help for more information.\n";
  return kExitUsage;
}

}  // namespace doublet::cli

int main(int argc, char** argv) {
  using namespace doublet::cli;
  open_closed_standard_fds();              // before anything opens a file (`2>&-`)
  remove_temp_files_on_fatal_signals();    // Ctrl-C or kill mid-batch leaves no .dbl-* file
  CLI::App app{"doublet " DOUBLET_VERSION
               " - lowers GLSL doubles (double, dvec2-4) to float-float GLSL ES / desktop GLSL",
               "doublet"};
  app.set_version_flag("--version", "doublet " DOUBLET_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  doublet lower globe.vert -o globe.es300.vert --manifest globe.json\n"
      "  doublet lower a.vert b.frag c.comp --out-dir lowered -MD\n"
      "  doublet lower --help\n"
      "\n"
      "Exit status: 0 success, 1 usage error, 2 input/output or compile error.");

  std::vector<Command> commands;
  commands.push_back(add_lower_command(app));
#ifndef DOUBLET_LOWER_ONLY  // the WebAssembly build (wasm/CMakeLists.txt) has no drivers to run
  commands.push_back(add_verify_command(app));
  commands.push_back(add_bench_command(app));
  commands.push_back(add_demo_command(app));
  commands.push_back(add_plan_command(app));
#endif

  try {
    // -MD/-MF/-MT (GCC's spelling) become --MD/--MF/--MT for CLI11.
    std::vector<std::string> args = rewrite_gcc_style_args(argc, argv);
    std::vector<const char*> arg_ptrs;
    for (const std::string& a : args) arg_ptrs.push_back(a.c_str());
    app.parse(static_cast<int>(arg_ptrs.size()), arg_ptrs.data());
  } catch (const CLI::ParseError& e) {
    // --help / --version exit 0; every real parse error is a usage error.
    int rc = app.exit(e);
    return rc == 0 ? kExitOk : kExitUsage;
  }

  try {
    for (const Command& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const std::exception& e) {
    std::cerr << "doublet: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  return usage_error(app, "no command given");
}
