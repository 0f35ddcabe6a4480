// GLES graphics backend: the wrapped stages (graphics_wrapper.hpp) linked by Mesa's GLES compiler
// and drawn on llvmpipe into a framebuffer without attachments (the wrapper stores its outputs in a
// storage buffer, so nothing is rendered): points for vertex and fragment jobs, the geometry
// shader's input primitives, or patches for tessellation (ES 3.2 has both stages).
#include <algorithm>
#include <cstring>

#include "runner/gles_context.hpp"
#include "runner/graphics_wrapper.hpp"

namespace doublet::runner::detail {
namespace {

struct GlGraphicsObjects {
  GLuint shaders[5] = {}, program = 0, framebuffer = 0, vertex_array = 0, buffers[2] = {};
  std::vector<std::string> block_names;  // active named uniform blocks; block i uses binding i
  std::vector<GLuint> block_buffers, textures;
  ~GlGraphicsObjects() {
    glDeleteBuffers(2, buffers);
    if (!block_buffers.empty()) glDeleteBuffers(static_cast<GLsizei>(block_buffers.size()), block_buffers.data());
    if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
    if (vertex_array) glDeleteVertexArrays(1, &vertex_array);
    if (framebuffer) glDeleteFramebuffers(1, &framebuffer);
    if (program) glDeleteProgram(program);
    for (GLuint s : shaders)
      if (s) glDeleteShader(s);
    glGetError();  // do not leak an error into the next job
  }
};

// The runner's test texture (runner.hpp) for a sampler of GL type `type`; 0 for other types.
GLuint make_test_texture(GLenum type) {
  const TextureKind kind = type == GL_SAMPLER_3D ? TextureKind::Tex3D : type == GL_SAMPLER_CUBE ? TextureKind::Cube
                                                                                                 : TextureKind::Tex2D;
  const GLenum target = kind == TextureKind::Tex3D ? GL_TEXTURE_3D : kind == TextureKind::Cube ? GL_TEXTURE_CUBE_MAP
                                                                                               : GL_TEXTURE_2D;
  const std::vector<float> texels = test_texture(kind);
  const auto n = static_cast<GLsizei>(kTextureSize);
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(target, texture);
  if (kind == TextureKind::Tex3D) {
    glTexImage3D(target, 0, GL_RGBA32F, n, n, n, 0, GL_RGBA, GL_FLOAT, texels.data());
  } else if (kind == TextureKind::Cube) {
    for (GLenum face = 0; face < 6; ++face)
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT,
                   texels.data() + size_t{face} * kTextureSize * kTextureSize * 4);
  } else {
    glTexImage2D(target, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT, texels.data());
  }
  // RGBA32F is not filterable in GLES 3.2: NEAREST, one level (as on Vulkan).
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const GLint wrap = kind == TextureKind::Cube ? GL_CLAMP_TO_EDGE : GL_REPEAT;
  glTexParameteri(target, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, wrap);
  glTexParameteri(target, GL_TEXTURE_WRAP_R, wrap);
  return texture;
}

// Every active sampler gets its own texture unit with the test texture; every named uniform block
// binding i, filled per job.
std::string bind_resources(GlGraphicsObjects& gl) {
  glUseProgram(gl.program);
  GLint count = 0;
  glGetProgramiv(gl.program, GL_ACTIVE_UNIFORMS, &count);
  GLint unit = 0;
  for (GLint i = 0; i < count; ++i) {
    char name[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(gl.program, static_cast<GLuint>(i), sizeof name, nullptr, &size, &type, name);
    if (type != GL_SAMPLER_2D && type != GL_SAMPLER_3D && type != GL_SAMPLER_CUBE) continue;
    const GLenum target = type == GL_SAMPLER_3D ? GL_TEXTURE_3D : type == GL_SAMPLER_CUBE ? GL_TEXTURE_CUBE_MAP
                                                                                          : GL_TEXTURE_2D;
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    gl.textures.push_back(make_test_texture(type));
    glBindTexture(target, gl.textures.back());
    glUniform1i(glGetUniformLocation(gl.program, name), unit++);
  }
  glActiveTexture(GL_TEXTURE0);
  GLint blocks = 0;
  glGetProgramiv(gl.program, GL_ACTIVE_UNIFORM_BLOCKS, &blocks);
  for (GLint i = 0; i < blocks; ++i) {
    char name[256];
    glGetActiveUniformBlockName(gl.program, static_cast<GLuint>(i), sizeof name, nullptr, name);
    glUniformBlockBinding(gl.program, static_cast<GLuint>(i), static_cast<GLuint>(i));
    gl.block_names.push_back(name);
  }
  gl.block_buffers.assign(gl.block_names.size(), 0);
  if (!gl.block_buffers.empty()) glGenBuffers(static_cast<GLsizei>(gl.block_buffers.size()), gl.block_buffers.data());
  return gl_error("binding textures and uniform blocks");
}

// The job's bytes of every named uniform block (zeros for a block it does not give).
std::string upload_blocks(GlGraphicsObjects& gl, const GraphicsJob& job) {
  for (size_t i = 0; i < gl.block_names.size(); ++i) {
    GLint size = 0;
    glGetActiveUniformBlockiv(gl.program, static_cast<GLuint>(i), GL_UNIFORM_BLOCK_DATA_SIZE, &size);
    auto given = job.uniform_blocks.find(gl.block_names[i]);
    std::vector<uint8_t> bytes = given == job.uniform_blocks.end() ? std::vector<uint8_t>() : given->second;
    bytes.resize(std::max<size_t>(bytes.size(), static_cast<size_t>(std::max(size, 16))), 0);
    glBindBuffer(GL_UNIFORM_BUFFER, gl.block_buffers[i]);
    glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(bytes.size()), bytes.data(), GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, static_cast<GLuint>(i), gl.block_buffers[i]);
  }
  return gl_error("uploading uniform blocks");
}

const char* stage_name(GLenum type) {
  switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_TESS_CONTROL_SHADER: return "tessellation control";
    case GL_TESS_EVALUATION_SHADER: return "tessellation evaluation";
    case GL_GEOMETRY_SHADER: return "geometry";
    default: return "fragment";
  }
}

