// GLES backend: Mesa's GLES 3.2 compiler on llvmpipe, through an EGL surfaceless context made once
// per process. The context is made current on the calling thread for each job and released after.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl32.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <mutex>

#include "runner/internal.hpp"

namespace doublet::runner::detail {
namespace {

std::string egl_error(const char* call) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string(call) + " failed: EGL error " + buf;
}

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t len = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += len)
    if ((p == list || p[-1] == ' ') && (p[len] == ' ' || p[len] == '\0')) return true;
  return false;
}

struct GlesContext {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string renderer;
  std::string error;  // non-empty: unusable, and why
  std::mutex mu;      // one EGL context, current on one thread at a time
};

EGLDisplay open_display() {
  const char* client_exts = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_extension(client_exts, "EGL_MESA_platform_surfaceless")) {
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display) {
      EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY) return d;
    }
  }
  return eglGetDisplay(EGL_DEFAULT_DISPLAY);  // fallback for EGLs without the surfaceless platform
}

std::string init(GlesContext& g) {
  g.display = open_display();
  if (g.display == EGL_NO_DISPLAY) return egl_error("eglGetPlatformDisplayEXT(SURFACELESS_MESA)/eglGetDisplay");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(g.display, &major, &minor)) return egl_error("eglInitialize");
  const char* exts = eglQueryString(g.display, EGL_EXTENSIONS);
  if (!has_extension(exts, "EGL_KHR_surfaceless_context"))
    return "EGL display lacks EGL_KHR_surfaceless_context (needed to compute without a surface)";
  if (!eglBindAPI(EGL_OPENGL_ES_API)) return egl_error("eglBindAPI(EGL_OPENGL_ES_API)");

  EGLConfig config = nullptr;  // EGL_NO_CONFIG_KHR
  if (!has_extension(exts, "EGL_KHR_no_config_context")) {
    const EGLint want[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
    EGLint n = 0;
    if (!eglChooseConfig(g.display, want, &config, 1, &n) || n < 1) return egl_error("eglChooseConfig(ES3)");
  }
  const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
  g.context = eglCreateContext(g.display, config, EGL_NO_CONTEXT, attribs);
  if (g.context == EGL_NO_CONTEXT) return egl_error("eglCreateContext(ES 3.2)");
  if (!eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, g.context)) return egl_error("eglMakeCurrent");
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  g.renderer = renderer ? renderer : "(unknown GL_RENDERER)";
  eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  return {};
}

GlesContext& shared_context() {
  static GlesContext* g = [] {  // never destroyed, like the Vulkan device
    auto* ctx = new GlesContext;
    ctx->error = init(*ctx);
    return ctx;
  }();
  return *g;
}

std::string gl_error(const char* where) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return {};
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", e);
  return std::string("GL error ") + buf + " after " + where;
}

std::string info_log(GLuint object, bool is_program) {
  GLint len = 0;
  is_program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &len) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
  is_program ? glGetProgramInfoLog(object, len, nullptr, log.data()) : glGetShaderInfoLog(object, len, nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  return log;
}

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

std::string set_uniform(GLuint program, const std::string& name, const std::vector<double>* values, float value) {
  GLuint index = GL_INVALID_INDEX;
  const char* cname = name.c_str();
  glGetUniformIndices(program, 1, &cname, &index);
  if (index == GL_INVALID_INDEX) return {};  // inactive or absent: GL ignores it too
  GLint size = 0;
  GLenum type = 0;
  char dummy[1];
  glGetActiveUniform(program, index, 0, nullptr, &size, &type, dummy);
  const GLint location = glGetUniformLocation(program, cname);
  if (!values) {
    if (type != GL_FLOAT) return "uniform '" + name + "' is not a float; float_uniforms can only set floats";
    glUniform1f(location, value);
    return {};
  }
  const size_t components = type == GL_FLOAT ? 1 : type == GL_FLOAT_VEC2 ? 2 : type == GL_FLOAT_VEC3 ? 3
                            : type == GL_FLOAT_VEC4 ? 4 : 0;
  if (components == 0 || size != 1) return "uniform '" + name + "' is not a float scalar or vector";
  if (values->size() != components)
    return "uniform '" + name + "' has " + std::to_string(components) + " component(s), job gives " +
           std::to_string(values->size());
  float f[4] = {};
  for (size_t c = 0; c < components; ++c) f[c] = static_cast<float>((*values)[c]);
  switch (components) {
    case 1: glUniform1fv(location, 1, f); break;
    case 2: glUniform2fv(location, 1, f); break;
    case 3: glUniform3fv(location, 1, f); break;
    default: glUniform4fv(location, 1, f); break;
  }
  return {};
}

std::string set_uniforms(GLuint program, const ComputeJob& job) {
  for (const auto& [name, value] : job.float_uniforms)
    if (std::string e = set_uniform(program, name, nullptr, value); !e.empty()) return e;
  for (const auto& [name, values] : job.uniforms)
    if (std::string e = set_uniform(program, name, &values, 0); !e.empty()) return e;
  return gl_error("glUniform*");
}

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
  if (std::string e = set_uniforms(gl.program, job); !e.empty()) return e;

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
