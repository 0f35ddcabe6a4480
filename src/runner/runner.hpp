// doublet_runner: executes GLSL compute shaders on real Mesa drivers, so that tests can see what
// the drivers' optimizers actually do to float-float code (see docs/numerics.md#what-optimizers-do).
//   Backend::Vulkan — glslang → SPIR-V (validated by SPIRV-Tools) → lavapipe.
//   Backend::Gles   — the text as-is → Mesa's GLES 3.2 compiler (llvmpipe, EGL surfaceless).
//   Backend::WebGl2 — vertex/fragment only: GLSL ES 1.00/3.00 text in headless Chromium's WebGL2
//                     (tools/browser, webgl2.hpp); one browser start per run_graphics_batches call.
// The driver objects (VkInstance/VkDevice, EGL context) are created once per process, lazily;
// run_compute is thread-safe (calls on one backend are serialised).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace doublet::runner {

// WebGpu: WGSL compute in headless Chromium's WebGPU (runner/webgpu.hpp, run_webgpu_compute); the
// GLSL entry points below answer it with an error.
enum class Backend { Vulkan, Gles, WebGl2, WebGpu };

const char* backend_name(Backend);

struct ComputeJob {
  // Full GLSL source with its #version line.
  // Vulkan: compiled by glslang with relaxed Vulkan rules: bindings/locations auto-mapped, loose
  //   uniforms gathered into a global uniform block (set kUniformSet, binding kUniformBinding).
  //   "#version 450" text may use double/dvec (needs shaderFloat64; reported if missing).
  // Gles: handed as-is to glShaderSource; ES 3.10/3.20 compute.
  std::string glsl;
  // buffers[i] is bound as SSBO binding i (set 0 on Vulkan); contents uploaded before the dispatch.
  std::vector<std::vector<uint8_t>> buffers;
  // Loose `uniform float` values by name. Unlisted uniforms stay 0. A name the compiler removed
  // (inactive) is ignored, as in GL; a name bound to a non-float uniform is an error.
  std::map<std::string, float> float_uniforms;
  // Loose uniforms of float/vecN or double/dvecN type by name, one value per component, converted to
  // the declared type (double types exist only on Vulkan). Set after float_uniforms; same rules.
  std::map<std::string, std::vector<double>> uniforms;
  uint32_t groups_x = 1, groups_y = 1, groups_z = 1;
  // Vulkan: every fp64 arithmetic instruction decorated NoContraction (as if `precise`), so Mesa
  // neither reassociates nor fuses it: fp64 evaluated as written, IEEE operation by operation (the
  // reference of `verify --mode exact`). Run with the first job's setting.
  bool strict_fp64 = false;
};

struct ComputeResult {
  bool ok = false;
  std::string error;                          // compile log / "invalid SPIR-V: ..." / driver error
  std::vector<std::vector<uint8_t>> buffers;  // every buffer, read back after the dispatch
  std::string device;                         // VkPhysicalDeviceProperties::deviceName / GL_RENDERER
};

ComputeResult run_compute(Backend, const ComputeJob&);

// Runs every job with one compiled program (jobs[0].glsl; the others' glsl is ignored): many input
// sets for one shader without paying for a compile and pipeline each time. Results in job order; on
// the first failure it stops and the last result carries the error.
std::vector<ComputeResult> run_compute_batch(Backend, const std::vector<ComputeJob>& jobs);

// Runs an already-compiled SPIR-V compute module on Vulkan (validated first, like compiled text).
// Loose-uniform offsets are unknown here, so job.float_uniforms must be empty; job.glsl is ignored.
ComputeResult run_spirv_compute(const std::vector<uint32_t>& spirv, const ComputeJob&);

// glslang front end used by the Vulkan backend, exposed for tools/tests. Returns false and sets
// *error (compile/link log, or "invalid SPIR-V: ...") on failure.
bool compile_compute_to_spirv(const std::string& glsl, std::vector<uint32_t>* spirv, std::string* error);

