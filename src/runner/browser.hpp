// Headless Chromium for the browser backends, the web page and its tests: runs one page of a
// directory through tools/browser/run-page.mjs (Node + npm playwright-core driving Debian's
// /usr/bin/chromium; nothing is downloaded) and returns what the page reported as JSON text.
// The page protocol (window.doubletResult) is described at the top of run-page.mjs.
#pragma once

#include <string>
#include <vector>

namespace doublet::runner {

struct BrowserPageOptions {
  std::string page = "index.html";  // relative to the directory
  int timeout_ms = 120000;           // for loading and for the page's result
  std::string screenshot;            // PNG of the full page after it reported, when non-empty
};

struct BrowserPageRun {
  bool ok = false;           // the page reported a result
  bool unavailable = false;  // no browser here (node, playwright-core or chromium missing): skip, not fail
  std::string result_json;   // the page's result, JSON text (when ok)
  std::string error;         // why not ok: the page's error, a timeout, or what is missing
  std::string log;           // the page's console output and run-page's messages (stderr)
};

// The directory holding run-page.mjs and its node_modules: $DOUBLET_BROWSER_TOOLS, else the
// source tree's tools/browser.
std::string browser_tools_dir();

// Empty when a page can run here; otherwise what is missing and how to install it.
std::string browser_unavailable_reason();

BrowserPageRun run_browser_page(const std::string& directory, const BrowserPageOptions& options = {});

// A Node script run to completion (the same child-process handling as the browser runs): its
// stdout, and why it failed. `unavailable` when there is no node on PATH or no such script.
struct NodeScriptRun {
  bool ok = false;  // exit status 0
  bool unavailable = false;
  std::string out;
  std::string error;  // stderr, or what is missing, or the timeout
};
NodeScriptRun run_node_script(const std::string& script, const std::vector<std::string>& args, int timeout_ms);

}  // namespace doublet::runner
