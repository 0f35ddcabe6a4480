// Internal interfaces between the runner's translation units.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "runner/runner.hpp"

namespace doublet::runner::detail {

// Where a live loose uniform sits in the global uniform block (std140, from glslang reflection).
struct UniformSlot {
  uint32_t offset = 0;
  bool is_float = false;   // only `float` can be set through ComputeJob::float_uniforms
  bool is_double = false;  // double/dvecN (else float/vecN when components > 0)
  char scalar = 'f';       // 'f', 'd', 'i', 'u', 'b' (bool: stored as a 32-bit 0 or 1)
  int components = 0;      // values: 1..4 for scalars/vectors, columns × rows for matrices, 0 otherwise
  int columns = 1;         // matrices: std140 puts each column at a 16-byte (dvec3/4: 32) stride
};

struct SpirvProgram {
  std::vector<uint32_t> words;           // the compute or vertex stage
  std::vector<uint32_t> fragment_words;  // graphics programs: the fragment stage
  std::vector<uint32_t> geometry_words;  // geometry jobs: the geometry stage (empty otherwise)
  std::vector<uint32_t> tess_control_words, tess_evaluation_words;  // tessellation jobs: both stages
  std::map<std::string, UniformSlot> uniforms;  // live members of the global uniform block
  uint32_t uniform_block_size = 0;              // 0 when the shader has no loose uniforms
  std::vector<int> ssbo_bindings;               // bindings of the shader's buffer blocks
  // Named uniform blocks and samplers with their Vulkan slots (glslang's automatic mapping).
  struct Resource {
    std::string name;
    uint32_t set = 0, binding = 0;
    uint32_t size = 0;                      // uniform blocks: bytes
    TextureKind kind = TextureKind::Tex2D;  // samplers
  };
  std::vector<Resource> uniform_blocks, samplers;
};

// One value of a uniform or buffer, stored as its scalar type ('f', 'd', 'i', 'u', 'b') at `at`.
void store_scalar(uint8_t* at, char scalar, double value);

// glslang compile + link + IO mapping + reflection + SPIRV-Tools validation.
// When `iface` is set it also receives the reflected interface. `strict_fp64`: ComputeJob::strict_fp64.
bool compile_glsl(const std::string& glsl, SpirvProgram* out, std::string* error, ShaderInterface* iface = nullptr,
                  bool strict_fp64 = false);

// The same for several stages linked as one program, each stage's SPIR-V in its SpirvProgram member.
enum class Stage { Compute, Vertex, Fragment, Geometry, TessControl, TessEvaluation };
bool compile_glsl_stages(const std::vector<std::pair<Stage, std::string>>& stages, SpirvProgram* out,
                         std::string* error, ShaderInterface* iface = nullptr, bool strict_fp64 = false);

// Decorates every fp64 arithmetic instruction (OpFAdd, OpFMul, OpDot, ...) NoContraction.
void decorate_fp64_no_contraction(std::vector<uint32_t>& words);

// True if the module declares OpCapability Float64.
bool spirv_uses_float64(const std::vector<uint32_t>& words);

std::vector<ComputeResult> vulkan_run(const SpirvProgram& program, const std::vector<ComputeJob>& jobs);
std::string vulkan_unavailable_reason();
std::vector<ComputeResult> gles_run(const std::vector<ComputeJob>& jobs);
std::string gles_unavailable_reason();

}  // namespace doublet::runner::detail
