// One unit of `doublet lower`: read a shader, lower it, write the lowered shader, its
// manifest and its depfile. Jobs share nothing, so a batch runs them on many threads;
// what they would print is returned instead, to be printed in input order.
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace doublet::cli {

struct LowerJob {
  std::string input;            // a path, or "-" for stdin
  Options options;              // stage, target, defines, ... (file_name set from input)
  std::string output;           // empty: stdout
  std::string manifest;         // empty: none; "-": stdout (output must be a file)
  std::string depfile;          // empty: none
  std::string depfile_target;   // the rule's target in the depfile
  // Non-empty: the input is a stage doublet does not lower (named by its extension); the job reports
  // this as the file's diagnostic (exit 2, like any shader it cannot lower) and writes nothing.
  std::string refusal;
};

struct JobOutcome {
  int exit_code = 0;                     // kExitOk or kExitInput
  std::vector<Diagnostic> diagnostics;   // to print on stderr, in order
  std::string stdout_text;               // the shader and/or manifest when sent to stdout
};

JobOutcome run_lower_job(const LowerJob& job);

}  // namespace doublet::cli
