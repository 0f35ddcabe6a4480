// Runs the doublet CLI with stdout and stderr captured (plan tests).
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace plan_test {

struct CliRun {
  int exit_code = -1;
  std::string out;
};

inline CliRun doublet(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string(DOUBLET_CLI_PATH) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
  const int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

const std::string kScenes = DOUBLET_SCENES;

}  // namespace plan_test
