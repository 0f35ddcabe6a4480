// `doublet demo jitter|mandelbrot`: render the demos (src/demo) and print the numbers.
// `doublet demo --web DIR`: write the browser page (src/demo/web_page.*) into DIR.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "demo/jitter.hpp"
#include "demo/mandelbrot.hpp"
#include "demo/web_page.hpp"

namespace doublet::cli {
namespace {

struct DemoArgs {
  std::vector<std::string> modes;
  int frames = 48;
  std::vector<double> center;  // X,Y
  std::vector<double> zooms;
  std::string out_dir = "demo-out";
  std::string web_dir;               // --web DIR
  std::string web_sabotage = "none";  // hidden --sabotage, for the page's tests
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int fail(const std::string& what, const std::string& error) {
  std::cerr << "doublet demo " << what << ": error: " << error << "\n";
  return kExitInput;
}

int run_jitter_demo(const CLI::App& app, const DemoArgs& a) {
  demo::JitterOptions o;
  std::string error;
  if (!demo::parse_modes(a.modes, &o.modes, &error)) return usage_error(app, error);
  if (a.frames < 2) return usage_error(app, "--frames must be at least 2");
  o.frames = a.frames;
  o.out_dir = a.out_dir;
  const auto t0 = std::chrono::steady_clock::now();
  const demo::JitterResult r = demo::run_jitter(o);
  if (!r.ok) return fail("jitter", r.error);
  std::printf("jitter: two boxes %.2f m apart at %.0f m from the Earth's centre, camera 10-50 m away, %d frames %dx%d\n",
              2.75, 42164137.0, o.frames, o.width, o.height);
  std::printf("largest frame-to-frame wobble of a vertex vs the host-double reference:\n");
  for (const demo::JitterModeResult& m : r.modes)
    std::printf("  %-7s %12.6f px   (largest error %.6f px; %s)\n", std::string(demo::mode_name(m.mode)).c_str(),
                m.max_wobble_px, m.max_error_px, m.device.c_str());
  for (const std::string& f : r.files) std::printf("wrote %s\n", f.c_str());
  std::printf("took %.1f s\n", seconds_since(t0));
  return kExitOk;
}

int run_mandelbrot_demo(const CLI::App& app, const DemoArgs& a) {
  demo::MandelbrotOptions o;
  std::string error;
  if (!demo::parse_modes(a.modes, &o.modes, &error)) return usage_error(app, error);
  if (!a.center.empty()) {
    if (a.center.size() != 2) return usage_error(app, "--center takes X,Y");
    o.center_x = a.center[0];
    o.center_y = a.center[1];
  }
  if (!a.zooms.empty()) o.zooms = a.zooms;
  for (double z : o.zooms)
    if (!(z > 0)) return usage_error(app, "--zoom must be positive (complex-plane units per pixel)");
  o.out_dir = a.out_dir;
  const auto t0 = std::chrono::steady_clock::now();
  const demo::MandelbrotResult r = demo::run_mandelbrot(o);
  if (!r.ok) return fail("mandelbrot", r.error);
  std::printf("mandelbrot: centre (%.15g, %.15g), %dx%d, %d iterations; panels left to right:", o.center_x,
              o.center_y, o.width, o.height, o.max_iterations);
  for (demo::Mode m : o.modes) std::printf(" %s", std::string(demo::mode_name(m)).c_str());
  std::printf("\n");
  for (const demo::MandelbrotView& v : r.views) {
    std::printf("zoom %g per pixel (native shows %d different iteration counts):\n", v.zoom, v.native_distinct_counts);
    for (const demo::MandelbrotModeResult& m : v.modes) {
      std::printf("  %-7s", std::string(demo::mode_name(m.mode)).c_str());
      if (m.equal_to_native >= 0) std::printf(" %6.2f%% of pixels equal to native", 100 * m.equal_to_native);
      std::printf("  (%s)\n", m.device.c_str());
    }
    if (!v.file.empty()) std::printf("  wrote %s\n", v.file.c_str());
  }
  std::printf("took %.1f s\n", seconds_since(t0));
  return kExitOk;
}

int write_web_demo(const CLI::App& app, const DemoArgs& a) {
  demo::WebPageOptions o;
  const std::optional<demo::WebSabotage> sabotage = demo::parse_web_sabotage(a.web_sabotage);
  if (!sabotage) return usage_error(app, "--sabotage takes none, no-guard or drop-lo");
  o.sabotage = *sabotage;
  if (std::string e = demo::write_web_page(a.web_dir, o); !e.empty()) return fail("--web", e);
  const std::string page = (std::filesystem::path(a.web_dir) / "index.html").string();
  std::printf("wrote %s (self-contained: open it from the file system or any static server)\n", page.c_str());
  std::printf("modes:");
  for (Mode m : o.modes) std::printf(" %s", std::string(to_string(m)).c_str());
  if (o.sabotage != demo::WebSabotage::None)
    std::printf("  (SABOTAGED: %s)", std::string(demo::to_string(o.sabotage)).c_str());
  std::printf("\n");
  return kExitOk;
}

}  // namespace

Command add_demo_command(CLI::App& app) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* demo = app.add_subcommand(
      "demo", "Render the jitter and deep-zoom demos on Mesa's drivers, or write them as a web page (--web DIR)");
  demo->require_subcommand(0, 1);
  demo->add_option("--web", args->web_dir,
                   "Write DIR/index.html: both demos in WebGL2 per mode, checked and timed in the browser")
      ->type_name("DIR");
  // Tests and manual checks: drop-lo (the page uploads lo = 0) must fail every float-float panel;
  // no-guard (lowered without the optimizer guard) shows what a browser folds without it, nothing
  // on Chromium's stack since the split by bits (docs/demo.md). An empty group hides it from --help.
  demo->add_option("--sabotage", args->web_sabotage, "none | no-guard | drop-lo")->group("");
  const char* modes_help = "fp32 (doubles demoted to float), df64 (doublet), native (fp64 on lavapipe); default: all";
  CLI::App* jitter = demo->add_subcommand("jitter", "Satellites at geostationary distance: vertex wobble per mode");
  jitter->add_option("--mode", args->modes, modes_help)->delimiter(',');
  jitter->add_option("--frames", args->frames, "Frames of camera motion (default 48)");
  jitter->add_option("-o,--out-dir", args->out_dir, "Where the PNGs go (default demo-out)");
  CLI::App* mandel = demo->add_subcommand("mandelbrot", "Deep-zoom Mandelbrot per mode, side by side");
  mandel->add_option("--mode", args->modes, modes_help)->delimiter(',');
  mandel->add_option("--center", args->center, "View centre X,Y")->delimiter(',')->expected(2);
  mandel->add_option("--zoom", args->zooms, "Complex-plane units per pixel (default: 1e-7 and 1e-12)");
  mandel->add_option("-o,--out-dir", args->out_dir, "Where the PNGs go (default demo-out)");
  return {demo, [=] {
            const bool web = !args->web_dir.empty();
            if (web && (jitter->parsed() || mandel->parsed()))
              return usage_error(*demo, "--web writes the page of both demos: give it without jitter/mandelbrot");
            if (web) return write_web_demo(*demo, *args);
            if (demo->count("--web")) return usage_error(*demo, "--web needs a directory");
            if (args->web_sabotage != "none") return usage_error(*demo, "--sabotage goes with --web");
            if (!jitter->parsed() && !mandel->parsed())
              return usage_error(*demo, "say which demo: jitter, mandelbrot, or --web DIR");
            if (jitter->parsed()) return run_jitter_demo(*jitter, *args);
            return run_mandelbrot_demo(*mandel, *args);
          }};
}

}  // namespace doublet::cli