// The numeric interface of a compute shader as glslang reflects it (active variables only; names as
// the shader spells them, without a trailing "[0]"). `doublet verify` feeds and reads shaders with it.
struct ShaderInterface {
  struct Uniform {
    std::string name;
    bool is_double = false;
    // Values: 1..4 for float/double scalars and vectors, columns × rows for matrices (given column
    // by column), 0 for other types.
    int components = 0;
    int columns = 1;  // matrices: columns (each holds components / columns rows)
    char scalar = 'f';  // 'f' float, 'd' double, 'i' int, 'u' uint, 'b' bool (is_double == (scalar == 'd'))
  };
  struct Block {
    std::string name;
    int binding = -1;
    bool readonly = false, writeonly = false;
    uint32_t fixed_size = 0;  // bytes before a trailing runtime-sized array
  };
  struct Member {
    std::string name;
    int block = -1;           // index into blocks
    uint32_t offset = 0;      // std430 byte offset in the block
    bool is_double = false;
    int components = 0;       // 1..4 for float/double scalars and vectors, 0 for other types
    uint32_t array_size = 1;  // elements; 0 for a runtime-sized array
    uint32_t array_stride = 0;
  };
  // A named uniform block (`uniform Params { dmat4 mvp; ... };`) and its active members, whose
  // `name`s are the member names without the block's prefix; `offset` is the std140 byte offset.
  struct UniformBlockMember : Uniform {
    uint32_t offset = 0;
  };
  struct UniformBlock {
    std::string name;   // the block name, as GL's glGetUniformBlockIndex takes it
    uint32_t size = 0;  // bytes
    std::vector<UniformBlockMember> members;
  };
  uint32_t local_size[3] = {1, 1, 1};
  std::vector<Uniform> uniforms;  // loose uniforms (and scalar int/uint/bool ones: components, is_integer)
  std::vector<Block> blocks;
  std::vector<Member> members;
  std::vector<UniformBlock> uniform_blocks;
  std::vector<std::string> samplers;  // sampler2D/3D/Cube uniforms (graphics jobs bind test_texture to them)
};
// Compiles like the Vulkan backend (so "#version 450" with doubles works) and reflects.
bool reflect_compute(const std::string& glsl, ShaderInterface* out, std::string* error);

// ---- Vertex and fragment stages --------------------------------------------------------------
// A graphics job runs one user stage over `count` samples (vertices, or one pixel each) and reads
// back every value it produces bit-exactly. The runner wraps the shader (graphics_wrapper.hpp):
// each global `in`/`out` declaration becomes a plain global, inputs are loaded from a storage
// buffer before the user's main() runs and outputs (and gl_Position) stored to another after it,
// indexed by gl_VertexIndex/gl_VertexID or by the pixel. So the arithmetic runs in the real stage
// (its denormal handling and optimizer), while nothing passes through attribute fetch,
// interpolation or float attachments. (lavapipe has no 64-bit vertex formats, which is why native
// double inputs cannot be vertex attributes.)
//   Vertex:   `count` points with rasterizer discard.
//   Fragment: `count` one-pixel points, one per pixel of a 64-wide grid, in a framebuffer without
//             attachments; a generated vertex shader places them.
// The text may be "#version 450" (doubles; Vulkan only), "#version 310 es"/"320 es", or
// "#version 300 es" (run as 310 es: the storage buffers need it; the language is a superset).
//   Geometry: `count` primitives of the shader's input type (points, lines, triangles, with or
//             without adjacency), one per sample, with rasterizer discard; each per-vertex input
//             array element is an input of its own ("world[1]", "gl_in[2].gl_Position"), and each
//             EmitVertex() stores the outputs as one of the sample's max_vertices output records
//             (GraphicsInterface::records_per_sample; a record never emitted reads as NaN). Vulkan only.
//   TessControl: one patch of layout(vertices = N) control points per sample, the per-vertex input
//             elements 0..N-1 fed; invocation k stores record k of its sample (its own element of a
//             per-vertex output, the tessellation levels it wrote, 0 where it wrote none).
//   TessEvaluation: one patch per sample tessellated at level 1; the per-vertex input elements of
//             the domain's corners (3, 4 or 2) fed, and gl_TessCoord an input; one record.
enum class GraphicsStage { Vertex, Fragment, Geometry, TessControl, TessEvaluation };

// One wrapped `in` or `out` variable (or gl_Position) of scalar/vector numeric type.
struct StageVariable {
  std::string name;
  char scalar = 'f';   // 'f' float, 'd' double, 'i' int, 'u' uint
  int components = 1;  // 1..4
  uint32_t offset = 0; // std430 offset in the per-sample record
};

