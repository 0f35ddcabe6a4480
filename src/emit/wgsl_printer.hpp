// WGSL printer: prints a module of float-only GLSL IR (doublet's lowered output, runtime
// included, re-imported by the front end) as a WebGPU Shading Language module.
// Facts used: W3C WGSL (Candidate Recommendation), sections on types, memory layout (uniform and
// storage address spaces), statements and built-in functions; no code was taken from Tint or naga.
#pragma once

#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"

namespace doublet::emit {

struct WgslPrintResult {
  std::string text;
  std::vector<Diagnostic> diagnostics;
  // The uniform buffer that gathers the loose uniforms (the guard included), when any.
  InterfaceVariable uniform_buffer;  // name empty when there is none
  // Every uniform and storage block's @binding (all in @group(0)).
  struct BlockBinding {
    std::string block, instance;  // instance: "" when anonymous
    int binding = 0;
  };
  std::vector<BlockBinding> block_bindings;
};

// `position_note` is appended to every error: the IR positions are those of the intermediate GLSL.
WgslPrintResult print_wgsl(const ir::Module& module, const std::string& file_name, const std::string& position_note);

}  // namespace doublet::emit
