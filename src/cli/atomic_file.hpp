// Atomic replacement of a file: the new contents are written to a temporary
// file in the destination's directory and rename()d over the destination, so a
// reader sees either the old file or the complete new one — never a partial
// file — and a failed run leaves the destination exactly as it was.
#pragma once

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
  // false and sets error(); no file is left behind.
  bool prepare(const std::string& path, std::string_view contents);

  // Renames the temporary file over the destination. On failure returns false,
  // sets error() and removes the temporary file; the destination is untouched.
  bool commit();

  // Removes the temporary file (if any) without touching the destination.
  void discard() noexcept;

  const std::string& path() const { return path_; }
  const std::string& error() const { return error_; }

 private:
  std::string path_;       // the destination as given (for messages)
  std::string real_path_;  // where rename() goes (a symlink's target)
  std::string temp_path_;  // empty when there is no temporary file
  std::string error_;
};

// Convenience: prepare + commit. Returns an empty string on success, otherwise
// a message like "cannot write 'x': Permission denied".
std::string write_file_atomically(const std::string& path, std::string_view contents);

}  // namespace doublet::cli
