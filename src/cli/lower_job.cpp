#include "lower_job.hpp"

#include <cerrno>
#include <cstring>
#include <optional>
#include <utility>

#include <unistd.h>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "depfile.hpp"
#include "diagnostic_printer.hpp"
#include "frontend/read_limited.hpp"
#include "output_paths.hpp"

namespace doublet::cli {
namespace {

// Reads the input (a path, or "-" for stdin), stopping one byte past doublet's source limit.
frontend::ReadResult read_input(const std::string& path, std::string& out) {
  if (path == "-") return frontend::read_limited(STDIN_FILENO, kMaxSourceBytes, out);
  return frontend::read_file_limited(path, kMaxSourceBytes, out);
}

// An output that is one of the files the shader #includes (known only once it is lowered).
std::optional<FileClash> find_included_output(const LowerJob& job, const std::vector<std::string>& included) {
  std::vector<NamedFile> outputs, inputs;
  for (const auto& [path, what] : {std::pair{job.output, "the output"}, {job.manifest, "the manifest"}, {job.depfile, "the depfile"}})
    if (!path.empty() && path != "-") outputs.push_back({path, what + (" '" + path + "'")});
  for (const std::string& path : included) inputs.push_back({path, "the #include'd file '" + path + "'"});
  return find_file_clash(outputs, inputs);
}

std::string with_newline(std::string text) {
  if (text.empty() || text.back() != '\n') text += '\n';
  return text;
}

}  // namespace

JobOutcome run_lower_job(const LowerJob& job) {
  JobOutcome outcome;
  auto fail = [&](std::string message) {
    outcome.diagnostics.push_back(tool_error(std::move(message)));
    outcome.exit_code = kExitInput;
    return outcome;
  };

  if (!job.refusal.empty()) {
    outcome.diagnostics.push_back({job.options.file_name, 1, 1, Severity::Error, job.refusal});
    outcome.exit_code = kExitInput;
    return outcome;
  }
  std::string source;
  if (frontend::ReadResult read = read_input(job.input, source); read.status != frontend::ReadStatus::Ok) {
    const bool too_large = read.status == frontend::ReadStatus::TooLarge;
    outcome.diagnostics.push_back({job.options.file_name, too_large ? 1 : 0, too_large ? 1 : 0, Severity::Error,
                                   too_large ? frontend::source_too_large_message("input")
                                             : std::string("cannot read file: ") + std::strerror(read.error)});
    outcome.exit_code = kExitInput;
    return outcome;
  }

  Result result = lower(source, job.options);
  bool has_error = !result.ok;
  for (const Diagnostic& d : result.diagnostics) has_error |= d.severity == Severity::Error;
  outcome.diagnostics = result.diagnostics;
  if (has_error) {
    if (result.ok) return fail("compilation reported errors; nothing written");
    outcome.exit_code = kExitInput;
    return outcome;
  }

  if (std::optional<FileClash> clash = find_included_output(job, result.included_files))
    return fail(clash->describe() + ": writing it would destroy the included file; write the output elsewhere");

  // Every file is prepared first and renamed into place only when all could be written,
  // the depfile last: a depfile on disk always describes outputs that exist.
  const bool manifest_to_stdout = job.manifest == "-";
  std::string manifest_json = job.manifest.empty() ? std::string() : with_newline(result.manifest.to_json());
  std::vector<std::string> prerequisites{job.input};
  prerequisites.insert(prerequisites.end(), result.included_files.begin(), result.included_files.end());

  AtomicFile out_file, manifest_file, dep_file;
  if (!job.output.empty() && !out_file.prepare(job.output, result.output)) return fail(out_file.error());
  if (!job.manifest.empty() && !manifest_to_stdout && !manifest_file.prepare(job.manifest, manifest_json))
    return fail(manifest_file.error());
  if (!job.depfile.empty() &&
      !dep_file.prepare(job.depfile, make_depfile(job.depfile_target, prerequisites)))
    return fail(dep_file.error());
  if (!job.output.empty() && !out_file.commit()) return fail(out_file.error());
  if (!job.manifest.empty() && !manifest_to_stdout && !manifest_file.commit()) return fail(manifest_file.error());
  if (!job.depfile.empty() && !dep_file.commit()) return fail(dep_file.error());

  if (job.output.empty()) outcome.stdout_text += result.output;
  if (manifest_to_stdout) outcome.stdout_text += manifest_json;
  return outcome;
}

}  // namespace doublet::cli
