// Runs WebGL2 graphics batches in headless Chromium: writes a directory with the page
// (tools/browser/webgl2-verify.html and .mjs) and jobs.json (every program's passes, every job's
// input words, uniforms and uniform block bytes, the test textures), opens it once through
// runner::run_browser_page, and decodes what the page reports. Every number that must arrive
// exactly (words, uniform values, texels, block bytes) travels as base64 of its little-endian
// bytes: JSON numbers cannot carry Inf or NaN, and the bits are what is compared.
#include <stdlib.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "runner/browser.hpp"
#include "runner/webgl2.hpp"

namespace doublet::runner::detail {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string base64(const void* data, size_t size) {
  const auto* p = static_cast<const uint8_t*>(data);
  std::string s;
  s.reserve((size + 2) / 3 * 4);
  for (size_t i = 0; i < size; i += 3) {
    const size_t left = size - i;
    uint32_t n = uint32_t{p[i]} << 16;
    if (left > 1) n |= uint32_t{p[i + 1]} << 8;
    if (left > 2) n |= p[i + 2];
    s += kAlphabet[n >> 18 & 63];
    s += kAlphabet[n >> 12 & 63];
    s += left > 1 ? kAlphabet[n >> 6 & 63] : '=';
    s += left > 2 ? kAlphabet[n & 63] : '=';
  }
  return s;
}

// False when `s` is not base64.
bool unbase64(const std::string& s, std::vector<uint8_t>* out) {
  out->clear();
  uint32_t n = 0;
  int bits = 0;
  for (char c : s) {
    if (c == '=') break;
    const char* at = std::strchr(kAlphabet, c);
    if (!at || c == '\0') return false;
    n = n << 6 | static_cast<uint32_t>(at - kAlphabet);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out->push_back(static_cast<uint8_t>(n >> bits));
    }
  }
  return true;
}

template <typename T>
std::string base64(const std::vector<T>& v) {
  return base64(v.data(), v.size() * sizeof(T));
}

// The directory the page runs from; removed when this goes out of scope.
struct PageDirectory {
  fs::path path;
  PageDirectory() {
    std::string pattern = (fs::temp_directory_path() / "doublet-webgl2-XXXXXX").string();
    if (::mkdtemp(pattern.data())) path = pattern;
  }
  ~PageDirectory() {
    std::error_code ignored;
    if (!path.empty()) fs::remove_all(path, ignored);
  }
};

json test_textures() {
  json t;
  t["size"] = kTextureSize;
  t["2d"] = base64(test_texture(TextureKind::Tex2D));
  t["3d"] = base64(test_texture(TextureKind::Tex3D));
  t["cube"] = base64(test_texture(TextureKind::Cube));
  return t;
}

// One batch as the page reads it, or an error before any browser work.
std::string describe_batch(const std::vector<GraphicsJob>& jobs, const WebGl2Program& program, json* out) {
  json& p = *out;
  p["stage"] = program.stage == GraphicsStage::Vertex ? "vertex" : "fragment";
  p["count"] = jobs[0].count;
  p["input_words"] = program.input_words;
  p["output_words"] = program.output_words;
  p["passes"] = json::array();
  for (const WebGl2Pass& pass : program.passes)
    p["passes"].push_back({{"vertex", pass.vertex}, {"fragment", pass.fragment}, {"varyings", pass.varyings},
                           {"first_slot", pass.first_slot}, {"slots", pass.slots}});
  p["jobs"] = json::array();
  for (const GraphicsJob& job : jobs) {
    std::vector<uint32_t> words;
    if (std::string e = webgl2_pack_inputs(program, job, &words); !e.empty()) return e;
    json j;
    j["inputs"] = base64(words);
    j["uniforms"] = json::object();
    for (const auto& [name, value] : job.float_uniforms) j["uniforms"][name] = base64(std::vector<double>{value});
    for (const auto& [name, values] : job.uniforms) j["uniforms"][name] = base64(values);
    j["blocks"] = json::object();
    for (const auto& [name, bytes] : job.uniform_blocks) j["blocks"][name] = base64(bytes);
    p["jobs"].push_back(std::move(j));
  }
  return {};
}

std::string check_batch(const std::vector<GraphicsJob>& jobs) {
  if (jobs.empty()) return "no jobs";
  if (jobs[0].count == 0 || jobs[0].count > kWebGl2GridWidth * 1024)
    return "a graphics job runs 1 to " + std::to_string(kWebGl2GridWidth * 1024) + " samples";
  for (const GraphicsJob& job : jobs)
    if (job.count != jobs[0].count) return "every job of a graphics batch must have the same count";
  return {};
}

