// Atomic replacement of a file: the new contents are written to a temporary
// file in the destination's directory and rename()d over the destination, so a
// reader sees either the old file or the complete new one — never a partial
// file — and a failed run leaves the destination exactly as it was.
//
// What is not a regular file is never replaced: an existing FIFO or device
// (/dev/null, a terminal), or an existing file reached through /dev/ or /proc/
// (/dev/stdout), is opened and written in place at commit(), as GCC does.
//
// Temporary files are short names (.dbl-XXXXXX, so a 255-byte output name still
// fits) and are listed where a fatal signal can find them: once
// remove_temp_files_on_fatal_signals() has run, SIGINT, SIGTERM or SIGHUP removes
// every live temporary file before the process dies of the signal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace doublet::cli {

class AtomicFile {
 public:
  AtomicFile() = default;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();

  // Creates the temporary file next to `path` and writes `contents` to it
  // (flushed to disk). Nothing is visible at `path` yet. On failure returns
  // false and sets error(); no file is left behind. For a destination written
  // in place, only keeps `contents` (and checks that it is writable).
  bool prepare(const std::string& path, std::string_view contents);

  // Renames the temporary file over the destination (or writes the destination
  // in place). On failure returns false, sets error() and removes the temporary
  // file; a renamed-over destination is untouched.
  bool commit();

  // Removes the temporary file (if any) without touching the destination.
  void discard() noexcept;

  const std::string& path() const { return path_; }
  const std::string& error() const { return error_; }

 private:
  bool prepare_in_place(std::string_view contents);
  bool prepare_temporary(std::string_view contents);
  bool commit_in_place();
  void fail(int err);

  std::string path_;        // the destination as given (for messages)
  std::string real_path_;   // where rename() goes (a symlink's target)
  std::string temp_path_;   // empty when there is no temporary file
  std::size_t temp_slot_ = 0;  // where temp_path_ is listed for the signal handler
  bool in_place_ = false;   // write the destination itself at commit()
  std::string pending_;     // the contents, when in_place_
  std::string error_;
};

// Convenience: prepare + commit. Returns an empty string on success, otherwise
// a message like "cannot write 'x': Permission denied".
std::string write_file_atomically(const std::string& path, std::string_view contents);

// Installs handlers for SIGINT, SIGTERM and SIGHUP (those not ignored when the
// process started) that unlink every live temporary file and then die of the
// signal with its default action. Call once, early in main().
void remove_temp_files_on_fatal_signals();

}  // namespace doublet::cli
