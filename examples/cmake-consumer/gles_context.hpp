// A GLES 3.1 context without a window: EGL on Mesa's surfaceless platform.
#pragma once

#include <string>

// Makes a context current on this thread. Returns an empty string, or what failed.
std::string make_surfaceless_gles31_context();

// Compiles and links one compute shader. Returns the program, or 0 with `log` set.
unsigned compile_compute_program(const char* source, std::string& log);
