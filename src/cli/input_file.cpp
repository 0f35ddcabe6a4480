#include "input_file.hpp"

#include <cstring>

#include "doublet/doublet.hpp"
#include "frontend/read_limited.hpp"

namespace doublet::cli {

std::string read_input_file(const std::string& path, std::string& out) {
  out.clear();
  const frontend::ReadResult read = frontend::read_file_limited(path, kMaxSourceBytes, out);
  switch (read.status) {
    case frontend::ReadStatus::Ok: return {};
    case frontend::ReadStatus::TooLarge:
      out.clear();
      return "larger than the " + std::to_string(kMaxSourceBytes >> 20) + " MiB limit on input files; is it the right file?";
    case frontend::ReadStatus::Failed: break;
  }
  return std::strerror(read.error);
}

}  // namespace doublet::cli
