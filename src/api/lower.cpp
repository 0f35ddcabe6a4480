// doublet::lower, the library's entry point: resolve the Config, run the pass table
// (pipeline/pipeline.hpp, docs/architecture.md), on a thread with a big stack, with every failure a
// diagnostic.
#include <algorithm>
#include <exception>

#include "doublet/doublet.hpp"
#include "frontend/read_limited.hpp"
#include "pipeline/config.hpp"
#include "pipeline/pipeline.hpp"
#include "support/big_stack.hpp"
#include "support/c_locale.hpp"

namespace doublet {
namespace {

// The compiler, in order: refuse what the options cannot mean, then the passes of the table.
Result lower_unchecked(std::string_view source, const Options& options) {
  ScopedCLocale c_locale;  // '.' in every number printed or read, whatever the application's locale
  Result result;
  const std::optional<pipeline::Config> config = pipeline::resolve_config(options, result.diagnostics);
  if (!config) return result;
  pipeline::State state(*config, options, source, result);
  pipeline::run(state);
  return result;
}

// A file of 80,000 faulty lines gives 80,000 diagnostics: report the first
// kMaxDiagnostics and say how many more there were.
constexpr std::size_t kMaxDiagnostics = 100;

void cap_diagnostics(std::vector<Diagnostic>& diags, const std::string& file_name) {
  if (diags.size() <= kMaxDiagnostics) return;
  const auto hidden_errors = std::count_if(diags.begin() + kMaxDiagnostics, diags.end(),
                                           [](const Diagnostic& d) { return d.severity == Severity::Error; });
  const std::size_t hidden = diags.size() - kMaxDiagnostics;
  diags.resize(kMaxDiagnostics);
  diags.push_back({file_name, 0, 0, Severity::Note,
                   std::to_string(hidden) + " more diagnostics not shown (" + std::to_string(hidden_errors) +
                       " errors): fix the first ones and run again"});
}

}  // namespace

Result lower(std::string_view source, const Options& options) {
  try {
    if (source.size() > kMaxSourceBytes) {
      Result r;
      r.diagnostics.push_back({options.file_name, 1, 1, Severity::Error, frontend::source_too_large_message("input")});
      return r;
    }
    if (std::size_t depth = max_statement_operators(source); depth > kMaxStatementOperators) {
      Result r;
      r.diagnostics.push_back({options.file_name, 1, 1, Severity::Error, too_many_operators_message(depth, false)});
      return r;
    }
    Result result;
    std::exception_ptr failure;
    bool ran = run_with_big_stack([&] {
      try {
        result = lower_unchecked(source, options);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    if (!ran) result = lower_unchecked(source, options);
    if (failure) std::rethrow_exception(failure);
    cap_diagnostics(result.diagnostics, options.file_name);
    return result;
  } catch (const std::exception& e) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error, std::string("internal error: ") + e.what()});
    return r;
  } catch (...) {
    Result r;
    r.diagnostics.push_back({options.file_name, 0, 0, Severity::Error, "internal error"});
    return r;
  }
}

}  // namespace doublet
