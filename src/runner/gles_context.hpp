// The process's EGL surfaceless GLES 3.2 context (llvmpipe), shared by the GLES backends.
#pragma once

#include <EGL/egl.h>
#include <GLES3/gl32.h>

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "runner/internal.hpp"

namespace doublet::runner::detail {

struct GlesContext {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  std::string renderer;
  std::string error;  // non-empty: unusable, and why
  std::mutex mu;      // one EGL context, current on one thread at a time
};

// Created on first use, never destroyed (like the Vulkan device). Callers lock `mu` and make the
// context current for the duration of their work, then release it for other threads.
GlesContext& shared_context();

std::string egl_error(const char* call);
std::string gl_error(const char* where);  // empty when glGetError() reports nothing
std::string info_log(GLuint object, bool is_program);

// Loose uniforms of a linked, current program, with ComputeJob's rules (absent names are ignored).
std::string set_uniforms(GLuint program, const std::map<std::string, float>& float_uniforms,
                         const std::map<std::string, std::vector<double>>& uniforms);

}  // namespace doublet::runner::detail
