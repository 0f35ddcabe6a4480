// The deep-zoom demo: per mode, the compute shader's iteration counts through runner::run_compute,
// coloured on the host, so equal counts mean equal pixels.
#include "demo/mandelbrot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <doublet/split.hpp>

#include "demo/png_image.hpp"
#include "runner/runner.hpp"

namespace doublet::demo {

const char* const kMandelbrotComputeShader = R"(#version 310 es
// Deep-zoom Mandelbrot, one invocation per pixel. Below ~1e-7 units per pixel neighbouring pixels
// share float coordinates; in double the view holds to ~1e-13.
layout(local_size_x = 8, local_size_y = 8) in;
uniform dvec2 center;          // complex-plane centre of the view
uniform double scale;          // complex-plane units per pixel
uniform vec2 resolution;       // pixels
uniform float max_iterations;
layout(std430, binding = 0) buffer Iterations { uint iterations[]; };

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (float(p.x) >= resolution.x || float(p.y) >= resolution.y) return;
  dvec2 c = center + dvec2(vec2(p) + 0.5 - 0.5 * resolution) * scale;
  dvec2 z = dvec2(0.0lf);
  uint n = 0u;
  uint limit = uint(max_iterations);
  while (n < limit && z.x * z.x + z.y * z.y < 4.0lf) {
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
    ++n;
  }
  iterations[p.y * uint(resolution.x) + p.x] = n;
}
)";

namespace {

void set_double(runner::ComputeJob& job, Mode mode, const std::string& name, std::vector<double> values) {
  if (mode != Mode::Df64) {
    job.uniforms[name] = std::move(values);  // fp32: the runner rounds to the declared float type
    return;
  }
  std::vector<double> hi, lo;
  for (double v : values) {
    const FloatPair p = split(v);
    hi.push_back(p.hi);
    lo.push_back(p.lo);
  }
  job.uniforms[name + "_hi"] = hi;
  job.uniforms[name + "_lo"] = lo;
}

std::string iterate(Mode mode, const MandelbrotOptions& o, double zoom, std::vector<uint32_t>* counts,
                    std::string* device) {
  std::string glsl, error;
  if (!shader_for_mode(mode, kMandelbrotComputeShader, Stage::Compute, Target::Es310, &glsl, &error)) return error;
  runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers.assign(1, std::vector<uint8_t>(static_cast<size_t>(o.width) * o.height * 4));
  set_double(job, mode, "center", {o.center_x, o.center_y});
  set_double(job, mode, "scale", {zoom});
  job.uniforms["resolution"] = {static_cast<double>(o.width), static_cast<double>(o.height)};
  job.float_uniforms["max_iterations"] = static_cast<float>(o.max_iterations);
  job.groups_x = static_cast<uint32_t>((o.width + 7) / 8);
  job.groups_y = static_cast<uint32_t>((o.height + 7) / 8);
  const runner::Backend backend = mode == Mode::Native ? runner::Backend::Vulkan : runner::Backend::Gles;
  const runner::ComputeResult r = runner::run_compute(backend, job);
  if (!r.ok) return std::string(mode_name(mode)) + " on " + runner::backend_name(backend) + ": " + r.error;
  *device = r.device;
  counts->resize(static_cast<size_t>(o.width) * o.height);
  std::memcpy(counts->data(), r.buffers[0].data(), counts->size() * 4);
  return {};
}

Image colour(const std::vector<uint32_t>& counts, int width, int height, int max_iterations) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t n = counts[static_cast<size_t>(height - 1 - y) * width + x];  // row 0 of the shader is the bottom
      uint8_t* px = image.at(x, y);
      if (n >= static_cast<uint32_t>(max_iterations)) continue;  // inside: black
      const double t = std::log2(1.0 + n) * 0.6;
      for (int k = 0; k < 3; ++k)
        px[k] = static_cast<uint8_t>(255 * (0.5 + 0.5 * std::cos(2 * M_PI * (t + k * 0.27 + 0.55))));
    }
  return image;
}

}  // namespace

MandelbrotResult run_mandelbrot(const MandelbrotOptions& o) {
  MandelbrotResult result;
  if (o.width < 8 || o.height < 8 || o.max_iterations < 1) {
    result.error = "mandelbrot needs at least 8x8 pixels and 1 iteration";
    return result;
  }
  for (double zoom : o.zooms) {
    MandelbrotView view;
    view.zoom = zoom;
    std::vector<std::vector<uint32_t>> counts;
    std::vector<Image> panels;
    const std::vector<uint32_t>* native = nullptr;
    for (Mode mode : o.modes) {
      MandelbrotModeResult m;
      m.mode = mode;
      counts.emplace_back();
      if (std::string e = iterate(mode, o, zoom, &counts.back(), &m.device); !e.empty()) {
        result.error = e;
        return result;
      }
      panels.push_back(colour(counts.back(), o.width, o.height, o.max_iterations));
      view.modes.push_back(m);
    }
    for (size_t i = 0; i < o.modes.size(); ++i)
      if (o.modes[i] == Mode::Native) native = &counts[i];
    if (native) {
      std::vector<uint32_t> sorted = *native;
      std::sort(sorted.begin(), sorted.end());
      view.native_distinct_counts = static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    }
    if (native)
      for (size_t i = 0; i < o.modes.size(); ++i) {
        size_t equal = 0;
        for (size_t p = 0; p < native->size(); ++p) equal += counts[i][p] == (*native)[p];
        view.modes[i].equal_to_native = static_cast<double>(equal) / static_cast<double>(native->size());
      }
    if (!o.out_dir.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(o.out_dir, ec);
      char name[64];
      std::snprintf(name, sizeof name, "mandelbrot_%.0e.png", zoom);
      view.file = (std::filesystem::path(o.out_dir) / name).string();
      if (std::string e = write_png(view.file, side_by_side(panels)); !e.empty()) {
        result.error = e;
        return result;
      }
    }
    result.views.push_back(std::move(view));
  }
  result.ok = true;
  return result;
}

}  // namespace doublet::demo
