// Turns one user vertex or fragment shader into a program whose inputs come from, and whose outputs
// go to, storage buffers (runner.hpp, "Vertex and fragment stages"):
//   - every global `in`/`out` declaration (one per line: qualifiers, type, names, `;`) becomes a plain
//     global, so nothing passes through attributes, varyings or attachments;
//   - `#define main doublet_user_main` after the #version line, and a new main() appended that loads
//     the inputs of sample i, calls the user's main and stores the outputs (and gl_Position) of i;
//   - the other stage is generated: for a vertex job an empty fragment shader (rasterizer discard),
//     for a fragment job a vertex shader that puts point i on pixel (i % 64, i / 64).
#pragma once

#include <string>

#include "runner/internal.hpp"
#include "runner/runner.hpp"

namespace doublet::runner::detail {

inline constexpr uint32_t kGridWidth = 64;      // pixels per row of a fragment job
inline constexpr uint32_t kGridHeight = 1024;   // rows: at most 65536 samples per draw
inline constexpr uint32_t kInputBinding = 0;    // storage buffer bindings of the wrapper
inline constexpr uint32_t kOutputBinding = 1;
// Under Vulkan the wrapper's buffers have a descriptor set of their own, so that the user's uniform
// blocks keep their bindings (0 and 1 included) in set 0; GL's storage buffers have bindings apart.
inline constexpr uint32_t kWrapperSet = 2;

struct WrappedProgram {
  std::string vertex, fragment;  // full texts of both stages
  // Geometry and tessellation jobs: the user's stage; the other stages are generated (a vertex
  // shader, a fragment shader that never runs, and the tessellation stage the user's one needs).
  std::string geometry, tess_control, tess_evaluation;
  GraphicsInterface iface;       // inputs/outputs with std430 offsets and strides (no uniforms yet)
  bool es = true;                // GLSL ES text (else desktop #version 450)
  // The user's rewritten stage before the storage-buffer main() is appended (its #version line,
  // `#define main doublet_user_main`, the globals): other transports (webgl2_wrapper.cpp) append
  // their own main().
  std::string user_text;
};

// Empty on success, else why the shader cannot be wrapped.
std::string wrap_graphics(GraphicsStage stage, const std::string& glsl, WrappedProgram* out);

}  // namespace doublet::runner::detail

namespace doublet::runner::detail {

// Input records for the job (count × input_stride bytes; absent inputs are 0). Empty on success.
std::string pack_inputs(const GraphicsInterface& iface, const GraphicsJob& job, std::vector<uint8_t>* bytes);
// What a fresh output buffer holds: all bits set, so a sample the stage never wrote reads as NaN.
std::vector<uint8_t> blank_outputs(const GraphicsInterface& iface, uint32_t count);
// Output records → per-variable values (see GraphicsResult::outputs).
void unpack_outputs(const GraphicsInterface& iface, uint32_t count, const uint8_t* bytes, GraphicsResult* out);

// The stages to compile: vertex, fragment, and a job's geometry or tessellation stages.
std::vector<std::pair<Stage, std::string>> stages_of(const WrappedProgram& w);

// The backends (gles_graphics.cpp, vulkan_graphics.cpp): every job drawn with one program.
std::vector<GraphicsResult> gles_run_graphics(const WrappedProgram& program, const std::vector<GraphicsJob>& jobs);
std::vector<GraphicsResult> vulkan_run_graphics(const WrappedProgram& wrapped, const SpirvProgram& program,
                                                const std::vector<GraphicsJob>& jobs);

}  // namespace doublet::runner::detail