std::string link(const WrappedProgram& w, GlGraphicsObjects& gl, const std::string& device) {
  const std::pair<GLenum, const std::string*> stages[5] = {{GL_VERTEX_SHADER, &w.vertex},
                                                           {GL_TESS_CONTROL_SHADER, &w.tess_control},
                                                           {GL_TESS_EVALUATION_SHADER, &w.tess_evaluation},
                                                           {GL_GEOMETRY_SHADER, &w.geometry},
                                                           {GL_FRAGMENT_SHADER, &w.fragment}};
  gl.program = glCreateProgram();
  for (int i = 0; i < 5; ++i) {
    const auto& [type, source] = stages[i];
    if (source->empty()) continue;
    gl.shaders[i] = glCreateShader(type);
    const char* text = source->c_str();
    glShaderSource(gl.shaders[i], 1, &text, nullptr);
    glCompileShader(gl.shaders[i]);
    GLint status = 0;
    glGetShaderiv(gl.shaders[i], GL_COMPILE_STATUS, &status);
    if (!status)
      return std::string("GLSL compile failed (GLES ") + stage_name(type) + ", " + device + "):\n" +
             info_log(gl.shaders[i], false);
    glAttachShader(gl.program, gl.shaders[i]);
  }
  glLinkProgram(gl.program);
  GLint status = 0;
  glGetProgramiv(gl.program, GL_LINK_STATUS, &status);
  if (!status) return "GLSL link failed (GLES, " + device + "):\n" + info_log(gl.program, true);
  // A framebuffer with no attachments (ES 3.1) gives the fragment stage its grid of pixels.
  glGenFramebuffers(1, &gl.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, gl.framebuffer);
  glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, static_cast<GLint>(kGridWidth));
  glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, static_cast<GLint>(kGridHeight));
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) return "attachment-less framebuffer incomplete";
  glViewport(0, 0, static_cast<GLsizei>(kGridWidth), static_cast<GLsizei>(kGridHeight));
  glGenVertexArrays(1, &gl.vertex_array);
  glBindVertexArray(gl.vertex_array);
  glGenBuffers(2, gl.buffers);
  if (std::string e = gl_error("setting up the program"); !e.empty()) return e;
  return bind_resources(gl);
}

