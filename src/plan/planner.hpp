// `doublet plan`: from a shader and a scene to a plan (Options::mode / mode_for), the table the
// CLI prints, and the plan file (docs/plan.md). The analysis is plan/analysis.hpp.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "doublet/doublet.hpp"
#include "plan/interval.hpp"
#include "plan/scene.hpp"

namespace doublet::plan {

struct PlanRow {
  std::string name;      // "eye", "main.rel", "main()"
  std::string kind;      // "input", "output", "local", "parameter", "global", "function"
  int line = 0;
  Interval range;        // hull over components (functions: unused)
  double budget = kInf;  // error the outputs tolerate on this value alone
  double bits = 0;       // log2(max|v| / budget) + 1 margin bit; 0 when nothing depends on it
  Mode mode = Mode::Df64;
  double flops = 0;      // of the assignments to it (functions: of the body), in `mode`
  std::string note;
};

struct OutputRow {
  std::string name;
  double required = 0;
  double estimate = 0;       // with the plan
  double estimate_df64 = 0;  // everything df64
  double estimate_fp32 = 0;  // everything fp32
  double estimate_exact = 0; // everything binary64 (mode exact)
};

struct PlanOutcome {
  bool ok = false;                       // false: diagnostics say why (bad shader or scene names)
  std::vector<Diagnostic> diagnostics;
  bool feasible = false;                 // every output's estimate within its requirement (df64, or exact)
  std::vector<PlanRow> rows;
  std::vector<OutputRow> outputs;
  std::vector<std::string> notes;
  Mode mode = Mode::Df64;
  std::vector<std::pair<std::string, Mode>> mode_for;
  double flops_df64 = 0, flops_plan = 0;
};

PlanOutcome make_plan(std::string_view source, const Options& options, const Scene& scene);

std::string format_table(const PlanOutcome& plan);
std::string plan_to_json(const PlanOutcome& plan);  // {"version": 1, "mode": ..., "mode_for": {...}}

// Reads a plan file into options->mode / mode_for. False with a file:line:col diagnostic.
bool load_plan(std::string_view text, const std::string& file, Options* options, Diagnostic* error);

}  // namespace doublet::plan
