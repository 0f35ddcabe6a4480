// `doublet plan SHADER --scene FILE [-o PLAN.json]`: range and error analysis of SHADER under the
// scene's input ranges and output precisions; prints the table and writes the plan file that
// `doublet lower --plan` applies (docs/plan.md). The work is plan::make_plan().
#include <iostream>

#include <CLI/CLI.hpp>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "input_file.hpp"
#include "plan/planner.hpp"

namespace doublet::cli {
namespace {

struct PlanArgs {
  std::string shader, scene, output, stage;
  std::vector<std::string> defines, include_dirs;
};

// Exit 1 (docs/plan.md): the scene's precision cannot be promised even with df64 everywhere.
constexpr int kExitInfeasible = 1;


int input_error(const std::string& message) {
  std::cerr << "doublet plan: error: " << message << "\n";
  return kExitInput;
}

int run_plan(const PlanArgs& a) {
  Options o;
  o.file_name = a.shader;
  o.stage = a.stage.empty() ? stage_from_path(a.shader) : parse_stage(a.stage);
  if (!o.stage) return input_error("cannot tell the stage of '" + a.shader + "': use -S vert|frag|comp|geom|tesc|tese");
  for (const std::string& d : a.defines) {
    const size_t eq = d.find('=');
    o.defines.emplace_back(d.substr(0, eq), eq == std::string::npos ? "1" : d.substr(eq + 1));
  }
  o.include_dirs = a.include_dirs;
  std::string source, scene_text;
  if (std::string e = read_input_file(a.shader, source); !e.empty()) return input_error("cannot read '" + a.shader + "': " + e);
  if (std::string e = read_input_file(a.scene, scene_text); !e.empty()) return input_error("cannot read scene '" + a.scene + "': " + e);
  plan::Scene scene;
  Diagnostic d;
  if (!plan::parse_scene(scene_text, a.scene, &scene, &d)) {
    std::cerr << format_diagnostic(d) << "\n";
    return kExitInput;
  }
  const plan::PlanOutcome p = plan::make_plan(source, o, scene);
  for (const Diagnostic& x : p.diagnostics) std::cerr << format_diagnostic(x) << "\n";
  if (!p.ok) return kExitInput;
  std::cout << plan::format_table(p) << std::flush;
  if (!a.output.empty()) {
    AtomicFile file;
    if (!file.prepare(a.output, plan::plan_to_json(p)) || !file.commit())
      return input_error("cannot write '" + a.output + "': " + file.error());
  }
  return p.feasible ? kExitOk : kExitInfeasible;
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Pick the cheapest precision mode per value that meets a scene's output precision (docs/plan.md)");
  cmd->add_option("SHADER", args->shader, "shader file (.vert, .frag or .comp)")->required();
  cmd->add_option("--scene", args->scene, "scene JSON: input ranges, relations, output abs_error")->required();
  cmd->add_option("-o,--output", args->output, "write the plan file (JSON) for `doublet lower --plan`");
  cmd->add_option("-S", args->stage, "stage: vert|frag|comp|geom|tesc|tese (default: from the extension)");
  cmd->add_option("-D", args->defines, "NAME[=VALUE] preprocessor define");
  cmd->add_option("-I", args->include_dirs, "include directory");
  cmd->footer(
      "Example:\n"
      "  doublet plan examples/scenes/globe_rte.vert --scene examples/scenes/globe.scene.json -o globe.plan.json\n"
      "  doublet lower examples/scenes/globe_rte.vert --plan globe.plan.json -o globe.es300.vert\n"
      "\n"
      "Exit status: 0 plan made, 1 usage error or a precision no mode can promise (df64 everywhere\n"
      "is estimated above it; the plan file is still written), 2 bad shader or scene.");
  return Command{cmd, [args] { return run_plan(*args); }};
}

}  // namespace doublet::cli
