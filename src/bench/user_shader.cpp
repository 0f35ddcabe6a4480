#include "bench/user_shader.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace doublet::bench {
namespace {

bool read(const std::filesystem::path& p, std::string* out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return true;
}

bool expand(const std::filesystem::path& path, const std::vector<std::string>& dirs, std::set<std::string>& seen,
            std::string* out, std::string* error) {
  std::string text;
  if (!read(path, &text)) {
    *error = "cannot read " + path.string();
    return false;
  }
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