std::string draw(const WrappedProgram& w, GlGraphicsObjects& gl, const GraphicsJob& job, uint32_t count,
                 GraphicsResult* result) {
  glUseProgram(gl.program);
  if (std::string e = set_uniforms(gl.program, job.float_uniforms, job.uniforms); !e.empty()) return e;
  if (std::string e = upload_blocks(gl, job); !e.empty()) return e;
  std::vector<uint8_t> inputs;
  if (std::string e = pack_inputs(w.iface, job, &inputs); !e.empty()) return e;
  const std::vector<uint8_t> outputs = blank_outputs(w.iface, count);
  const std::vector<uint8_t>* data[2] = {&inputs, &outputs};
  const GLuint bindings[2] = {kInputBinding, kOutputBinding};
  for (int i = 0; i < 2; ++i) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[i]);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(data[i]->size()), data[i]->data(), GL_DYNAMIC_COPY);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings[i], gl.buffers[i]);
  }
  if (std::string e = gl_error("uploading buffers"); !e.empty()) return e;

  // Geometry: one input primitive per sample; tessellation: one patch per sample.
  GLenum primitive = GL_POINTS;
  if (!w.tess_control.empty()) {
    primitive = GL_PATCHES;
    glPatchParameteri(GL_PATCH_VERTICES, static_cast<GLint>(w.iface.input_vertices));
  } else if (!w.geometry.empty()) {
    switch (w.iface.input_vertices) {
      case 2: primitive = GL_LINES; break;
      case 3: primitive = GL_TRIANGLES; break;
      case 4: primitive = GL_LINES_ADJACENCY; break;
      case 6: primitive = GL_TRIANGLES_ADJACENCY; break;
      default: break;
    }
  }
  const bool discard = job.stage != GraphicsStage::Fragment;
  if (discard) glEnable(GL_RASTERIZER_DISCARD);
  glDrawArrays(primitive, 0, static_cast<GLsizei>(count * std::max<uint32_t>(w.iface.input_vertices, 1)));
  if (discard) glDisable(GL_RASTERIZER_DISCARD);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  if (std::string e = gl_error("glDrawArrays"); !e.empty()) return e;

  glBindBuffer(GL_SHADER_STORAGE_BUFFER, gl.buffers[1]);
  const void* p = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(outputs.size()), GL_MAP_READ_BIT);
  if (!p) return gl_error("glMapBufferRange") + " (outputs)";
  unpack_outputs(w.iface, count, static_cast<const uint8_t*>(p), result);
  glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
  return gl_error("reading outputs back");
}

}  // namespace

std::vector<GraphicsResult> gles_run_graphics(const WrappedProgram& w, const std::vector<GraphicsJob>& jobs) {
  GlesContext& g = shared_context();
  GraphicsResult failed;
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
  std::vector<GraphicsResult> results;
  {
    glGetError();  // start clean
    GlGraphicsObjects gl;
    const std::string error = link(w, gl, g.renderer);
    for (size_t i = 0; i < jobs.size() && (i == 0 || results.back().ok); ++i) {
      GraphicsResult result;
      result.device = g.renderer;
      result.error = error.empty() ? draw(w, gl, jobs[i], jobs[0].count, &result) : error;
      result.ok = result.error.empty();
      if (!result.ok) result.outputs.clear();
      results.push_back(std::move(result));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindVertexArray(0);
  }
  eglMakeCurrent(g.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);  // let other threads use it
  return results;
}

}  // namespace doublet::runner::detail
