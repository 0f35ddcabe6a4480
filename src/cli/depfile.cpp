#include "depfile.hpp"

#include <algorithm>

namespace doublet::cli {
namespace {

std::string escape_path(std::string_view path) {
  std::string out;
  for (char c : path) {
    if (c == ' ' || c == '#') out += '\\';
    if (c == '$') out += '$';
    out += c;
  }
  return out;
}

}  // namespace

std::string make_depfile(std::string_view target, const std::vector<std::string>& prerequisites) {
  std::vector<std::string> unique;
  for (const auto& p : prerequisites)
    if (std::find(unique.begin(), unique.end(), p) == unique.end()) unique.push_back(p);
  std::string out = escape_path(target) + ":";
  for (const auto& p : unique) out += " \\\n  " + escape_path(p);
  return out + "\n";
}

}  // namespace doublet::cli
