// GLES half of run_compute_timed. Device time comes from GL_EXT_disjoint_timer_query
// (GL_TIME_ELAPSED_EXT around the dispatch) when the context exposes it; otherwise the dispatch
// is bracketed by glFinish() on the CPU clock. TimedResult::clock says which.
#include <algorithm>
#include <chrono>
#include <cstring>
#include <mutex>

#include "runner/gles_context.hpp"
#include "runner/timed_compute.hpp"

namespace doublet::runner::detail {
namespace {

// From GL_EXT_disjoint_timer_query (gl2ext.h does not combine with gl32.h, so spelled out here).
constexpr GLenum kTimeElapsed = 0x88BF;  // GL_TIME_ELAPSED_EXT
constexpr GLenum kGpuDisjoint = 0x8FBB;  // GL_GPU_DISJOINT_EXT
using GetQueryObjectui64v = void(GL_APIENTRYP)(GLuint id, GLenum pname, GLuint64* params);

struct TimerQueryApi {
  GetQueryObjectui64v get_ui64 = nullptr;
  bool available() const { return get_ui64 != nullptr; }
};

TimerQueryApi timer_query_api() {
  TimerQueryApi api;
  const auto* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (ext && std::strstr(ext, "GL_EXT_disjoint_timer_query"))
    api.get_ui64 = reinterpret_cast<GetQueryObjectui64v>(eglGetProcAddress("glGetQueryObjectui64vEXT"));
  return api;
}

struct GlTimedObjects {
  GLuint shader = 0, program = 0, query = 0;
  std::vector<GLuint> buffers;
  ~GlTimedObjects() {
    if (query) glDeleteQueries(1, &query);
    if (!buffers.empty()) glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (program) glDeleteProgram(program);
    if (shader) glDeleteShader(shader);
    glGetError();
  }
};

std::string run(const ComputeJob& job, int warmup, int reps, const std::string& device, TimedResult* out) {
  const auto start = std::chrono::steady_clock::now();
  glGetError();
  GlTimedObjects gl;
  gl.shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = job.glsl.c_str();
  glShaderSource(gl.shader, 1, &text, nullptr);
  glCompileShader(gl.shader);
  GLint status = 0;
  glGetShaderiv(gl.shader, GL_COMPILE_STATUS, &status);
  if (!status) return "GLSL compile failed (GLES, " + device + "):\n" + info_log(gl.shader, false);
  gl.program = glCreateProgram();
  glAttachShader(gl.program, gl.shader);
  glLinkProgram(gl.program);
  glGetProgramiv(gl.program, GL_LINK_STATUS, &status);
  if (!status) return "GLSL link failed (GLES, " + device + "):\n" + info_log(gl.program, true);
  glUseProgram(gl.program);
  if (std::string e = set_uniforms(gl.program, job.float_uniforms, job.uniforms); !e.empty()) return e;

  gl.buffers.assign(job.buffers.size(), 0);
  if (!gl.buffers.empty()) glGenBuffers(static_cast<GLsizei>(gl.buffers.size()), gl.buffers.data());
  for (size_t i = 0; i < job.buffers.size(); ++i) {
    const std::vector<uint8_t>& data = job.buffers[i];
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[i]);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<size_t>(data.size(), 16)), nullptr,
                 GL_DYNAMIC_COPY);
    if (!data.empty()) glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(data.size()), data.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(i), gl.buffers[i]);
  }
  if (std::string e = gl_error("uploading buffers"); !e.empty()) return e;

  const TimerQueryApi timer = timer_query_api();
  if (timer.available()) glGenQueries(1, &gl.query);
  out->clock = timer.available() ? "GL_EXT_disjoint_timer_query" : "glFinish-bracketed CPU time";
  glFinish();  // uploads (and compilation, which Mesa may defer to first use) stay out of the samples
  for (int rep = 0; rep < warmup + reps; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    if (gl.query) glBeginQuery(kTimeElapsed, gl.query);
    glDispatchCompute(job.groups_x, job.groups_y, job.groups_z);
    if (gl.query) glEndQuery(kTimeElapsed);
    glFinish();
    const auto done = std::chrono::steady_clock::now();
    double seconds = std::chrono::duration<double>(done - t0).count();
    if (rep == 0 && out->first_result_seconds == 0)
      out->first_result_seconds = std::chrono::duration<double>(done - start).count();
    if (gl.query) {
      GLuint64 ns = 0;
      timer.get_ui64(gl.query, GL_QUERY_RESULT, &ns);
      GLint disjoint = 0;
      glGetIntegerv(kGpuDisjoint, &disjoint);
      if (disjoint) return "GL_GPU_DISJOINT_EXT set during a timed dispatch";
      // llvmpipe exposes the extension but its TIME_ELAPSED only covers rasterizer work: a compute
      // dispatch reads ~0. A query far below the CPU bracket measured nothing; use the bracket.
      if (static_cast<double>(ns) * 1e-9 < 0.01 * seconds) {
        glDeleteQueries(1, &gl.query);
        gl.query = 0;
        out->clock = "glFinish-bracketed CPU time (GL_EXT_disjoint_timer_query reads ~0 for compute here)";
        out->seconds.clear();
        if (rep >= warmup) --rep;  // this sample was taken with the wrong clock: take it again
        continue;
      }
      seconds = static_cast<double>(ns) * 1e-9;
    }
    if (std::string e = gl_error("timed glDispatchCompute"); !e.empty()) return e;
    if (rep >= warmup) out->seconds.push_back(seconds);
  }
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  out->buffers.resize(job.buffers.size());
  for (size_t i = 0; i < job.buffers.size(); ++i) {
    const size_t size = job.buffers[i].size();
    if (size == 0) continue;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[i]);
    const void* p = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(size), GL_MAP_READ_BIT);
    if (!p) return gl_error("glMapBufferRange");
    out->buffers[i].assign(static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + size);
    glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  }
  return gl_error("reading buffers back");
}

}  // namespace

TimedResult gles_run_timed(const ComputeJob& job, int warmup, int repetitions) {
  GlesContext& g = shared_context();
  TimedResult r;
  r.device = g.renderer;
  if (!g.error.empty()) {
    r.error = "GLES unavailable: " + g.error;
    return r;
  }
  std::lock_guard<std::mutex> lock(g.mu);
  if (!eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, g.context)) {
    r.error = egl_error("eglMakeCurrent");
    return r;
  }
  r.error = run(job, warmup, repetitions, g.renderer, &r);
  r.ok = r.error.empty();
  eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  return r;
}

}  // namespace doublet::runner::detail
