// The WebGPU backend: WGSL compute shaders run in headless Chromium's WebGPU (Dawn; here on
// SwiftShader, docs/web.md) through run_browser_page and tools/browser/webgpu-page.mjs, and WGSL
// modules are validated there (the WGSL front end doublet has: there is no WGSL validator in Debian).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace doublet::runner {

struct WebGpuBuffer {
  enum class Kind { Uniform, Storage, ReadOnlyStorage };
  int binding = 0;  // @group(group) @binding(N)
  Kind kind = Kind::Storage;
  std::vector<std::uint8_t> bytes;  // initial contents (std430-compatible for storage buffers)
  int group = 0;
};

struct WebGpuRun {
  bool ok = false;
  bool unavailable = false;  // no browser here: skip, not fail
  std::string error;
  std::string adapter;  // the WebGPU adapter's vendor / architecture / device / description
  std::vector<std::vector<std::uint8_t>> buffers;  // every buffer after the dispatch, in input order
  std::string log;
};

WebGpuRun run_webgpu_compute(const std::string& wgsl, const std::vector<WebGpuBuffer>& buffers,
                             std::array<int, 3> workgroups);

struct WgslModule {
  std::string name;
  std::string stage;  // "comp", "vert", "frag"
  std::string code;
};
struct WgslValidation {
  std::string name;
  bool ok = false;
  std::string messages;  // the compilation and pipeline-validation messages, one per line
};
struct WgslValidationRun {
  bool ok = false;  // the page ran (each module's verdict is in results)
  bool unavailable = false;
  std::string error, adapter, log;
  std::vector<WgslValidation> results;
};

// Compiles every module in one page run.
WgslValidationRun validate_wgsl_in_browser(const std::vector<WgslModule>& modules);

}  // namespace doublet::runner
