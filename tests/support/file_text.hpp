// The whole content of a file read as bytes, or "" when it cannot be read (the golden-style tests
// compare it with what they produce, so a missing expected file shows as a difference).
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace doublet::test {

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace doublet::test