std::vector<GraphicsResult> failed(const std::string& error, const std::string& device = "") {
  GraphicsResult r;
  r.error = error;
  r.device = device;
  return {r};
}

// One program's reply: { error } or { jobs: [base64 words] }, one result per job; like
// run_graphics_batch, the results stop at the first failure, which carries the error.
std::vector<GraphicsResult> decode_program(const json& reply, const std::vector<GraphicsJob>& jobs,
                                           const WebGl2Program& program, const std::string& renderer) {
  if (!reply.is_object()) return failed("the WebGL2 page's reply is not an object", renderer);
  if (reply.contains("error"))
    return failed("WebGL2 (" + renderer + "): " + (reply["error"].is_string() ? reply["error"].get<std::string>() : reply["error"].dump()),
                  renderer);
  if (!reply.contains("jobs") || !reply["jobs"].is_array() || reply["jobs"].size() != jobs.size())
    return failed("the WebGL2 page did not return one result per draw", renderer);
  const size_t want = size_t{jobs[0].count} * program.output_words * 4;
  std::vector<GraphicsResult> results;
  for (const json& words_b64 : reply["jobs"]) {
    GraphicsResult result;
    result.device = renderer;
    std::vector<uint8_t> bytes;
    if (!words_b64.is_string() || !unbase64(words_b64.get<std::string>(), &bytes) || bytes.size() != want) {
      result.error = "the WebGL2 page returned " + std::to_string(bytes.size()) + " output bytes, not " + std::to_string(want);
      results.push_back(std::move(result));
      break;
    }
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    webgl2_unpack_outputs(program, jobs[0].count, words, &result);
    result.ok = true;
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace

std::vector<std::vector<GraphicsResult>> webgl2_run_graphics(const std::vector<std::vector<GraphicsJob>>& batches) {
  std::vector<std::vector<GraphicsResult>> results(batches.size());
  std::vector<WebGl2Program> programs(batches.size());
  std::vector<size_t> sent;  // batches that go to the page, in page order
  json page;
  page["textures"] = test_textures();
  page["programs"] = json::array();
  for (size_t b = 0; b < batches.size(); ++b) {
    std::string error = check_batch(batches[b]);
    if (error.empty()) error = wrap_webgl2(batches[b][0].stage, batches[b][0].glsl, &programs[b]);
    json p;
    if (error.empty()) error = describe_batch(batches[b], programs[b], &p);
    if (!error.empty()) {
      results[b] = failed(error);
      continue;
    }
    page["programs"].push_back(std::move(p));
    sent.push_back(b);
  }
  if (sent.empty()) return results;

  PageDirectory dir;
  std::error_code copy_error;
  for (const char* file : {"webgl2-verify.html", "webgl2-verify.mjs"})
    if (!dir.path.empty())
      fs::copy_file(fs::path(browser_tools_dir()) / file, dir.path / file, fs::copy_options::overwrite_existing, copy_error);
  if (dir.path.empty() || copy_error) {
    for (size_t b : sent) results[b] = failed("cannot prepare the WebGL2 page: " + (copy_error ? copy_error.message() : "no temporary directory"));
    return results;
  }
  std::ofstream(dir.path / "jobs.json") << page.dump();
  BrowserPageOptions options;
  options.page = "webgl2-verify.html";
  options.timeout_ms = 300000;
  const BrowserPageRun run = run_browser_page(dir.path.string(), options);
  if (!run.ok) {
    const std::string why = run.unavailable ? "no browser here: " + run.error : "the WebGL2 page failed: " + run.error;
    for (size_t b : sent) results[b] = failed(why);
    return results;
  }
  json reply;
  try {
    reply = json::parse(run.result_json);
  } catch (const json::exception& e) {
    for (size_t b : sent) results[b] = failed(std::string("the WebGL2 page's result is not JSON: ") + e.what());
    return results;
  }
  const std::string renderer = reply.is_object() && reply.contains("renderer") && reply["renderer"].is_string()
                                   ? reply["renderer"].get<std::string>() : "";
  const json* replies = reply.is_object() && reply.contains("programs") ? &reply["programs"] : nullptr;
  for (size_t k = 0; k < sent.size(); ++k) {
    const size_t b = sent[k];
    if (!replies || !replies->is_array() || k >= replies->size()) {
      results[b] = failed("the WebGL2 page reported no result for this program", renderer);
      continue;
    }
    results[b] = decode_program((*replies)[k], batches[b], programs[b], renderer);
  }
  return results;
}

}  // namespace doublet::runner::detail
