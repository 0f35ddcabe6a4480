// run_browser_page on the real headless Chromium: a page's result comes back as JSON, a page that
// fails or never reports is an error (not a result), and a missing browser is "unavailable".
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "browser_test_util.hpp"
#include "runner/browser.hpp"

namespace {

namespace fs = std::filesystem;
using doublet::runner::BrowserPageOptions;
using doublet::runner::run_browser_page;

// A fresh directory holding one index.html with `script` as its module script.
fs::path page_dir(const std::string& name, const std::string& script) {
  fs::path dir = fs::temp_directory_path() / ("doublet-browser-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "index.html") << "<!doctype html><script type=\"module\">\n" << script << "\n</script>\n";
  return dir;
}

TEST(Browser, PageResultComesBackAsJsonWithWebGL2AndWebGPU) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  // The page squares 3 in a WebGPU compute shader and reads a job file next to it, so the result
  // depends on the GPU stack and the served directory, not on the page text alone.
  auto dir = page_dir("ok", R"(
window.doubletResult = (async () => {
  const job = await (await fetch('job.json')).json();
  const gl = document.createElement('canvas').getContext('webgl2');
  const device = await (await navigator.gpu.requestAdapter()).requestDevice();
  const buffer = device.createBuffer({ size: 4, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(buffer, 0, new Float32Array([job.x]));
  const module = device.createShaderModule({ code: `
    @group(0) @binding(0) var<storage, read_write> v: array<f32>;
    @compute @workgroup_size(1) fn main() { v[0] = v[0] * v[0]; }` });
  const pipeline = device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: 'main' } });
  const read = device.createBuffer({ size: 4, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
  const encoder = device.createCommandEncoder();
  const pass = encoder.beginComputePass();
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: { buffer } }] }));
  pass.dispatchWorkgroups(1);
  pass.end();
  encoder.copyBufferToBuffer(buffer, 0, read, 0, 4);
  device.queue.submit([encoder.finish()]);
  await read.mapAsync(GPUMapMode.READ);
  return { webgl2: !!gl, squared: new Float32Array(read.getMappedRange())[0] };
})();)");
  std::ofstream(dir / "job.json") << R"({"x": 3})";
  auto run = run_browser_page(dir.string());
  ASSERT_TRUE(run.ok) << run.error << "\n" << run.log;
  auto result = nlohmann::json::parse(run.result_json);
  EXPECT_EQ(result.at("webgl2"), true);
  EXPECT_EQ(result.at("squared").get<double>(), 9.0);
  fs::remove_all(dir);
}

TEST(Browser, ScreenshotIsWritten) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  auto dir = page_dir("shot", "document.body.style.background = 'red'; window.doubletResult = 1;");
  BrowserPageOptions options;
  options.screenshot = (dir / "shot.png").string();
  auto run = run_browser_page(dir.string(), options);
  ASSERT_TRUE(run.ok) << run.error;
  std::ifstream png(options.screenshot, std::ios::binary);
  char magic[4] = {};
  png.read(magic, 4);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  fs::remove_all(dir);
}

TEST(Browser, RejectedResultIsAnErrorWithThePagesMessage) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  auto dir = page_dir("reject", "window.doubletResult = Promise.reject(new Error('shader failed: xyz'));");
  auto run = run_browser_page(dir.string());
  EXPECT_FALSE(run.ok);
  EXPECT_FALSE(run.unavailable);
  EXPECT_NE(run.error.find("shader failed: xyz"), std::string::npos) << run.error;
  fs::remove_all(dir);
}

TEST(Browser, PageThatNeverReportsTimesOut) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  auto dir = page_dir("silent", "console.log('never reports');");
  BrowserPageOptions options;
  options.timeout_ms = 1500;
  auto run = run_browser_page(dir.string(), options);
  EXPECT_FALSE(run.ok);
  EXPECT_FALSE(run.unavailable);
  EXPECT_NE(run.error.find("Timeout"), std::string::npos) << run.error;
  EXPECT_NE(run.log.find("never reports"), std::string::npos) << run.log;  // the page's console reaches the log
  fs::remove_all(dir);
}

TEST(Browser, MissingBrowserIsUnavailableNotFailed) {
  auto dir = page_dir("missing", "window.doubletResult = 1;");
  ::setenv("CHROMIUM", "/nonexistent/chromium", 1);
  auto run = run_browser_page(dir.string());
  ::unsetenv("CHROMIUM");
  EXPECT_FALSE(run.ok);
  EXPECT_TRUE(run.unavailable);
  EXPECT_NE(run.error.find("/nonexistent/chromium"), std::string::npos) << run.error;
  fs::remove_all(dir);
}

}  // namespace
