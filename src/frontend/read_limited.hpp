// Reading a file whose size nobody vouches for (an input that may be /dev/zero, a pipe
// fed by `yes`, a sparse 3 GB file): at most `limit` bytes are kept, and reading stops
// one byte past the limit, so memory stays bounded whatever the file is.
#pragma once

#include <cstddef>
#include <string>

namespace doublet::frontend {

enum class ReadStatus { Ok, TooLarge, Failed };

struct ReadResult {
  ReadStatus status = ReadStatus::Ok;
  int error = 0;  // errno when Failed
};

// Appends what `fd` holds (to its end) to `out`. TooLarge when it holds more than `limit`
// bytes: `out` then has at most limit + 1 bytes appended. A directory fails with EISDIR.
ReadResult read_limited(int fd, std::size_t limit, std::string& out);

// The same for the file at `path`.
ReadResult read_file_limited(const std::string& path, std::size_t limit, std::string& out);

// The refusal of a source over doublet::kMaxSourceBytes: `what` ("input", "#include \"x\"")
// "is larger than the 64 MiB limit ...".
std::string source_too_large_message(const std::string& what);

}  // namespace doublet::frontend
