// Front end: runs glslang over the user's source and keeps the typed AST alive.
//
// GLSL ES reserves `double`, so every input (ES 1.00–3.20 or desktop) is parsed
// as desktop GLSL 4.50 compatibility: the compatibility profile still knows
// `attribute`, `varying`, `gl_FragColor` and `texture2D`. Line numbers are the
// user's; glslang prints no column, so diagnostics recover it from the source.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"

struct TBuiltInResource;

namespace glslang {
class TShader;
class TIntermediate;
}  // namespace glslang

namespace doublet::frontend {

struct SourceInfo {
  int version = 100;  // the user's #version (100 when absent)
  bool es = true;     // user wrote an ES version (or none)
};

struct ParsedShader {
  std::unique_ptr<glslang::TShader> shader;  // owns the AST's memory pool
  glslang::TIntermediate* intermediate = nullptr;
  SourceInfo info;
  std::vector<std::string> included_files;
  std::string source;  // the main file's text (global declarations are located in it)
  bool transcendentals = false;  // parsed with the transcendental prototypes (transcendentals.hpp)
  // --target wgsl: each Vulkan `layout(set = N)` with N > 0 of the main file, parsed as set = 0
  // (OpenGL GLSL has set 0 only), as (line, column of `set`, N); import_module gives N to the
  // declaration it qualifies, the WGSL printer makes it the @group.
  struct DescriptorSet {
    int line = 0, column = 0, set = 0;
  };
  std::vector<DescriptorSet> descriptor_sets;
  ParsedShader();
  ParsedShader(ParsedShader&&) noexcept;
  ~ParsedShader();
  void release_ast();  // frees glslang's AST (once the IR is imported)
};

// Reads the #version line the way the GLSL specs define it.
SourceInfo scan_version(std::string_view source);

// Parses `source`; appends diagnostics (with file:line:col) on failure.
bool parse(std::string_view source, const Options& options, ParsedShader& out,
           std::vector<Diagnostic>& diagnostics);

// Turns glslang's info log into diagnostics. `files` maps names used in the log
// to their text, for recovering columns.
void append_glslang_log(std::string_view log, const std::string& main_name,
                        const std::vector<std::pair<std::string, std::string>>& files,
                        std::vector<Diagnostic>& out);

// Line numbers of glslang's "ERROR: 0:<line>:" entries (errors in its first, unnamed string).
std::vector<int> error_lines_of_main_string(std::string_view log);

void ensure_glslang_initialized();

// The resource limits shaders are parsed and re-validated with: glslang's default table, with the
// atomic-counter limits raised from its 1 binding to 8 (the GL 4.6 minimum of
// MAX_COMBINED_ATOMIC_COUNTER_BUFFERS is 1, but desktop drivers and Mesa offer 8 or more), so
// real shaders with several counter bindings parse.
const TBuiltInResource& resource_limits();

}  // namespace doublet::frontend
