#include "job_runner.hpp"

#include <algorithm>
#include <atomic>
#include <future>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "diagnostic_printer.hpp"

// WebAssembly without threads (wasm/CMakeLists.txt): -j is accepted and jobs run one at a time.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
#define DOUBLET_SINGLE_THREADED 1
#else
#define DOUBLET_SINGLE_THREADED 0
#endif

namespace doublet::cli {
namespace {

constexpr bool kSingleThreaded = DOUBLET_SINGLE_THREADED;

int report(JobOutcome& outcome, bool color) {
  for (const Diagnostic& d : outcome.diagnostics) std::cerr << render_diagnostic(d, color);
  std::cerr.flush();
  if (!outcome.stdout_text.empty()) {
    std::cout.write(outcome.stdout_text.data(), static_cast<std::streamsize>(outcome.stdout_text.size()));
    std::cout.flush();
    if (!std::cout) {
      std::cerr << render_diagnostic(tool_error("cannot write to stdout"), color);
      return kExitInput;
    }
  }
  return outcome.exit_code;
}

}  // namespace

int run_jobs(const std::vector<LowerJob>& jobs, unsigned threads, bool color) {
  int worst = kExitOk;
  threads = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(jobs.size())));
  if (threads == 1 || kSingleThreaded) {
    for (const LowerJob& job : jobs) {
      JobOutcome outcome = run_lower_job(job);
      worst = std::max(worst, report(outcome, color));
    }
    return worst;
  }

#if !DOUBLET_SINGLE_THREADED
  std::vector<std::promise<JobOutcome>> promises(jobs.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next.fetch_add(1)) < jobs.size();) {
      try {
        promises[i].set_value(run_lower_job(jobs[i]));
      } catch (...) {  // rethrown by get() below: main() reports it as an internal error
        promises[i].set_exception(std::current_exception());
      }
    }
  };
  std::vector<std::jthread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& p : promises) {
    JobOutcome outcome = p.get_future().get();
    worst = std::max(worst, report(outcome, color));
  }
#endif
  return worst;
}

}  // namespace doublet::cli
