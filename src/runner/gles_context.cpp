// The one EGL surfaceless GLES 3.2 context of the process (llvmpipe), shared by the GLES compute and
// graphics backends, and helpers both use.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl32.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "runner/gles_context.hpp"

namespace doublet::runner::detail {

std::string egl_error(const char* call) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string(call) + " failed: EGL error " + buf;
}

namespace {

bool has_extension(const char* list, const char* name) {
  if (!list) return false;
  const size_t len = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += len)
    if ((p == list || p[-1] == ' ') && (p[len] == ' ' || p[len] == '\0')) return true;
  return false;
}

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

}  // namespace

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

namespace {

// Sets a float matrix uniform from column-major values; false when `type` is no matrix or the count is wrong.
bool set_matrix(GLint location, GLenum type, const std::vector<double>& values) {
  using Setter = void (*)(GLint, GLsizei, GLboolean, const GLfloat*);
  struct Shape { GLenum type; size_t count; Setter set; };
  const Shape shapes[] = {{GL_FLOAT_MAT2, 4, glUniformMatrix2fv},     {GL_FLOAT_MAT3, 9, glUniformMatrix3fv},
                          {GL_FLOAT_MAT4, 16, glUniformMatrix4fv},    {GL_FLOAT_MAT2x3, 6, glUniformMatrix2x3fv},
                          {GL_FLOAT_MAT2x4, 8, glUniformMatrix2x4fv}, {GL_FLOAT_MAT3x2, 6, glUniformMatrix3x2fv},
                          {GL_FLOAT_MAT3x4, 12, glUniformMatrix3x4fv}, {GL_FLOAT_MAT4x2, 8, glUniformMatrix4x2fv},
                          {GL_FLOAT_MAT4x3, 12, glUniformMatrix4x3fv}};
  for (const Shape& s : shapes) {
    if (s.type != type) continue;
    if (values.size() != s.count) return false;
    float f[16];
    for (size_t i = 0; i < s.count; ++i) f[i] = static_cast<float>(values[i]);
    s.set(location, 1, GL_FALSE, f);
    return true;
  }
  return false;
}

// Sets an int/uint/bool scalar or vector uniform; false when `type` is none of them or the count is wrong.
bool set_integer_vector(GLint location, GLenum type, const std::vector<double>& values) {
  struct Shape { GLenum type; size_t count; bool is_unsigned; };
  static constexpr Shape kShapes[] = {
      {GL_INT, 1, false},  {GL_INT_VEC2, 2, false},  {GL_INT_VEC3, 3, false},  {GL_INT_VEC4, 4, false},
      {GL_BOOL, 1, false}, {GL_BOOL_VEC2, 2, false}, {GL_BOOL_VEC3, 3, false}, {GL_BOOL_VEC4, 4, false},
      {GL_UNSIGNED_INT, 1, true}, {GL_UNSIGNED_INT_VEC2, 2, true}, {GL_UNSIGNED_INT_VEC3, 3, true},
      {GL_UNSIGNED_INT_VEC4, 4, true}};
  for (const Shape& s : kShapes) {
    if (s.type != type) continue;
    if (values.size() != s.count) return false;
    GLint i[4] = {};
    GLuint u[4] = {};
    const bool is_bool = type == GL_BOOL || type == GL_BOOL_VEC2 || type == GL_BOOL_VEC3 || type == GL_BOOL_VEC4;
    for (size_t c = 0; c < s.count; ++c) {
      // Only the conversion the type needs: a uint above INT_MAX is no int, a negative int no uint.
      const double lowest = s.is_unsigned ? 0.0 : -2147483648.0;
      const double highest = s.is_unsigned ? 4294967295.0 : 2147483647.0;
      if (!is_bool && !(values[c] >= lowest && values[c] <= highest)) return false;
      if (is_bool) i[c] = values[c] != 0;
      else if (s.is_unsigned) u[c] = static_cast<GLuint>(values[c]);
      else i[c] = static_cast<GLint>(values[c]);
    }
    if (s.is_unsigned) {
      if (s.count == 1) glUniform1uiv(location, 1, u);
      else if (s.count == 2) glUniform2uiv(location, 1, u);
      else if (s.count == 3) glUniform3uiv(location, 1, u);
      else glUniform4uiv(location, 1, u);
    } else {
      if (s.count == 1) glUniform1iv(location, 1, i);
      else if (s.count == 2) glUniform2iv(location, 1, i);
      else if (s.count == 3) glUniform3iv(location, 1, i);
      else glUniform4iv(location, 1, i);
    }
    return true;
  }
  return false;
}

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
  if (size > 1 && (type == GL_UNSIGNED_INT_VEC4 || type == GL_INT_VEC4) && values->size() == 4 * size_t(size)) {
    std::vector<GLuint> u(values->size());  // an array of uvec4 (mode exact's matrix words), all elements
    for (size_t c = 0; c < u.size(); ++c) {
      const double v = (*values)[c];  // a word: a uint, or an int whose bits the array carries
      if (!(v >= -2147483648.0 && v <= 4294967295.0)) return "uniform '" + name + "': " + std::to_string(v) + " is no 32-bit word";
      u[c] = static_cast<GLuint>(static_cast<long long>(v));
    }
    if (type == GL_UNSIGNED_INT_VEC4) glUniform4uiv(location, size, u.data());
    else glUniform4iv(location, size, reinterpret_cast<const GLint*>(u.data()));
    return {};
  }
  if (size == 1 && set_matrix(location, type, *values)) return {};
  if (size == 1 && set_integer_vector(location, type, *values)) return {};
  const size_t components = type == GL_FLOAT ? 1 : type == GL_FLOAT_VEC2 ? 2 : type == GL_FLOAT_VEC3 ? 3
                            : type == GL_FLOAT_VEC4 ? 4 : 0;
  if (components == 0 || size != 1) return "uniform '" + name + "' is not a float scalar, vector or matrix";
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

}  // namespace

std::string set_uniforms(GLuint program, const std::map<std::string, float>& float_uniforms,
                         const std::map<std::string, std::vector<double>>& uniforms) {
  for (const auto& [name, value] : float_uniforms)
    if (std::string e = set_uniform(program, name, nullptr, value); !e.empty()) return e;
  for (const auto& [name, values] : uniforms)
    if (std::string e = set_uniform(program, name, &values, 0); !e.empty()) return e;
  return gl_error("glUniform*");
}

}  // namespace doublet::runner::detail
