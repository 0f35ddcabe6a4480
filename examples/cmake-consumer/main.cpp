// Runs the two lowered compute shaders on Mesa's GLES driver and checks them against the
// same computation in double on the CPU. The shaders come from the generated headers
// (doublet_lower_shaders(... EMBED)); the double uniforms are set through the manifest
// and the buffers filled with doublet's split helpers.
#include <GLES3/gl31.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <doublet/pack.hpp>
#include <doublet/split.hpp>

#include "gles_context.hpp"
#include "mandelbrot_zoom.comp.hpp"  // generated: doublet_shaders::mandelbrot_zoom_comp
#include "orbit_step.comp.hpp"       // generated: doublet_shaders::orbit_step_comp

namespace {

struct Program {
  GLuint id = 0;
  doublet::pack::Manifest manifest;
};

bool load(std::string_view source, std::string_view manifest_json, Program& p) {
  std::string log;
  p.id = compile_compute_program(std::string(source).c_str(), log);
  if (!p.id) return std::fprintf(stderr, "compile failed:\n%s\n", log.c_str()), false;
  auto manifest = doublet::pack::parse_manifest(manifest_json, &log);
  if (!manifest) return std::fprintf(stderr, "%s\n", log.c_str()), false;
  p.manifest = std::move(*manifest);
  glUseProgram(p.id);
  return true;
}

// A double (or dvecN) uniform: the manifest says which float uniforms it became.
bool set_double_uniform(const Program& p, const char* name, std::initializer_list<double> value) {
  const doublet::pack::Variable* v = p.manifest.find(name);
  if (!v) return std::fprintf(stderr, "uniform %s is not in the manifest\n", name), false;
  for (const auto& u : doublet::pack::uniform_values(*v, value)) {
    GLint location = glGetUniformLocation(p.id, u.name.c_str());
    if (u.components == 1) glUniform1fv(location, 1, u.value.data());
    if (u.components == 2) glUniform2fv(location, 1, u.value.data());
  }
  return true;
}

GLuint storage_buffer(const void* data, std::size_t bytes) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_COPY);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
  return buffer;
}

template <typename T>
std::vector<T> read_buffer(std::size_t count) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const void* mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(T)), GL_MAP_READ_BIT);
  std::vector<T> out(count);
  if (mapped) std::copy_n(static_cast<const T*>(mapped), count, out.data());
  glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  return out;
}

// 64 bodies in low Earth orbit, 2000 steps of 10 µs: each step moves a body ~8 cm at a
// radius of ~7000 km, far below float's resolution there (0.5 m).
bool run_orbits() {
  Program p;
  if (!load(doublet_shaders::orbit_step_comp::source, doublet_shaders::orbit_step_comp::manifest, p)) return false;
  const int bodies = 64, steps = 2000;
  const double mu = 3.986004418e14, dt = 1e-5;
  std::vector<double> state;  // x, y, vx, vy per body
  for (int b = 0; b < bodies; ++b) {
    double r = 6.771e6 + 1000.0 * b, angle = 0.1 * b, speed = std::sqrt(mu / r);
    state.insert(state.end(), {r * std::cos(angle), r * std::sin(angle), -speed * std::sin(angle), speed * std::cos(angle)});
  }
  std::vector<float> pairs(state.size() * 2);  // (hi, lo) per double: the shader's vec2
  doublet::split_interleaved(state, 1, pairs, 2);
  GLuint buffer = storage_buffer(pairs.data(), pairs.size() * sizeof(float));
  if (!set_double_uniform(p, "dt", {dt}) || !set_double_uniform(p, "mu", {mu})) return false;
  glUniform1i(glGetUniformLocation(p.id, "steps"), steps);
  glDispatchCompute(1, 1, 1);
  std::vector<float> result = read_buffer<float>(pairs.size());
  glDeleteBuffers(1, &buffer);

  double worst = 0;  // position error relative to the orbit radius
  for (int b = 0; b < bodies; ++b) {
    double* s = &state[4 * b];
    double px = s[0], py = s[1], vx = s[2], vy = s[3];
    for (int i = 0; i < steps; ++i) {  // the shader's algorithm, in double
      double r2 = px * px + py * py, k = mu * (1.0 / (r2 * std::sqrt(r2))) * dt;
      vx -= px * k, vy -= py * k;
      px += vx * dt, py += vy * dt;
    }
    double gx = doublet::join(result[8 * b], result[8 * b + 1]);
    double gy = doublet::join(result[8 * b + 2], result[8 * b + 3]);
    worst = std::fmax(worst, std::hypot(gx - px, gy - py) / std::hypot(px, py));
  }
  std::printf("orbit_step: %d bodies x %d steps, worst position error %.3g of the radius (float: ~1e-7)\n", bodies,
              steps, worst);
  return worst < 1e-10;
}

// 64x64 escape counts 1e-10 apart near -0.1011 + 0.9563i, where floats are 6e-8 apart.
bool run_zoom() {
  Program p;
  if (!load(doublet_shaders::mandelbrot_zoom_comp::source, doublet_shaders::mandelbrot_zoom_comp::manifest, p))
    return false;
  const double cx = -0.10109636384562, cy = 0.95628651080914, scale = 1e-10;
  const int max_iterations = 200;
  std::vector<unsigned> zeros(64 * 64, 0);
  GLuint buffer = storage_buffer(zeros.data(), zeros.size() * sizeof(unsigned));
  if (!set_double_uniform(p, "center", {cx, cy}) || !set_double_uniform(p, "scale", {scale})) return false;
  glUniform1i(glGetUniformLocation(p.id, "max_iterations"), max_iterations);
  glDispatchCompute(8, 8, 1);
  std::vector<unsigned> counts = read_buffer<unsigned>(zeros.size());
  glDeleteBuffers(1, &buffer);

  int same = 0, distinct = 0;
  std::vector<bool> seen(max_iterations + 1, false);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      double re = cx + (x - 32) * scale, im = cy + (y - 32) * scale, zr = 0, zi = 0;
      int n = 0;
      for (; n < max_iterations && zr * zr + zi * zi < 4.0; ++n) {
        double t = zr * zr - zi * zi + re;
        zi = 2.0 * zr * zi + im, zr = t;
      }
      unsigned got = counts[y * 64 + x];
      same += got == static_cast<unsigned>(n);
      if (got <= static_cast<unsigned>(max_iterations) && !seen[got]) seen[got] = true, ++distinct;
    }
  std::printf("mandelbrot_zoom: %d of 4096 escape counts equal the CPU's double, %d distinct values\n", same, distinct);
  return same >= 4096 * 9 / 10 && distinct >= 10;  // a float image would be flat
}

}  // namespace

int main() {
  if (std::string error = make_surfaceless_gles31_context(); !error.empty()) {
    std::fprintf(stderr, "GLES: %s\n", error.c_str());
    return 1;
  }
  std::printf("GL_RENDERER: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  bool ok = run_orbits();
  ok = run_zoom() && ok;
  std::printf(ok ? "OK\n" : "FAILED\n");
  return ok ? 0 : 1;
}
