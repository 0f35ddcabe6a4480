// Runs tools/browser/run-page.mjs as a child process (posix_spawn, stdout and stderr read through
// pipes with poll, so neither can fill up and block the child) and maps its exit status: 0 result,
// 1 page failure, 2 no browser here.
#include "runner/browser.hpp"

#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

extern char** environ;

namespace doublet::runner {
namespace {

bool file_exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

// The node executable on PATH, or "" when there is none.
std::string find_node() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    std::string candidate = dirs.substr(start, end - start) + "/node";
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return "";
}

struct ChildOutput {
  int status = -1;  // exit status, or -1 when killed or not started
  bool timed_out = false;
  std::string out, err;
};

ChildOutput run_child(const std::vector<std::string>& argv, int timeout_ms) {
  ChildOutput result;
  int out_pipe[2], err_pipe[2];
  if (::pipe(out_pipe) != 0) return result;
  if (::pipe(err_pipe) != 0) {
    ::close(out_pipe[0]);
    ::close(out_pipe[1]);
    return result;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out_pipe[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err_pipe[1], 2);
  posix_spawn_file_actions_addclose(&actions, out_pipe[0]);
  posix_spawn_file_actions_addclose(&actions, err_pipe[0]);
  // Its own process group, so a timeout can stop node and the browser it started together.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  int spawned = posix_spawn(&pid, argv[0].c_str(), &actions, &attributes, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  if (spawned != 0) {
    ::close(out_pipe[0]);
    ::close(err_pipe[0]);
    result.err = "cannot start " + argv[0];
    return result;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&result.out, &result.err};
  int open_pipes = 2;
  while (open_pipes > 0) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      result.timed_out = true;
      ::kill(-pid, SIGKILL);
      break;
    }
    if (::poll(fds, 2, static_cast<int>(left)) < 0) continue;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buffer[65536];
      ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        sinks[i]->append(buffer, static_cast<size_t>(n));
      } else {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_pipes;
      }
    }
  }
  for (auto& fd : fds)
    if (fd.fd >= 0) ::close(fd.fd);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
  }
  if (!result.timed_out && WIFEXITED(status)) result.status = WEXITSTATUS(status);
  return result;
}

}  // namespace

std::string browser_tools_dir() {
  if (const char* dir = std::getenv("DOUBLET_BROWSER_TOOLS"); dir && *dir) return dir;
  return DOUBLET_SOURCE_DIR "/tools/browser";
}

std::string browser_unavailable_reason() {
  const std::string tools = browser_tools_dir();
  if (find_node().empty()) return "node is not installed (apt-get install nodejs npm)";
  if (!file_exists(tools + "/node_modules/playwright-core"))
    return "playwright-core is not installed (cd " + tools + " && npm ci)";
  const char* chromium = std::getenv("CHROMIUM");
  std::string browser = chromium && *chromium ? chromium : "/usr/bin/chromium";
  if (!file_exists(browser)) return "no browser at " + browser + " (apt-get install chromium)";
  return "";
}

BrowserPageRun run_browser_page(const std::string& directory, const BrowserPageOptions& options) {
  BrowserPageRun run;
  if (std::string why = browser_unavailable_reason(); !why.empty()) {
    run.unavailable = true;
    run.error = why;
    return run;
  }
  std::vector<std::string> argv = {find_node(), browser_tools_dir() + "/run-page.mjs", directory,
                                   "--page", options.page, "--timeout-ms", std::to_string(options.timeout_ms)};
  if (!options.screenshot.empty()) {
    argv.push_back("--screenshot");
    argv.push_back(options.screenshot);
  }
  // The page's own timeout covers loading and reporting; the margin covers starting the browser.
  ChildOutput child = run_child(argv, options.timeout_ms + 60000);
  run.log = child.err;
  if (child.timed_out) {
    run.error = "the browser did not finish within " + std::to_string(options.timeout_ms / 1000 + 60) + " s";
  } else if (child.status == 0) {
    run.ok = true;
    run.result_json = child.out;
  } else if (child.status == 2) {
    run.unavailable = true;
    run.error = child.err;
  } else {
    run.error = child.err.empty() ? "the browser run failed" : child.err;
  }
  return run;
}

NodeScriptRun run_node_script(const std::string& script, const std::vector<std::string>& args, int timeout_ms) {
  NodeScriptRun run;
  const std::string node = find_node();
  if (node.empty() || !file_exists(script)) {
    run.unavailable = true;
    run.error = node.empty() ? "node is not installed (apt-get install nodejs npm)" : "no script " + script;
    return run;
  }
  std::vector<std::string> argv = {node, script};
  argv.insert(argv.end(), args.begin(), args.end());
  ChildOutput child = run_child(argv, timeout_ms);
  run.out = child.out;
  if (child.timed_out) run.error = script + " did not finish within " + std::to_string(timeout_ms / 1000) + " s";
  else if (child.status != 0) run.error = child.err.empty() ? script + " failed" : child.err;
  else run.ok = true;
  return run;
}

}  // namespace doublet::runner
