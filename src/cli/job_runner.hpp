// Runs lower jobs on up to `threads` threads and reports each in input order (stderr
// diagnostics, then stdout text) as soon as it and all before it are done, so a batch
// prints the same thing whatever -j is.
#pragma once

#include <vector>

#include "lower_job.hpp"

namespace doublet::cli {

// Returns the worst exit code of all jobs (kExitOk when every job succeeded).
int run_jobs(const std::vector<LowerJob>& jobs, unsigned threads, bool color);

}  // namespace doublet::cli
