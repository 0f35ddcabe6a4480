// The compiler as a sequence of passes (docs/architecture.md): one table of passes, each with a
// name, a test of whether the Config wants it and the function that runs it, executed in order by
// run() — which can stop after any pass and checks the IR between passes when asked.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"
#include "emit/printer.hpp"
#include "frontend/frontend.hpp"
#include "frontend/mode_pragmas.hpp"
#include "ir/ir.hpp"
#include "lower/exact_functions.hpp"
#include "lower/lower.hpp"
#include "pipeline/config.hpp"

namespace doublet::pipeline {

// Everything the passes hand on to each other.
struct State {
  State(const Config& c, const Options& o, std::string_view s, Result& r)
      : config(c), frontend_options(pipeline::frontend_options(o, c)), source(s), result(r), ctx{c, r.diagnostics, s} {}

  const Config& config;
  const Options frontend_options;  // what the front end reads (its target the user's: wgsl, not config.target)
  std::string_view source;
  Result& result;
  frontend::ParsedShader parsed;
  std::vector<frontend::ModePragma> pragmas;
  std::vector<std::string> user_extensions;  // the shader's #extension lines, carried
  ir::Module module;
  passes::Context ctx;  // the passes' requests of the runtime linker, and their diagnostics
  std::unique_ptr<passes::ExactPart> exact;  // exact functions of a float-float shader, if any
  emit::PrintOptions print_options;
  emit::PrintResult printed;
};

struct Pass {
  const char* name;   // for --stop-after, and in internal errors
  const char* phase;  // its share of Result::phase_seconds
  bool (*wanted)(const Config&);
  bool (*run)(State&);
  bool on_ir;  // the pass reads or writes the IR (the IR check runs after it)
};

// The passes, in order.
const std::vector<Pass>& pass_table();

// Runs every wanted pass in order (up to config.stop_after); fills result.
void run(State& state);

// Whether any of `diags` is an error.
bool has_error(const std::vector<Diagnostic>& diags);

}  // namespace doublet::pipeline
