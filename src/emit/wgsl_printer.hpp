// WGSL printer: prints a module of float-only GLSL IR (doublet's lowered output, runtime
// included, re-imported by the front end) as a WebGPU Shading Language module.
// Facts used: W3C WGSL (Candidate Recommendation), sections on types, memory layout (uniform and
// storage address spaces), statements and built-in functions; no code was taken from Tint or naga.
#pragma once

#include <map>
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
  // Every uniform and storage block's @group and @binding.
  struct BlockBinding {
    std::string block, instance;  // instance: "" when anonymous
    int group = 0, binding = 0;
  };
  std::vector<BlockBinding> block_bindings;
};

// `position_note` is appended to every error: the IR positions are those of the intermediate GLSL.
// `block_groups`: the @group of a block by its type name (Vulkan GLSL's `layout(set = N)`, which
// the intermediate GLSL cannot carry); every other block is in group 0.
WgslPrintResult print_wgsl(const ir::Module& module, const std::string& file_name, const std::string& position_note,
                           const std::map<std::string, int>& block_groups = {});

}  // namespace doublet::emit
