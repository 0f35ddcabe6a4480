// The jitter demo: lower the shader per mode, draw every frame on GLES (native fp64: the vertex stage
// on lavapipe, its gl_Position then drawn on GLES), compare vertices with the host-double reference.
#include "demo/jitter.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <doublet/split.hpp>

#include "demo/gles_scene.hpp"
#include "demo/jitter_scene.hpp"
#include "runner/runner.hpp"

namespace doublet::demo {

const char* const kJitterVertexShader = R"(#version 300 es
// Satellites on a geostationary orbit seen from a camera 10-50 m away. Positions are Earth-centred
// metres (~4.2e7, where neighbouring floats are 2-4 m apart); the eye is subtracted in double.
in dvec3 position;             // Earth-centred, metres
in vec3 color;
uniform dvec3 eye;             // camera position, Earth-centred, metres
uniform mat4 view_projection;  // rotation and projection only
out vec3 v_color;

void main() {
  dvec3 relative = position - eye;
  v_color = color;
  gl_Position = view_projection * vec4(vec3(relative), 1.0);
}
)";

namespace {

const char* const kFragmentShader = R"(#version 300 es
precision highp float;
in vec3 v_color;
out vec4 frag_color;
void main() { frag_color = vec4(v_color, 1.0); }
)";

// Draws clip positions computed elsewhere (the native fp64 vertex stage on lavapipe).
const char* const kPassThroughVertexShader = R"(#version 300 es
in vec4 clip;
in vec3 color;
out vec3 v_color;
void main() { v_color = color; gl_Position = clip; }
)";

std::vector<double> vec3_of(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

// Per frame, the uniforms and attributes of `mode`'s shader.
std::vector<SceneFrame> frames_for(Mode mode, const JitterGeometry& g, const std::vector<JitterCamera>& cams) {
  SceneFrame base;
  base.attributes.push_back({"color", 3, g.colors});
  if (mode == Mode::Fp32) {
    base.attributes.push_back({"position", 3, std::vector<float>(g.positions.begin(), g.positions.end())});
  } else {
    Attribute hi{"position_hi", 3, std::vector<float>(g.positions.size())}, lo{"position_lo", 3, hi.values};
    split(g.positions, hi.values, lo.values);
    base.attributes.push_back(std::move(hi));
    base.attributes.push_back(std::move(lo));
  }
  std::vector<SceneFrame> frames;
  for (const JitterCamera& cam : cams) {
    SceneFrame f = base;
    f.uniforms["view_projection"] = std::vector<double>(cam.view_projection.begin(), cam.view_projection.end());
    if (mode == Mode::Fp32) {
      f.uniforms["eye"] = vec3_of(cam.eye);  // rounded to float by the runner's uniform setter
    } else {
      std::vector<double> hi, lo;
      for (double e : cam.eye) {
        const FloatPair p = split(e);
        hi.push_back(p.hi);
        lo.push_back(p.lo);
      }
      f.uniforms["eye_hi"] = hi;
      f.uniforms["eye_lo"] = lo;
    }
    frames.push_back(std::move(f));
  }
  return frames;
}

// Native fp64: the original shader's vertex stage on lavapipe; returns gl_Position per frame.
std::string native_clip(const JitterGeometry& g, const std::vector<JitterCamera>& cams,
                        std::vector<std::vector<float>>* clip, std::string* device) {
  std::string glsl, error;
  shader_for_mode(Mode::Native, kJitterVertexShader, Stage::Vertex, Target::Es300, &glsl, &error);
  std::vector<runner::GraphicsJob> jobs;
  for (const JitterCamera& cam : cams) {
    runner::GraphicsJob job;
    job.stage = runner::GraphicsStage::Vertex;
    job.glsl = glsl;
    job.count = static_cast<uint32_t>(g.vertex_count());
    job.inputs["position"] = g.positions;
    job.inputs["color"] = std::vector<double>(g.colors.begin(), g.colors.end());
    job.uniforms["eye"] = vec3_of(cam.eye);
    job.uniforms["view_projection"] = std::vector<double>(cam.view_projection.begin(), cam.view_projection.end());
    jobs.push_back(std::move(job));
  }
  const std::vector<runner::GraphicsResult> results = runner::run_graphics_batch(runner::Backend::Vulkan, jobs);
  if (results.size() != jobs.size() || !results.back().ok)
    return "native fp64 vertex stage on lavapipe failed: " + results.back().error;
  *device = results[0].device;
  for (const runner::GraphicsResult& r : results) {
    const std::vector<double>& p = r.outputs.at("gl_Position");
    clip->emplace_back(p.begin(), p.end());
  }
  return {};
}

void measure(const std::vector<std::vector<float>>& clip, const std::vector<std::vector<double>>& reference, int width,
             int height, JitterModeResult* out) {
  auto pixel = [&](double x, double y, double w, int axis) { return ((axis ? y : x) / w * 0.5 + 0.5) * (axis ? height : width); };
  std::vector<double> previous;
  for (size_t f = 0; f < clip.size(); ++f) {
    std::vector<double> error;  // per vertex: dx, dy in pixels
    for (size_t v = 0; v * 4 < clip[f].size(); ++v) {
      const float* c = &clip[f][v * 4];
      const double* r = &reference[f][v * 4];
      for (int axis = 0; axis < 2; ++axis)
        error.push_back(pixel(c[0], c[1], c[3], axis) - pixel(r[0], r[1], r[3], axis));
      out->max_error_px = std::max(out->max_error_px, std::hypot(error[error.size() - 2], error.back()));
    }
    for (size_t k = 0; k + 1 < previous.size(); k += 2)
      out->max_wobble_px =
          std::max(out->max_wobble_px, std::hypot(error[k] - previous[k], error[k + 1] - previous[k + 1]));
    previous = std::move(error);
  }
}

std::string write_pictures(Mode mode, const std::vector<Image>& images, const JitterOptions& o, JitterResult* result) {
  namespace fs = std::filesystem;
  const std::string name(mode_name(mode));
  const fs::path dir = fs::path(o.out_dir) / "jitter_frames";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create " + dir.string() + ": " + ec.message();
  for (size_t i = 0; i < images.size(); ++i) {
    char file[64];
    std::snprintf(file, sizeof file, "%s_%03zu.png", name.c_str(), i);
    if (std::string e = write_png((dir / file).string(), images[i]); !e.empty()) return e;
  }
  std::vector<Image> strip;
  const int n = std::min<int>(o.strip_frames, static_cast<int>(images.size()));
  for (int k = 0; k < n; ++k) strip.push_back(images[n > 1 ? k * (images.size() - 1) / (n - 1) : 0]);
  const std::string path = (fs::path(o.out_dir) / ("jitter_" + name + ".png")).string();
  if (std::string e = write_png(path, side_by_side(strip)); !e.empty()) return e;
  result->files.push_back(path);
  result->files.push_back((dir / (name + "_NNN.png")).string());
  return {};
}

}  // namespace