struct GraphicsInterface {
  std::vector<StageVariable> inputs, outputs;  // declaration order; outputs end with gl_Position
  uint32_t input_stride = 0, output_stride = 0;  // bytes per sample record (std430 struct)
  uint32_t records_per_sample = 1;  // output records per sample: a geometry shader's max_vertices, a control shader's N
  uint32_t input_vertices = 1;      // vertices drawn per sample: a geometry primitive's, a patch's
  std::vector<ShaderInterface::Uniform> uniforms;  // active loose uniforms (glslang reflection)
  std::vector<ShaderInterface::UniformBlock> uniform_blocks;  // named uniform blocks (GraphicsJob::uniform_blocks)
  std::vector<std::string> samplers;  // sampler uniforms, each bound to test_texture(its kind)
};

// Parses the stage's in/out declarations and reflects its uniforms (compiling the wrapped shader as
// the Vulkan backend would). False with *error for unsupported interfaces (arrays, blocks, structs).
bool reflect_graphics(GraphicsStage, const std::string& glsl, GraphicsInterface* out, std::string* error);

struct GraphicsJob {
  GraphicsStage stage = GraphicsStage::Vertex;
  std::string glsl;    // the user's stage, as in ComputeJob::glsl
  uint32_t count = 1;  // samples: vertices or pixels
  // Per input variable: count × components values (converted to its type). Unlisted inputs are 0.
  std::map<std::string, std::vector<double>> inputs;
  std::map<std::string, float> float_uniforms;               // as ComputeJob
  std::map<std::string, std::vector<double>> uniforms;       // as ComputeJob (matrices, int/uint/bool too)
  // Named uniform blocks by block name: their bytes (std140, as the shader declares them), bound
  // as uniform buffers. A block the job does not list reads as zeros.
  std::map<std::string, std::vector<uint8_t>> uniform_blocks;
  bool strict_fp64 = false;  // as ComputeJob::strict_fp64
};

// std140 bytes between the columns of a matrix with `rows` rows: a vec4's 16, a dvec3/dvec4's 32.
inline uint32_t std140_column_stride(bool is_double, int rows) { return is_double && rows > 2 ? 32 : 16; }

// Every sampler2D, sampler3D and samplerCube of a graphics job samples this texture (both
// backends, both shaders): kTextureSize texels per side, RGBA32F, one level, NEAREST filtering,
// REPEAT wrapping (cube maps clamp). Texels are exact floats from a fixed pattern, so a texel
// fetch is bit-identical on every driver.
enum class TextureKind { Tex2D, Tex3D, Cube };
inline constexpr uint32_t kTextureSize = 16;
// RGBA values, x fastest, then y, then z (3D) or face (cube: +X -X +Y -Y +Z -Z).
std::vector<float> test_texture(TextureKind kind);

struct GraphicsResult {
  bool ok = false;
  std::string error;
  std::string device;
  // Per output variable (and "gl_Position"): count × records_per_sample × components values, each
  // exactly the bits the shader stored (a float widened to double). Records never written read NaN.
  std::map<std::string, std::vector<double>> outputs;
};

GraphicsResult run_graphics(Backend, const GraphicsJob&);
// Many draws with one compiled pipeline (jobs[0].glsl, .stage and .count are used for all).
std::vector<GraphicsResult> run_graphics_batch(Backend, const std::vector<GraphicsJob>& jobs);
// Several batches, each with its own program, results per batch. On WebGl2 all of them run in one
// page (one browser start); elsewhere this is run_graphics_batch per batch.
std::vector<std::vector<GraphicsResult>> run_graphics_batches(Backend, const std::vector<std::vector<GraphicsJob>>& batches);

// SPIRV-Tools validation for the Vulkan 1.1 environment. Empty when valid, else the messages.
std::string validate_spirv(const std::vector<uint32_t>& spirv);

// Empty when the backend works on this machine, else why not. Tests report it; they never skip.
std::string backend_unavailable_reason(Backend);

// Descriptor slot of the glslang global uniform block on Vulkan (SSBOs live in set 0).
inline constexpr uint32_t kUniformSet = 1;
inline constexpr uint32_t kUniformBinding = 0;

}  // namespace doublet::runner
