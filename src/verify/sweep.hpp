// Per-operation sweeps (`doublet verify --sweep OP|all`): the lowered operation on a real driver
// against an MPFR reference (256-bit, exact for these inputs), over the input families of
// docs/numerics.md#input-families: a binade grid over both exponents (-126..127), magnitude
// ratios 2^0..2^-60, cancellation a ≈ -b(1 ± 2^-k) for k = 1..60, the CTS fixed values, the
// split-overflow region (|x| > FLT_MAX/4097) and sums near FLT_MAX. Error in bits and in u²
// against the rule's proven bound; a PNG heatmap of min correct bits over (exponent a,
// exponent b) per op.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/sabotage.hpp"

namespace doublet::verify {

struct SweepOptions {
  std::vector<std::string> ops;  // from sweep_ops(); "all" expanded by the caller
  Target target = Target::Es310;
  runner::Backend backend = runner::Backend::Gles;
  int grid_step = 1;             // exponent step of the grid (1: every binade pair)
  std::string heatmap_dir;       // empty: no PNG
  uint64_t seed = 1;
  Sabotage sabotage = Sabotage::None;  // the sweep's bound check must fail under either
};

struct SweepFamily {
  std::string name;  // "grid", "ratio", "cancel", "cts", "split-overflow", "near-max"
  uint64_t samples = 0;
  double min_bits = 60;
  double max_err_u2 = 0;          // over finite samples where the bound applies
  uint64_t class_mismatches = 0;
  std::string worst;              // hex inputs of the min-bits sample
};

struct OpSweep {
  std::string op;                 // "add"
  std::string bound;              // "3u^2 + 13u^3"
  double bound_u2 = 0;            // the bound in u² (u³ terms included at u = 2^-24)
  std::vector<SweepFamily> families;
  double in_range_min_bits = 60;  // where the bound applies: inputs and result in [2^-75, 2^75]
  double in_range_max_err_u2 = 0;
  bool within_bound = false;      // in_range_max_err_u2 <= bound_u2
  std::string heatmap;            // PNG path, when written
  std::string driver;
  double seconds = 0;
};

const std::vector<std::string>& sweep_ops();  // add sub mul div sqrt

// Runs the sweep of every op in options.ops. Empty error on success.
std::vector<OpSweep> sweep(const SweepOptions& options, std::string* error);
std::string format_sweep(const std::vector<OpSweep>&);

}  // namespace doublet::verify
