// Offscreen triangle rendering on Mesa GLES (the runner's EGL surfaceless context, an FBO with colour
// and depth), capturing every vertex's gl_Position with transform feedback.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "demo/png_image.hpp"

namespace doublet::demo {

struct Attribute {
  std::string name;           // a vertex shader `in` (inactive or absent names are skipped)
  int components = 3;         // 1..4 floats per vertex
  std::vector<float> values;  // vertex_count × components
};

struct SceneFrame {
  std::vector<Attribute> attributes;
  std::map<std::string, float> float_uniforms;
  std::map<std::string, std::vector<double>> uniforms;  // float/vecN/matN, as runner::ComputeJob
};

struct SceneResult {
  bool ok = false;
  std::string error;
  std::string device;                      // GL_RENDERER
  std::vector<Image> images;               // one per frame
  std::vector<std::vector<float>> clip;    // per frame: vertex_count × 4 (gl_Position as drawn)
};

// Links vertex + fragment once, then draws `vertex_count` vertices as GL_TRIANGLES per frame.
SceneResult draw_scene(const std::string& vertex_glsl, const std::string& fragment_glsl, int vertex_count,
                       int width, int height, const std::vector<SceneFrame>& frames);

}  // namespace doublet::demo
