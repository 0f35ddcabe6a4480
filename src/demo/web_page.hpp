// `doublet demo --web DIR`: one self-contained HTML page (inline script and style, the lowered
// shaders embedded as strings, nothing fetched, so it works from file:// and from any static
// server) that runs the deep-zoom Mandelbrot (a WebGL2 fragment shader) and the GEO jitter scene
// (a WebGL2 vertex shader) in every mode side by side, compares them with JavaScript doubles in
// the page, times them, and publishes the numbers as window.doubletResult (tools/browser/run-page.mjs).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <doublet/doublet.hpp>

namespace doublet::demo {

// The page's panels, left to right (doublet's own Mode, not demo::Mode of modes.hpp, which has
// no df64 variants). Mode::Fp32 is the shader with its doubles demoted to float;
// every other mode is doublet::lower with Options::mode set to it. A new mode is one more entry.
inline std::vector<doublet::Mode> web_page_modes() { return {doublet::Mode::Fp32, doublet::Mode::Df64, doublet::Mode::Df64Int}; }

// Hidden test option (--sabotage): a page whose float-float panels must fail their checks.
enum class WebSabotage {
  None,
  NoGuard,  // lowered with GuardKind::None: the browser's optimizer may fold the error terms
  DropLo,   // the page uploads every lo word as 0: float-float arithmetic on float inputs
};
std::optional<WebSabotage> parse_web_sabotage(std::string_view);  // "none" | "no-guard" | "drop-lo"
std::string_view to_string(WebSabotage);

struct WebPageOptions {
  std::vector<doublet::Mode> modes = web_page_modes();
  WebSabotage sabotage = WebSabotage::None;
  // Jitter: the scene of src/demo/jitter_scene.*, measured over this many frames of the camera path.
  int jitter_frames = 48;
  int jitter_width = 320, jitter_height = 240;
  // Mandelbrot: the view of `doublet demo mandelbrot`.
  double center_x = -1.7497591451303665, center_y = 0.0;
  std::vector<double> zooms = {1e-7, 1e-12};  // complex-plane units per pixel, one row each
  int mandelbrot_size = 256;                   // square panels
  int max_iterations = 1000;
  int reference_stride = 2;  // the JS-double reference checks every Nth pixel in x and y
  int timing_frames = 8;     // frames per timing cell
};

// The page's HTML, or false with *error (a lowering's diagnostics, or a mode the page cannot show).
bool make_web_page(const WebPageOptions&, std::string* html, std::string* error);

// Writes DIR/index.html (creating DIR). Returns "" or what went wrong.
std::string write_web_page(const std::string& dir, const WebPageOptions&);

// The demo's Mandelbrot as a WebGL2 fragment shader with doubles (GLSL ES 3.00): the compute
// shader of mandelbrot.cpp, one fragment per pixel, writing the iteration count to an R32UI target.
extern const char* const kMandelbrotFragmentShader;

}  // namespace doublet::demo
