// The WebGL2 backend of the graphics runner: a user's vertex or fragment stage (GLSL ES 1.00 or
// 3.00 text) runs in headless Chromium's WebGL2 (tools/browser/webgl2-verify.mjs). WebGL2 has no
// storage buffers, so the values travel differently from graphics_wrapper.hpp, still bit-exactly:
//   inputs:  every sample's input words (float bits, int bits) in an RGBA32UI texture, read with
//            texelFetch and uintBitsToFloat by a generated main() before the user's main runs;
//   outputs: every output component as floatBitsToUint words packed into uvec4 "slots" —
//            vertex: flat uvec4 varyings captured by transform feedback (rasterizer discard);
//            fragment: RGBA32UI colour attachments of a 64-pixel-wide framebuffer covered by one
//            triangle, one pixel per sample (i = y * 64 + x, as the storage-buffer path).
// When there are more slots than one program can write (4 draw buffers, 15 captured uvec4s: the
// ES 3.00 minimums), the stage runs in several passes, each writing some of the slots.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runner/runner.hpp"

namespace doublet::runner::detail {

inline constexpr uint32_t kWebGl2GridWidth = 64;       // samples per row (texture and framebuffer)
inline constexpr uint32_t kWebGl2FragmentSlots = 4;    // MAX_DRAW_BUFFERS >= 4 in ES 3.00
inline constexpr uint32_t kWebGl2VertexSlots = 15;     // 64 interleaved components >= 15 uvec4 + gl_Position

struct WebGl2Pass {
  std::string vertex, fragment;          // complete #version 300 es texts
  std::vector<std::string> varyings;     // vertex stage: the captured uvec4 outputs, in order
  uint32_t first_slot = 0, slots = 0;    // the uvec4 output slots this pass writes
};

struct WebGl2Program {
  GraphicsStage stage = GraphicsStage::Vertex;
  GraphicsInterface iface;                    // inputs/outputs (their `offset` is unused here)
  std::vector<uint32_t> input_word, output_word;  // first 32-bit word of each variable in a sample's record
  uint32_t input_words = 0, output_words = 0;     // words per sample, multiples of 4 (one texel / slot)
  std::vector<WebGl2Pass> passes;
};

// Empty on success, else why the shader cannot run in WebGL2 (its #version must be 100 or 300 es).
std::string wrap_webgl2(GraphicsStage stage, const std::string& glsl, WebGl2Program* out);

// The job's input words: count × input_words (absent inputs 0). Empty on success.
std::string webgl2_pack_inputs(const WebGl2Program& program, const GraphicsJob& job, std::vector<uint32_t>* words);
// count × output_words words → GraphicsResult::outputs (floats from their bits).
void webgl2_unpack_outputs(const WebGl2Program& program, uint32_t count, const std::vector<uint32_t>& words,
                           GraphicsResult* out);

// Every batch its own program, all of them in one page run (one browser start).
std::vector<std::vector<GraphicsResult>> webgl2_run_graphics(const std::vector<std::vector<GraphicsJob>>& batches);

}  // namespace doublet::runner::detail
