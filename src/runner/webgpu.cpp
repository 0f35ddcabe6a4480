// See webgpu.hpp. One temporary directory per run holds index.html, webgpu-page.mjs (copied from
// the browser tools) and job.json; run_browser_page serves it to headless Chromium.
#include "runner/webgpu.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "runner/browser.hpp"

namespace doublet::runner {
namespace {
namespace fs = std::filesystem;

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    unsigned v = bytes[i] << 16 | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) | (i + 2 < bytes.size() ? bytes[i + 2] : 0);
    out += table[v >> 18 & 63];
    out += table[v >> 12 & 63];
    out += i + 1 < bytes.size() ? table[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? table[v & 63] : '=';
  }
  return out;
}

std::vector<std::uint8_t> unbase64(const std::string& s) {
  std::vector<std::uint8_t> out;
  unsigned v = 0;
  int bits = 0;
  for (char c : s) {
    int d = c >= 'A' && c <= 'Z' ? c - 'A' : c >= 'a' && c <= 'z' ? c - 'a' + 26 : c >= '0' && c <= '9' ? c - '0' + 52
            : c == '+' ? 62 : c == '/' ? 63 : -1;
    if (d < 0) continue;
    v = v << 6 | static_cast<unsigned>(d);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>(v >> bits & 0xff));
    }
  }
  return out;
}

// A fresh page directory with `job` as job.json; empty string when the page script is missing.
std::string page_directory(const nlohmann::json& job, std::string& error) {
  static std::atomic<int> counter{0};
  fs::path dir = fs::temp_directory_path() / ("doublet-webgpu-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::error_code ec;
  fs::copy_file(fs::path(browser_tools_dir()) / "webgpu-page.mjs", dir / "webgpu-page.mjs", ec);
  if (ec) {
    error = "cannot copy webgpu-page.mjs from " + browser_tools_dir() + ": " + ec.message();
    return "";
  }
  std::ofstream(dir / "index.html") << "<!doctype html><script type=\"module\" src=\"webgpu-page.mjs\"></script>\n";
  std::ofstream(dir / "job.json") << job.dump();
  return dir.string();
}

}  // namespace

// Runs `job` in a fresh page directory and fills `run`'s unavailable, log, error and adapter; the
// page's result object, or an empty one (with run.error said) when the page failed or answered
// something that is not a JSON object.
template <class Run>
nlohmann::json run_job_page(const nlohmann::json& job, Run& run) {
  const std::string dir = page_directory(job, run.error);
  if (dir.empty()) return nlohmann::json::object();
  BrowserPageRun page = run_browser_page(dir);
  fs::remove_all(dir);
  run.unavailable = page.unavailable;
  run.log = page.log;
  if (!page.ok) {
    run.error = page.error;
    return nlohmann::json::object();
  }
  nlohmann::json result = nlohmann::json::parse(page.result_json, nullptr, /*allow_exceptions=*/false);
  if (!result.is_object()) {
    run.error = "the page's answer is not a JSON object: " + page.result_json.substr(0, 200);
    return nlohmann::json::object();
  }
  if (result.contains("adapter") && result.at("adapter").is_string()) run.adapter = result.at("adapter").get<std::string>();
  return result;
}

WebGpuRun run_webgpu_compute(const std::string& wgsl, const std::vector<WebGpuBuffer>& buffers,
                             std::array<int, 3> workgroups) {
  WebGpuRun run;
  nlohmann::json job;
  job["kind"] = "compute";
  job["code"] = wgsl;
  job["groups"] = {workgroups[0], workgroups[1], workgroups[2]};
  job["buffers"] = nlohmann::json::array();
  for (const auto& b : buffers)
    job["buffers"].push_back({{"group", b.group},
                              {"binding", b.binding},
                              {"kind", b.kind == WebGpuBuffer::Kind::Uniform ? "uniform"
                                       : b.kind == WebGpuBuffer::Kind::Storage ? "storage" : "read-only-storage"},
                              {"data", base64(b.bytes)}});
  const nlohmann::json result = run_job_page(job, run);
  if (!result.contains("buffers") || !result.at("buffers").is_array()) {
    if (run.error.empty()) run.error = "the page's answer has no buffers";
    return run;
  }
  for (const auto& b : result.at("buffers")) {
    if (!b.is_string()) return (run.error = "the page returned a buffer that is not base64 text"), run;
    run.buffers.push_back(unbase64(b.get<std::string>()));
  }
  run.ok = true;
  return run;
}

WgslValidationRun validate_wgsl_in_browser(const std::vector<WgslModule>& modules) {
  WgslValidationRun run;
  nlohmann::json job;
  job["kind"] = "validate";
  job["modules"] = nlohmann::json::array();
  for (const auto& m : modules) job["modules"].push_back({{"name", m.name}, {"stage", m.stage}, {"code", m.code}});
  const nlohmann::json result = run_job_page(job, run);
  if (!result.contains("results") || !result.at("results").is_array()) {
    if (run.error.empty()) run.error = "the page's answer has no results";
    return run;
  }
  for (const auto& r : result.at("results")) {
    WgslValidation v;
    v.name = r.at("name").get<std::string>();
    v.ok = r.at("ok").get<bool>();
    for (const auto& m : r.at("messages")) v.messages += m.get<std::string>() + "\n";
    run.results.push_back(v);
  }
  run.ok = true;
  return run;
}

}  // namespace doublet::runner
