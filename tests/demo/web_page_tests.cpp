// `doublet demo --web DIR` in the real headless Chromium (label browser): the page the CLI writes is
// opened over HTTP (runner::run_browser_page) and from file:// (tools/browser/open-file.mjs), its
// numbers are checked against thresholds that say what the demo is for (float-float shakes far
// below a pixel and matches JS doubles, fp32 does neither), and a page generated with the guard
// removed or the lo words dropped must fail those same checks.
#include <gtest/gtest.h>
#include <png.h>

#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "browser_test_util.hpp"
#include "runner/browser.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using doublet::cli_test::ProcessResult;
using doublet::cli_test::read_file;
using doublet::cli_test::run_process;
using doublet::cli_test::ScratchDir;
using json = nlohmann::json;

// What the page must show, per float-float mode (every mode but fp32): a vertex shakes by far
// less than a pixel, and the Mandelbrot's iteration counts equal JS doubles' on >= 99% of the
// checked pixels at every zoom. Returns the checks that failed, for `mode`.
std::vector<std::string> float_float_failures(const json& result, const std::string& mode) {
  std::vector<std::string> failed;
  const double wobble = result.at("jitter").at("modes").at(mode).at("wobble_px").get<double>();
  if (!(wobble < 0.01)) failed.push_back(mode + " jitter wobble " + std::to_string(wobble) + " px");
  for (const json& view : result.at("mandelbrot").at("views")) {
    const double match = view.at("modes").at(mode).at("match_fraction").get<double>();
    if (!(match >= 0.99))
      failed.push_back(mode + " mandelbrot at " + view.at("zoom").dump() + ": " + std::to_string(match));
  }
  return failed;
}

std::vector<std::string> float_float_modes(const json& result) {
  std::vector<std::string> modes;
  for (const json& m : result.at("modes"))
    if (m != "fp32") modes.push_back(m.get<std::string>());
  return modes;
}

// Writes the page with the real CLI; `extra` are more arguments (the hidden --sabotage).
fs::path make_page(const ScratchDir& scratch, const std::vector<std::string>& extra = {}) {
  const fs::path dir = scratch / "page";
  std::vector<std::string> args = {"demo", "--web", dir.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const ProcessResult r = run_process(DOUBLET_CLI_PATH, args, scratch.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("index.html"), std::string::npos) << r.out;
  return dir;
}

json open_page(const fs::path& dir, const std::string& screenshot = "") {
  doublet::runner::BrowserPageOptions options;
  options.screenshot = screenshot;
  const auto run = doublet::runner::run_browser_page(dir.string(), options);
  if (!run.ok) ADD_FAILURE() << run.error << "\n" << run.log;
  return run.ok ? json::parse(run.result_json) : json();
}

struct Png {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;
  // Distinct colours in a rectangle of the image.
  size_t colours(int x0, int y0, int w, int h) const {
    std::set<uint32_t> seen;
    for (int y = y0; y < y0 + h && y < height; ++y)
      for (int x = x0; x < x0 + w && x < width; ++x) {
        const uint8_t* p = &rgba[(static_cast<size_t>(y) * width + x) * 4];
        seen.insert(p[0] | p[1] << 8 | p[2] << 16);
      }
    return seen.size();
  }
  // Rows of a rectangle that hold more than one colour.
  int mixed_rows(int x0, int y0, int w, int h) const {
    int mixed = 0;
    for (int y = y0; y < y0 + h; ++y) mixed += colours(x0, y, w, 1) > 1;
    return mixed;
  }
};

bool read_png(const std::string& path, Png* out) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return false;
  image.format = PNG_FORMAT_RGBA;
  out->width = static_cast<int>(image.width);
  out->height = static_cast<int>(image.height);
  out->rgba.resize(PNG_IMAGE_SIZE(image));
  return png_image_finish_read(&image, nullptr, out->rgba.data(), 0, nullptr) != 0;
}

const json* panel(const json& result, const std::string& id) {
  for (const json& p : result.at("panels"))
    if (p.at("id") == id) return &p;
  return nullptr;
}

TEST(WebDemo, PageIsSelfContained) {
  ScratchDir scratch;
  const fs::path dir = make_page(scratch);
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path().filename().string());
  EXPECT_EQ(files, std::vector<std::string>{"index.html"});
  const std::string html = read_file(dir / "index.html");
  // Nothing to load: no URL, no external script/style/image, no fetch or import.
  for (const char* outside : {"http:", "https:", "src=", "href=", "<link", "@import", "fetch(", "import("})
    EXPECT_EQ(html.find(outside), std::string::npos) << outside;
  // The float-float shaders are doublet's output (its uniform guard), the fp32 ones demoted text.
  EXPECT_NE(html.find("- df_guard[int(df_guard[1])])"), std::string::npos);
  EXPECT_NE(html.find("in vec3 position;"), std::string::npos);  // fp32: dvec3 position demoted
}