JitterResult run_jitter(const JitterOptions& o) {
  JitterResult result;
  if (o.frames < 2 || o.width < 8 || o.height < 8) {
    result.error = "jitter needs at least 2 frames of at least 8x8 pixels";
    return result;
  }
  const JitterGeometry geometry = jitter_geometry();
  std::vector<JitterCamera> cams;
  std::vector<std::vector<double>> reference;
  for (int i = 0; i < o.frames; ++i) {
    cams.push_back(jitter_camera(i, o.frames, static_cast<double>(o.width) / o.height));
    reference.push_back(reference_clip(geometry, cams.back()));
  }
  for (Mode mode : o.modes) {
    JitterModeResult m;
    m.mode = mode;
    SceneResult scene;
    if (mode == Mode::Native) {
      std::vector<std::vector<float>> clip;
      if (std::string e = native_clip(geometry, cams, &clip, &m.device); !e.empty()) {
        result.error = e;
        return result;
      }
      std::vector<SceneFrame> frames;
      for (const auto& c : clip) frames.push_back({{{"clip", 4, c}, {"color", 3, geometry.colors}}, {}, {}});
      scene = draw_scene(kPassThroughVertexShader, kFragmentShader, geometry.vertex_count(), o.width, o.height, frames);
      scene.clip = clip;  // measure what lavapipe computed (drawing it again on GLES is exact anyway)
    } else {
      std::string vs;
      if (!shader_for_mode(mode, kJitterVertexShader, Stage::Vertex, Target::Es300, &vs, &result.error)) return result;
      scene = draw_scene(vs, kFragmentShader, geometry.vertex_count(), o.width, o.height,
                         frames_for(mode, geometry, cams));
      m.device = scene.device;
    }
    if (!scene.ok) {
      result.error = std::string(mode_name(mode)) + ": " + scene.error;
      return result;
    }
    measure(scene.clip, reference, o.width, o.height, &m);
    if (!o.out_dir.empty())
      if (std::string e = write_pictures(mode, scene.images, o, &result); !e.empty()) {
        result.error = e;
        return result;
      }
    result.modes.push_back(m);
  }
  result.ok = true;
  return result;
}

}  // namespace doublet::demo
