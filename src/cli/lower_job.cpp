#include "lower_job.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.hpp"
#include "commands.hpp"
#include "depfile.hpp"
#include "diagnostic_printer.hpp"

namespace doublet::cli {
namespace {

// Reads a whole file (or stdin for fd 0). Returns errno on failure.
int read_fd(int fd, std::string& out) {
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) return EISDIR;
  char buf[1 << 16];
  for (;;) {
    ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) return 0;
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    out.append(buf, static_cast<size_t>(n));
  }
}

int read_input(const std::string& path, std::string& out) {
  if (path == "-") return read_fd(STDIN_FILENO, out);
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  int err = read_fd(fd, out);
  ::close(fd);
  return err;
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

  std::string source;
  if (int err = read_input(job.input, source); err != 0) {
    outcome.diagnostics.push_back(
        {job.options.file_name, 0, 0, Severity::Error, std::string("cannot read file: ") + std::strerror(err)});
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
