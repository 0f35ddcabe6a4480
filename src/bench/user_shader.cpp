#include "bench/user_shader.hpp"

#include <filesystem>
#include <set>
#include <sstream>

#include "doublet/doublet.hpp"
#include "frontend/read_limited.hpp"

namespace doublet::bench {
namespace {

// The file's text, within what is left of doublet's source limit (the shader and its includes
// together, as doublet::lower counts them): a /dev/zero or an endless pipe is refused, not read.
bool read(const std::filesystem::path& p, std::size_t already_read, std::string* out, std::string* error) {
  const std::size_t budget = already_read >= kMaxSourceBytes ? 0 : kMaxSourceBytes - already_read;
  switch (frontend::read_file_limited(p.string(), budget, *out).status) {
    case frontend::ReadStatus::Ok: return true;
    case frontend::ReadStatus::TooLarge: *error = p.string() + ": " + frontend::source_too_large_message("input"); return false;
    case frontend::ReadStatus::Failed: break;
  }
  *error = "cannot read " + p.string();
  return false;
}

bool expand(const std::filesystem::path& path, const std::vector<std::string>& dirs, std::set<std::string>& seen,
            std::string* out, std::string* error) {
  std::string text;
  if (!read(path, out->size(), &text, error)) return false;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const size_t hash = line.find_first_not_of(" \t");
    const size_t q1 = line.find('"');
    const size_t q2 = q1 == std::string::npos ? q1 : line.find('"', q1 + 1);
    if (hash == std::string::npos || line.compare(hash, 8, "#include") != 0 || q2 == std::string::npos) {
      *out += line + "\n";
      continue;
    }
    const std::string name = line.substr(q1 + 1, q2 - q1 - 1);
    std::vector<std::filesystem::path> candidates{path.parent_path() / name};
    for (const std::string& d : dirs) candidates.push_back(std::filesystem::path(d) / name);
    bool found = false;
    for (const auto& c : candidates) {
      if (!std::filesystem::exists(c)) continue;
      found = true;
      const std::string key = std::filesystem::weakly_canonical(c).string();
      // Like #pragma once: a second include adds nothing (and a cycle cannot recurse forever).
      if (seen.insert(key).second && !expand(c, dirs, seen, out, error)) return false;
      break;
    }
    if (!found) {
      *error = path.string() + ": cannot find include \"" + name + "\"";
      return false;
    }
  }
  return true;
}

}  // namespace

bool expand_includes(const std::string& path, const std::vector<std::string>& include_dirs, std::string* out,
                     std::string* error) {
  std::set<std::string> seen;
  out->clear();
  return expand(path, include_dirs, seen, out, error);
}

std::string as_desktop_450(const std::string& source) {
  const size_t v = source.find("#version");
  if (v == std::string::npos) return source;
  const size_t eol = source.find('\n', v);
  return source.substr(0, v) + "#version 450" + (eol == std::string::npos ? "" : source.substr(eol));
}

}  // namespace doublet::bench
