// GLES compute backend: Mesa's GLES 3.2 compiler on llvmpipe (EGL surfaceless, gles_context.hpp).
// The context is made current on the calling thread for each batch and released after.
#include <algorithm>
#include <cstdio>
#include <cstring>

#include "runner/gles_context.hpp"

namespace doublet::runner::detail {
namespace {

// GL objects of one batch, deleted whatever happens.
struct GlObjects {
  GLuint shader = 0, program = 0;
  std::vector<GLuint> buffers;
  ~GlObjects() {
    if (!buffers.empty()) glDeleteBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
    if (program) glDeleteProgram(program);
    if (shader) glDeleteShader(shader);
    glGetError();  // do not leak an error into the next job
  }
};

std::string build_program(const std::string& glsl, GlObjects& gl, const std::string& device) {
  gl.shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* text = glsl.c_str();
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
  return {};
}

// One dispatch of an already linked program with the job's uniforms and buffers.
std::string dispatch(GlObjects& gl, const ComputeJob& job, ComputeResult* result) {
  glUseProgram(gl.program);
  if (std::string e = set_uniforms(gl.program, job.float_uniforms, job.uniforms); !e.empty()) return e;

  // Every active SSBO must have a buffer, or the dispatch would read unbound memory.
  GLint blocks = 0;
  glGetProgramInterfaceiv(gl.program, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
  for (GLint i = 0; i < blocks; ++i) {
    const GLenum prop = GL_BUFFER_BINDING;
    GLint binding = -1;
    glGetProgramResourceiv(gl.program, GL_SHADER_STORAGE_BLOCK, i, 1, &prop, 1, nullptr, &binding);
    if (binding < 0 || static_cast<size_t>(binding) >= job.buffers.size())
      return "shader declares an SSBO at binding " + std::to_string(binding) + " but the job has " +
             std::to_string(job.buffers.size()) + " buffer(s)";
  }
  GLint max_bindings = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &max_bindings);
  if (job.buffers.size() > static_cast<size_t>(max_bindings)) return "too many buffers for " + result->device;

  if (!gl.buffers.empty()) glDeleteBuffers(static_cast<GLsizei>(gl.buffers.size()), gl.buffers.data());
  gl.buffers.assign(job.buffers.size(), 0);
  if (!gl.buffers.empty()) glGenBuffers(static_cast<GLsizei>(gl.buffers.size()), gl.buffers.data());
  for (size_t i = 0; i < job.buffers.size(); ++i) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[i]);
    const std::vector<uint8_t>& data = job.buffers[i];
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<size_t>(data.size(), 16)), nullptr,
                 GL_DYNAMIC_COPY);
    if (!data.empty()) glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(data.size()), data.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(i), gl.buffers[i]);
  }
  if (std::string e = gl_error("uploading buffers"); !e.empty()) return e;

  glDispatchCompute(job.groups_x, job.groups_y, job.groups_z);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  if (std::string e = gl_error("glDispatchCompute"); !e.empty()) return e;

  result->buffers.resize(job.buffers.size());
  for (size_t i = 0; i < job.buffers.size(); ++i) {
    const size_t size = job.buffers[i].size();
    if (size == 0) continue;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[i]);
    const void* p = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(size), GL_MAP_READ_BIT);
    if (!p) return gl_error("glMapBufferRange") + " (buffer " + std::to_string(i) + ")";
    const auto* bytes = static_cast<const uint8_t*>(p);
    result->buffers[i].assign(bytes, bytes + size);
    glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  }
  return gl_error("reading buffers back");
}

std::vector<ComputeResult> run_jobs(const std::vector<ComputeJob>& jobs, const std::string& device) {
  std::vector<ComputeResult> results;
  glGetError();  // start clean
  GlObjects gl;
  std::string error = build_program(jobs[0].glsl, gl, device);
  for (size_t i = 0; i < jobs.size() && (i == 0 || results.back().ok); ++i) {
    ComputeResult result;
    result.device = device;
    result.error = error.empty() ? dispatch(gl, jobs[i], &result) : error;
    result.ok = result.error.empty();
    if (!result.ok) result.buffers.clear();
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace

std::string gles_unavailable_reason() { return shared_context().error; }

std::vector<ComputeResult> gles_run(const std::vector<ComputeJob>& jobs) {
  GlesContext& g = shared_context();
  ComputeResult failed;
  failed.device = g.renderer;
  if (!g.error.empty()) {
    failed.error = "GLES unavailable: " + g.error;
    return {failed};
  }
  std::lock_guard<std::mutex> lock(g.mu);
  if (!eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, g.context)) {
    failed.error = egl_error("eglMakeCurrent");
    return {failed};
  }
  std::vector<ComputeResult> results = run_jobs(jobs, g.renderer);
  eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);  // let other threads use it
  return results;
}

}  // namespace doublet::runner::detail
