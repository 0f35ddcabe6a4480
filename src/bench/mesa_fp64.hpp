// Mesa's soft-fp64 (src/compiler/glsl/float64.glsl, Berkeley SoftFloat 3e ported to GLSL; fetched
// at run time by scripts/fetch-mesa-fp64, never committed) made into plain GLSL ES 3.10 so it runs
// as a compute shader on lavapipe and on Mesa GLES next to doublet's mode exact.
//
// Mesa compiles the file as desktop GLSL 4.00 with GL_ARB_gpu_shader_int64, where a double travels
// as a uint64_t that the functions split with unpackUint2x32. ES has no 64-bit integers, so the
// adaptation only changes how that type is spelled, never an operation of the arithmetic:
//   - uint64_t is uvec2 and packUint2x32/unpackUint2x32 are the identity (the same (lo, hi) words);
//   - 64-bit literals (0xFFFFFFFFFFFFFFFFUL, 0ul) become uvec2(lo, hi) constants;
//   - mix(x, y, bool) on such values selects both words (GLSL's mix on uvec2 wants a bvec2);
//   - the three int literals the file compares with or assigns to a uint get their u (desktop
//     GLSL converts them implicitly, ES does not);
//   - #version/#extension/#pragma lines are dropped, and only the functions the benchmark calls and
//     what they call are kept (the rest use int64 arithmetic that ES cannot express).
#pragma once

#include <string>
#include <vector>

namespace doublet::bench {

// The file's entry points the peer benchmark uses.
const std::vector<std::string>& mesa_fp64_roots();

// `file_text` (float64.glsl as Mesa ships it) adapted as above: GLSL ES 3.10 text without a
// #version line, defining every function of mesa_fp64_roots() and what they call, plus mesa_div:
// division as Mesa's NIR lowers a double `a / b` on drivers without fp64 (float64.glsl has none).
// Returns false and sets *error when the file is not what this expects (a root missing, an
// unbalanced brace, a preprocessor conditional around functions).
bool adapt_mesa_fp64(const std::string& file_text, std::string* library, std::string* error);

// The GLSL expression of one operation on uvec2 operands `a`, `b` in the adapted library, or ""
// for an op Mesa's path does not have. sub is a + (-b), as NIR lowers fsub.
std::string mesa_op_expression(const std::string& op, const std::string& a, const std::string& b);

}  // namespace doublet::bench