TEST(WebDemo, NumbersScreenshotAndTimingsInChromium) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  ScratchDir scratch;
  const fs::path dir = make_page(scratch);
  const std::string shot = (scratch / "page.png").string();
  const json r = open_page(dir, shot);
  ASSERT_FALSE(r.is_null());
  EXPECT_EQ(r.at("loaded_from"), "http:");
  EXPECT_FALSE(r.at("renderer").get<std::string>().empty());
  EXPECT_TRUE(r.at("sabotage").is_null());

  // fp32 shakes by more than a pixel and misses the reference; the float-float modes pass.
  EXPECT_GT(r.at("jitter").at("modes").at("fp32").at("wobble_px").get<double>(), 1.0);
  for (const json& view : r.at("mandelbrot").at("views")) {
    EXPECT_LT(view.at("modes").at("fp32").at("match_fraction").get<double>(), 0.99) << view.dump();
    EXPECT_GT(view.at("reference_distinct_counts").get<int>(), 10) << "a flat view proves nothing";
    EXPECT_GE(view.at("checked_pixels").get<int>(), 1000);
  }
  const std::vector<std::string> modes = float_float_modes(r);
  ASSERT_FALSE(modes.empty());
  for (const std::string& mode : modes) EXPECT_EQ(float_float_failures(r, mode), std::vector<std::string>{});

  // A timing per mode and demo, positive.
  for (const json& mode : r.at("modes"))
    for (const char* demo : {"mandelbrot_ms", "jitter_ms"}) {
      const json& t = r.at("timing").at("modes").at(mode.get<std::string>()).at(demo);
      ASSERT_TRUE(t.is_number()) << mode << " " << demo;
      EXPECT_GT(t.get<double>(), 0.0) << mode << " " << demo;
    }

  // The screenshot: the page at the viewport's width, as tall as its panels, and showing them.
  Png png;
  ASSERT_TRUE(read_png(shot, &png)) << shot;
  EXPECT_EQ(png.width, 1280);  // run-page.mjs's viewport
  int bottom = 0;
  for (const json& p : r.at("panels")) bottom = std::max(bottom, p.at("y").get<int>() + p.at("height").get<int>());
  EXPECT_GE(png.height, bottom);
  const json* deep_fp32 = panel(r, "mandelbrot-1e-12-fp32");
  const json* deep_df64 = panel(r, "mandelbrot-1e-12-df64");
  const json* jitter_df64 = panel(r, "jitter-df64");
  ASSERT_TRUE(deep_fp32 && deep_df64 && jitter_df64) << r.at("panels").dump();
  auto colours = [&](const json* p) {
    return png.colours(p->at("x"), p->at("y"), p->at("width"), p->at("height"));
  };
  // At 1e-12 per pixel the pixels of a row share one float x (-1.7497591 + 1e-10 rounds back to
  // it): fp32 draws horizontal stripes. df64 shows detail along the rows too.
  auto mixed_rows = [&](const json* p) {
    return png.mixed_rows(p->at("x"), p->at("y"), p->at("width"), p->at("height"));
  };
  EXPECT_EQ(mixed_rows(deep_fp32), 0);
  EXPECT_GE(mixed_rows(deep_df64), 10);
  EXPECT_GE(colours(deep_df64), 20u);
  EXPECT_GE(colours(jitter_df64), 3u);  // background and lit box faces
}

TEST(WebDemo, OpensFromFileUrl) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  ScratchDir scratch;
  const fs::path dir = make_page(scratch);
  const std::string script = doublet::runner::browser_tools_dir() + "/open-file.mjs";
  const ProcessResult run = run_process("/usr/bin/env", {"node", script, (dir / "index.html").string()}, scratch.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json r = json::parse(run.out);
  EXPECT_EQ(r.at("loaded_from"), "file:");
  for (const std::string& mode : float_float_modes(r))
    EXPECT_EQ(float_float_failures(r, mode), std::vector<std::string>{});
}

// The sabotage: the page uploads every lo word as 0, so float-float works on float inputs; every
// float-float mode must fail both demos.
TEST(WebDemo, PageWithoutLoWordsFailsEveryCheck) {
  DOUBLET_REQUIRE_BROWSER_OR_SKIP();
  ScratchDir scratch;
  const json r = open_page(make_page(scratch, {"--sabotage", "drop-lo"}));
  ASSERT_FALSE(r.is_null());
  EXPECT_EQ(r.at("sabotage"), "drop-lo");
  for (const std::string& mode : float_float_modes(r)) {
    const std::vector<std::string> failed = float_float_failures(r, mode);
    EXPECT_EQ(failed.size(), 1 + r.at("mandelbrot").at("views").size()) << mode << ": " << r.dump();
  }
}

TEST(WebDemo, BadCommandLinesAreUsageErrors) {
  ScratchDir scratch;
  const std::string page = (scratch / "page").string();
  struct Case {
    std::vector<std::string> args;
    int exit_code;
    std::string message;
  };
  const Case cases[] = {
      {{"demo"}, 1, "say which demo"},
      {{"demo", "--web", page, "jitter"}, 1, "without jitter/mandelbrot"},
      {{"demo", "--web", page, "--sabotage", "everything"}, 1, "--sabotage takes"},
      {{"demo", "--sabotage", "no-guard", "jitter"}, 1, "--sabotage goes with --web"},
      // A file where the directory should be: an input error, not a crash.
      {{"demo", "--web", (scratch / "a-file" / "page").string()}, 2, "cannot create the directory"},
  };
  doublet::cli_test::write_file(scratch / "a-file", "not a directory");
  for (const Case& c : cases) {
    const ProcessResult r = run_process(DOUBLET_CLI_PATH, c.args, scratch.path());
    EXPECT_EQ(r.exit_code, c.exit_code) << c.args.back() << "\n" << r.err;
    EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(page));
}

}  // namespace
