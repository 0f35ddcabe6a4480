// `doublet demo jitter`: satellites at geostationary distance rendered with a double-precision
// vertex shader in each mode, and how much each mode makes their vertices wobble.
#pragma once

#include <string>
#include <vector>

#include "demo/modes.hpp"

namespace doublet::demo {

struct JitterOptions {
  std::vector<Mode> modes = all_modes();
  int frames = 48;
  int width = 320, height = 240;
  int strip_frames = 4;   // frames side by side in each mode's strip
  std::string out_dir;    // empty: measure only, write no pictures
};

struct JitterModeResult {
  Mode mode = Mode::Fp32;
  // Largest frame-to-frame change, over vertices, of a vertex's screen-space error against the
  // host-double reference, in pixels: the shake the viewer sees on top of the true motion.
  double max_wobble_px = 0;
  double max_error_px = 0;  // largest distance from the reference, pixels
  std::string device;       // driver that ran the vertex shader
};

struct JitterResult {
  bool ok = false;
  std::string error;
  std::vector<JitterModeResult> modes;
  std::vector<std::string> files;  // pictures written
};

JitterResult run_jitter(const JitterOptions&);

// The demo's vertex shader as an application would write it (doubles, GLSL ES 3.00).
extern const char* const kJitterVertexShader;

}  // namespace doublet::demo
