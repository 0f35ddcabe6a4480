#include "gcc_style_args.hpp"

#include <string_view>

namespace doublet::cli {

std::vector<std::string> rewrite_gcc_style_args(int argc, char** argv) {
  std::vector<std::string> args;
  bool options_ended = false;  // after "--" everything is a file name
  for (int i = 0; i < argc; ++i) {
    std::string_view a = argv[i];
    if (i == 0 || options_ended) {
      args.emplace_back(a);
      continue;
    }
    if (a == "--") options_ended = true;
    if (a == "-MD") {
      args.emplace_back("--MD");
    } else if (a == "-O0") {
      args.emplace_back("--no-optimize");
    } else if (a.starts_with("-MF") || a.starts_with("-MT")) {
      std::string name = "--" + std::string(a.substr(1, 2));
      args.push_back(a.size() == 3 ? name : name + "=" + std::string(a.substr(3)));
    } else {
      args.emplace_back(a);
    }
  }
  return args;
}

}  // namespace doublet::cli
