// draw_scene on the runner's shared GLES context (runner/gles_context.hpp): one EGL setup per process.
#include "demo/gles_scene.hpp"

#include <cstring>

#include "runner/gles_context.hpp"

namespace doublet::demo {
namespace {

using runner::detail::gl_error;
using runner::detail::info_log;

struct GlObjects {
  GLuint shaders[2] = {}, program = 0, framebuffer = 0, renderbuffers[2] = {}, vertex_array = 0;
  GLuint buffers[5] = {}, feedback = 0;  // buffers[0]: transform feedback, [1..4]: attributes
  ~GlObjects() {
    glDeleteBuffers(5, buffers);
    if (feedback) glDeleteTransformFeedbacks(1, &feedback);
    if (vertex_array) glDeleteVertexArrays(1, &vertex_array);
    glDeleteRenderbuffers(2, renderbuffers);
    if (framebuffer) glDeleteFramebuffers(1, &framebuffer);
    if (program) glDeleteProgram(program);
    for (GLuint s : shaders)
      if (s) glDeleteShader(s);
    glGetError();
  }
};

std::string link(const std::string& vs, const std::string& fs, GlObjects& gl) {
  const GLenum types[2] = {GL_VERTEX_SHADER, GL_FRAGMENT_SHADER};
  const std::string* texts[2] = {&vs, &fs};
  gl.program = glCreateProgram();
  for (int i = 0; i < 2; ++i) {
    gl.shaders[i] = glCreateShader(types[i]);
    const char* text = texts[i]->c_str();
    glShaderSource(gl.shaders[i], 1, &text, nullptr);
    glCompileShader(gl.shaders[i]);
    GLint ok = 0;
    glGetShaderiv(gl.shaders[i], GL_COMPILE_STATUS, &ok);
    if (!ok) return std::string(i ? "fragment" : "vertex") + " shader failed to compile:\n" + info_log(gl.shaders[i], false);
    glAttachShader(gl.program, gl.shaders[i]);
  }
  const char* captured[] = {"gl_Position"};
  glTransformFeedbackVaryings(gl.program, 1, captured, GL_INTERLEAVED_ATTRIBS);
  glLinkProgram(gl.program);
  GLint ok = 0;
  glGetProgramiv(gl.program, GL_LINK_STATUS, &ok);
  if (!ok) return "link failed:\n" + info_log(gl.program, true);
  return {};
}

std::string make_targets(GlObjects& gl, int width, int height, int vertex_count) {
  glGenFramebuffers(1, &gl.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, gl.framebuffer);
  glGenRenderbuffers(2, gl.renderbuffers);
  glBindRenderbuffer(GL_RENDERBUFFER, gl.renderbuffers[0]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gl.renderbuffers[0]);
  glBindRenderbuffer(GL_RENDERBUFFER, gl.renderbuffers[1]);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gl.renderbuffers[1]);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return "framebuffer incomplete";
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glGenVertexArrays(1, &gl.vertex_array);
  glBindVertexArray(gl.vertex_array);
  glGenBuffers(5, gl.buffers);
  glGenTransformFeedbacks(1, &gl.feedback);
  glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, gl.feedback);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, gl.buffers[0]);
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(vertex_count) * 16, nullptr, GL_DYNAMIC_READ);
  return gl_error("creating the framebuffer");
}

std::string draw_frame(GlObjects& gl, const SceneFrame& f, int vertex_count, int width, int height, SceneResult* out) {
  glUseProgram(gl.program);
  if (std::string e = runner::detail::set_uniforms(gl.program, f.float_uniforms, f.uniforms); !e.empty()) return e;
  if (f.attributes.size() > 4) return "at most 4 attributes";
  for (size_t i = 0; i < f.attributes.size(); ++i) {
    const Attribute& a = f.attributes[i];
    const GLint location = glGetAttribLocation(gl.program, a.name.c_str());
    if (location < 0) continue;
    if (a.values.size() != static_cast<size_t>(vertex_count * a.components)) return "attribute '" + a.name + "': wrong size";
    glBindBuffer(GL_ARRAY_BUFFER, gl.buffers[i + 1]);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(a.values.size() * 4), a.values.data(), GL_STREAM_DRAW);
    glEnableVertexAttribArray(static_cast<GLuint>(location));
    glVertexAttribPointer(static_cast<GLuint>(location), a.components, GL_FLOAT, GL_FALSE, 0, nullptr);
  }
  glClearColor(0.02f, 0.03f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBeginTransformFeedback(GL_TRIANGLES);
  glDrawArrays(GL_TRIANGLES, 0, vertex_count);
  glEndTransformFeedback();
  if (std::string e = gl_error("glDrawArrays"); !e.empty()) return e;

  Image image(width, height);
  std::vector<uint8_t> rows(image.rgba.size());
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  for (int y = 0; y < height; ++y)  // GL's row 0 is the bottom one
    std::memcpy(image.at(0, y), rows.data() + static_cast<size_t>(height - 1 - y) * width * 4, static_cast<size_t>(width) * 4);
  out->images.push_back(std::move(image));

  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, gl.buffers[0]);
  const size_t bytes = static_cast<size_t>(vertex_count) * 16;
  const void* p = glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLsizeiptr>(bytes), GL_MAP_READ_BIT);
  if (!p) return gl_error("glMapBufferRange") + " (transform feedback)";
  std::vector<float> clip(static_cast<size_t>(vertex_count) * 4);
  std::memcpy(clip.data(), p, bytes);
  glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
  out->clip.push_back(std::move(clip));
  return gl_error("reading the frame back");
}

}  // namespace

SceneResult draw_scene(const std::string& vertex_glsl, const std::string& fragment_glsl, int vertex_count, int width,
                       int height, const std::vector<SceneFrame>& frames) {
  runner::detail::GlesContext& g = runner::detail::shared_context();
  SceneResult out;
  out.device = g.renderer;
  if (!g.error.empty()) {
    out.error = "GLES unavailable: " + g.error;
    return out;
  }
  std::lock_guard<std::mutex> lock(g.mu);
  if (!eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, g.context)) {
    out.error = runner::detail::egl_error("eglMakeCurrent");
    return out;
  }
  {
    glGetError();
    GlObjects gl;
    out.error = link(vertex_glsl, fragment_glsl, gl);
    if (out.error.empty()) out.error = make_targets(gl, width, height, vertex_count);
    for (size_t i = 0; i < frames.size() && out.error.empty(); ++i)
      out.error = draw_frame(gl, frames[i], vertex_count, width, height, &out);
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
  }
  eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);  // let the runner use it
  out.ok = out.error.empty();
  return out;
}

}  // namespace doublet::demo
