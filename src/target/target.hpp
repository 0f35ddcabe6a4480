// What each output target has: one table, asked by every pass, the printers and the driver
// (docs/architecture.md, "Targets"). A new target is one row here plus its printer's spellings.
// Facts that only glslang can answer (which built-in names, opaque types and variables a
// profile has) are the checks of target/glslang_checks.hpp.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace doublet::target {

struct Facts {
  Target id;
  const char* name;            // "es300", as the CLI spells it
  bool es;                     // GLSL ES (webgl2 too)
  int version;                 // the GLSL version number of the text; 0 for WGSL
  const char* version_line;    // "#version 300 es"; empty for WGSL
  // Language features the lowering and the guard depend on.
  bool precise;                // the `precise` qualifier (ES 3.20, desktop 4.00+)
  bool precise_via_gpu_shader5;  // `precise` through GL_EXT_gpu_shader5 when allowed (ES 3.10)
  bool compute;                // compute shaders
  bool geometry;               // geometry shaders
  bool tessellation;           // tessellation shaders
  bool uint_and_bit_ops;       // uint, bit operators, switch, non-float varyings (not ES 1.00)
  bool bit_casts;              // floatBitsToUint and friends
  bool integer_functions;      // umulExtended, findMSB (ES 3.10+, desktop 4.00+)
  bool frexp_ldexp;            // frexp/ldexp on float
  bool fma;                    // the fma() built-in
  bool storage_blocks;         // `buffer` blocks (ES 3.10+, desktop 4.30+)
  bool io_blocks;              // in/out interface blocks (ES 3.20, desktop 3.30+)
  bool overloads_builtin_names;  // a user function may overload a built-in name (desktop only)
  bool webgl_rules;            // WebGL 2.0's rules on top of ES 3.00 (docs/web.md)
  bool wgsl;                   // WebGPU Shading Language, printed from an ES 3.10 intermediate
  bool carries_extensions;     // `#extension` lines may appear in the shader (not WebGL)
  // `uniform T x = value;` (desktop GLSL 1.20+); GLSL ES and WGSL have no uniform initializers.
  bool uniform_initializers() const { return !es && !wgsl; }
  std::size_t max_identifier_length;  // 0: no limit doublet knows of
  std::vector<std::string> reserved_prefixes;  // identifiers the target forbids
};

// "vertex", "fragment", "compute", "geometry", "tessellation control", "tessellation evaluation".
const char* stage_noun(Stage stage);
// The extension ES 3.10 needs for geometry (GL_EXT_geometry_shader) and tessellation
// (GL_EXT_tessellation_shader) shaders; null where the stage needs none or the target lacks it.
const char* stage_extension(const Facts& t, Stage stage);
// Whether `t` has the stage's shaders at all (compute, geometry, tessellation are not everywhere),
// natively or through stage_extension.
bool has_stage(const Facts& t, Stage stage);

// The row of `t`.
const Facts& facts(Target t);
// Every row, es100 first; `with_wgsl` false leaves out the WGSL row (the GLSL targets).
std::vector<Target> all_targets(bool with_wgsl = true);

// The #version line (no newline) of `target`'s profile: "#version 100", "#version 300 es" (webgl2
// too), "#version 450 core".
std::string version_directive(Target target);

// The GLSL profile WGSL is printed from (its intermediate text).
inline constexpr Target kWgslIntermediate = Target::Es310;

}  // namespace doublet::target
