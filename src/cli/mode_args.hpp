// --mode MODE and --mode-for NAME=MODE (repeatable), shared by `doublet lower` and `doublet verify`.
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace doublet::cli {

inline constexpr const char* kModeNames = "fp32, rte, df64-fast, df64, df64-int, native, exact or rte-exact";

// Fills options.mode / options.mode_for; returns the usage error, or "" when both parse.
inline std::string apply_mode_args(const std::string& mode, const std::vector<std::string>& mode_for,
                                   Options& options) {
  if (!mode.empty()) {
    std::optional<Mode> m = parse_mode(mode);
    if (!m) return "--mode: unknown mode '" + mode + "' (expected " + kModeNames + ")";
    options.mode = *m;
  }
  for (const std::string& entry : mode_for) {
    size_t eq = entry.find('=');
    if (eq == std::string::npos || eq == 0)
      return "--mode-for: expected NAME=MODE (NAME a global, a function or FUNCTION.LOCAL), got '" + entry + "'";
    std::string name = entry.substr(0, eq), value = entry.substr(eq + 1);
    std::optional<Mode> m = parse_mode(value);
    if (!m) return "--mode-for " + entry + ": unknown mode '" + value + "' (expected " + kModeNames + ")";
    options.mode_for.emplace_back(name, *m);
  }
  return {};
}

// Puts the modes of a plan file (`doublet plan`) under the command line's: the plan's mode is
// taken unless --mode chose another than the default df64, and the plan's entries go before the
// --mode-for entries, so those (later) win.
inline void merge_plan_modes(const Options& plan, Options& options) {
  if (options.mode == Mode::Df64) options.mode = plan.mode;
  options.mode_for.insert(options.mode_for.begin(), plan.mode_for.begin(), plan.mode_for.end());
}

}  // namespace doublet::cli
