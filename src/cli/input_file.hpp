// Reading a file named on the command line (a shader, plan, scene or spec), bounded like
// every shader source by doublet::kMaxSourceBytes: `/dev/zero` or a huge file is refused
// after limit + 1 bytes, never read whole.
#pragma once

#include <string>

namespace doublet::cli {

// Replaces `out` with the file's contents. Empty on success, else why not: "No such file or
// directory", "larger than the 64 MiB limit on input files; is it the right file?".
std::string read_input_file(const std::string& path, std::string& out);

}  // namespace doublet::cli
