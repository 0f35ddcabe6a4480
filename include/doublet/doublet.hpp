// doublet — lowers GLSL doubles (double, dvec2-4) to float-float GLSL.
//
// The library entry point. No exception crosses this API: every failure is a
// Diagnostic in Result::diagnostics and Result::ok == false.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace doublet {

// Geometry and tessellation lower for the targets that have the stage (desktop 3.30/4.00+, ES 3.20,
// ES 3.10 with GL_EXT_geometry_shader/GL_EXT_tessellation_shader).
enum class Stage { Vertex, Fragment, Compute, Geometry, TessControl, TessEvaluation };

// Output dialects. es* are GLSL ES, glsl* desktop GLSL (core profile).
// webgl2: ES 3.00 under WebGL 2.0's rules. wgsl: WebGPU Shading Language (no f64: every double is
// float-float; docs/web.md).
enum class Target { Es100, Es300, Es310, Es320, Glsl330, Glsl450, Webgl2, Wgsl };

// How the float-float error terms are protected from the driver's optimizer.
//  Precise: every rule temporary is declared `precise` (ES 3.20, desktop 4.00+,
//           or ES 3.10 with GL_EXT_gpu_shader5 when allowed).
//  Uniform: every rule step adds an opaque `uniform float` that GL zero-fills at
//           link time, so the compiler cannot prove algebraic identities.
//  Auto:    Precise where the target has it, Uniform otherwise.
enum class GuardKind { Auto, Precise, Uniform, None /* unprotected: tests only */ };

// Precision modes (docs/modes.md), cheapest first by cost, weakest first by accuracy:
//  Fp32:     every double demoted to float (what users have without doublet);
//  Rte:      doubles stored and passed as hi/lo, arithmetic in float except the exact
//            float-float subtraction of two split values, whose result is float
//            (relative-to-eye/center in the Cesium sense);
//  Df64Fast: float-float with the cheaper algorithms and their weaker bounds;
//  Df64:     float-float with the accurate algorithms (the default);
//  Df64Int:  df64 with the error terms of TwoSum/TwoProd computed by integer operations on
//            the decoded floats (rules/int.glsl): no optimizer guard needed; ES 3.00+, whole
//            shader only;
//  Native:   doubles kept as they are (desktop targets with fp64; the reference).
//  Exact:    IEEE binary64 bit patterns in two uint words (low, high), every operation in integer
//            arithmetic, bit-identical to native fp64 (rules/exact.glsl; ES 3.00+, desktop; whole
//            shader only).
//  RteExact: doubles stored as in Exact; arithmetic as in Rte (float), except the difference of two
//            doubles: the exact real difference rounded once to float (rules/rte_exact.glsl; ES
//            3.00+, desktop; whole shader only).
enum class Mode { Fp32, Rte, Df64Fast, Df64, Native, Df64Int, Exact, RteExact };

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  std::string file;
  int line = 0;    // 1-based; 0 when not tied to a place
  int column = 0;  // 1-based; 0 when unknown
  Severity severity = Severity::Error;
  std::string message;
};

// `file:line:col: error: message`, the form compilers print.
std::string format_diagnostic(const Diagnostic& d);

// Resolves `#include "name"` for the front end. Return std::nullopt when the
// file cannot be found; `resolved_path` names the file for diagnostics/depfiles.
struct IncludeResult {
  std::string resolved_path;
  std::string contents;
};
// lower() parses on an internal thread with a large stack (deeply nested
// expressions would overflow the caller's), so include() is called from that
// thread while the calling thread waits: it must not rely on thread-local state.
class Includer {
 public:
  virtual ~Includer() = default;
  virtual std::optional<IncludeResult> include(std::string_view requested,
                                               std::string_view includer_path) = 0;
};

struct Options {
  std::optional<Stage> stage;          // required; the CLI derives it from the extension
  Target target = Target::Es300;
  std::string file_name = "<stdin>";   // used in diagnostics
  std::vector<std::pair<std::string, std::string>> defines;  // -D NAME[=VALUE]
  std::vector<std::string> include_dirs;                     // -I DIR (used when includer is null)
  Includer* includer = nullptr;        // overrides include_dirs when set
  std::string hi_suffix = "_hi";
  std::string lo_suffix = "_lo";
  GuardKind guard = GuardKind::Auto;
  bool allow_gpu_shader5 = false;      // es310: use `precise` via GL_EXT_gpu_shader5
  std::string guard_uniform_name = "df_guard";
  // Double constants too small for float-float (|x| < 1.2e-38, e.g. 1e-300lf) are a
  // warning by default and an error when this is set. Too large ones are always errors.
  bool constant_range_errors = false;
  // Lints (docs/robustness.md, "Lints"): warnings that end in [-WNAME], NAME one of
  // lint_names(). A name here silences that lint, "all" every lint (-Wno-NAME); an unknown
  // name is an error. lint_errors makes the lints that run errors (-Werror).
  std::vector<std::string> disabled_lints;
  bool lint_errors = false;
  // The precision mode of everything not named in mode_for (--mode).
  Mode mode = Mode::Df64;
  // Per-declaration and per-function modes (--mode-for NAME=MODE, or a plan file), the same as
  // `#pragma doublet mode(MODE)` in the source before the declaration. NAME is a global
  // variable, a function (every overload), or FUNCTION.LOCAL for a local variable or parameter.
  // A later entry for the same NAME wins; a NAME the shader does not declare is an error.
  std::vector<std::pair<std::string, Mode>> mode_for;
  // Whole-shader float-float optimizations (src/lower/optimize_df.hpp, docs/performance.md):
  // cheaper rules of equal or better accuracy where the operands allow (x*x, a power of two, a
  // float widened to double). Off: every operation is its general rule.
  bool optimize = true;
  // Mode exact: the calls of one arithmetic operation in a run of statements share one call site
  // (src/lower/share_exact_calls.cpp, docs/performance.md): drivers compile each operation once
  // per run instead of once per use (precise_orbit.comp 2.9-3.3x faster to compile on lavapipe),
  // at some run time (+15-45% for a chain of one operation on Mesa's CPU drivers). Off: every call
  // inlined where it is.
  bool share_exact_calls = true;
  // The pipeline (docs/architecture.md): stop after the pass of this name (`doublet lower
  // --stop-after PASS`; pass_names() lists them) and return the IR printed as it is then, not
  // re-validated — for tests and for debugging a lowering. Empty: run every pass.
  std::string stop_after;
  // Tests only: passes to leave out (to show that a pass test fails without its pass).
  std::vector<std::string> skip_passes;
  // Check the IR's consistency after every pass (an internal error names the pass that broke
  // it). On in the test suites; costs a walk of the IR per pass.
  bool check_ir = false;
};

// One member of a uniform or storage block after lowering (members of nested structs are listed
// with dotted names, "s.v"): where its words live in the emitted std140/std430 layout. A double
// member becomes a df_* struct with hi and lo side by side.
struct BlockMember {
  std::string name;          // "x", "s.v"
  std::string type;          // original GLSL type, e.g. "dvec3", "double[4]"
  std::string lowered_type;  // e.g. "df_dvec3", "df_double[4]"; the original type when unchanged
  int offset = 0;            // byte offset in the lowered block
  int size = 0;              // bytes, the whole array for arrays (0 for an unsized array)
  int array_stride = 0;      // bytes between array elements; 0 when not an array
  int hi_offset = -1;        // doubles: byte offset of hi (float/vecN/matCxR) inside one element
  int lo_offset = -1;        // doubles: byte offset of lo inside one element
  int matrix_stride = 0;     // matrices: bytes between columns (of hi and of lo)
  // Mode exact: "binary64-words" when the member holds the doubles' IEEE binary64 patterns at
  // the same offsets, size and strides as the original block (hi_offset/lo_offset are then -1).
  std::string encoding;
};

// One original interface variable and what it became in the output.
struct InterfaceVariable {
  std::string name;          // as the user wrote it
  std::string storage;       // "in", "out", "uniform", "attribute", "varying", "buffer"
  std::string type;          // original GLSL type, e.g. "dvec3"
  bool split = false;        // true when the variable held doubles and was split
  std::string lowered_type;  // type of each emitted variable, e.g. "vec3"
  std::vector<std::string> lowered_names;  // {"X_hi","X_lo"} when split, else {"X"}
  std::vector<int> locations;              // explicit locations of lowered_names, if any
  // Mode exact: "binary64-words" — each double is the two 32-bit words of its IEEE binary64
  // pattern, low word first (packDouble2x32's order): the lowered variables' words, in the order of
  // lowered_names, are the little-endian bytes of the original value. lowered_types then gives
  // each lowered variable's type (dvec3 p -> p_xy: uvec4, p_z: uvec2). Empty otherwise.
  std::string encoding;
  std::vector<std::string> lowered_types;
  // A member of an in/out block flattened into a plain variable (targets without I/O blocks:
  // es100, es300, es310): the block's name; `name` is then BLOCK_MEMBER.
  std::string block;
  // Blocks only: the packing emitted ("std140"/"std430") and every member's new place.
  std::string layout;
  std::vector<BlockMember> members;
  // A uniform declared with an initializer (`uniform double zoom = 1.0lf;`): its value, every
  // component in GLSL's order (column-major for matrices, elements in order for arrays; ints and
  // bools as numbers). Targets without uniform initializers (GLSL ES, WGSL) and mode exact declare
  // the uniform without one: the application sets this value (README, `--manifest`).
  std::vector<double> default_value;
  // WGSL buffers (target wgsl): @group and @binding; -1 elsewhere.
  int group = -1;
  int binding = -1;
};

struct GuardInfo {
  std::string kind;          // "precise", "uniform" or "none"
  std::string uniform_name;  // for kind == "uniform"
  std::string uniform_type;  // "float[2]" (read at a non-constant index), "float" on es100 and wgsl
  double required_value = 0; // the value the host must leave it (every element) at: GL's default 0
};

struct Manifest {
  std::string stage;   // "vert", "frag", "comp"
  std::string target;  // "es300", ...
  std::string mode;    // Options::mode, "df64", ... (in the JSON only when not df64)
  std::vector<InterfaceVariable> variables;
  GuardInfo guard;
  std::string to_json() const;  // pretty-printed JSON
};

struct Result {
  bool ok = false;
  std::string output;                    // the lowered shader (empty unless ok)
  std::vector<Diagnostic> diagnostics;   // errors and warnings, in source order
  Manifest manifest;
  std::vector<std::string> included_files;
  // Wall-clock seconds of each phase that finished, in order ("parse", "import", "lints", "modes",
  // "lower", "optimize", "interfaces", "print", "validate"): where a lowering's time goes
  // (`doublet bench --compiler` prints their medians).
  std::vector<std::pair<std::string, double>> phase_seconds;
};

// The most bytes of shader source lower() accepts: the source plus every #include'd file's
// text. Over it, lower() answers with an error at file:1:1 and reads no more includes; the
// CLI stops reading an input at this size plus one byte (docs/robustness.md, "Input size").
// Real shaders are kilobytes; the limit only stops runaway inputs (/dev/zero, `yes |`).
inline constexpr std::size_t kMaxSourceBytes = std::size_t{64} << 20;  // 64 MiB

Result lower(std::string_view source, const Options& options);

// Spelling helpers shared by the CLI and tests.
std::string_view to_string(Target t);           // "es300"
std::string_view to_string(Stage s);            // "vert"
std::optional<Target> parse_target(std::string_view name);
std::string_view to_string(Mode m);             // "fp32", "rte", "df64-fast", "df64", "native", "df64-int", "exact", "rte-exact"
std::optional<Mode> parse_mode(std::string_view name);
std::optional<Stage> parse_stage(std::string_view name);  // "vert"|"frag"|"comp"
std::optional<GuardKind> parse_guard(std::string_view name);  // "auto"|"precise"|"uniform" (None: tests only)
// The passes of the pipeline, in order (Options::stop_after names one): "parse", "import", ...
std::vector<std::string_view> pass_names();
// The lints Options::disabled_lints can name: "float-literal", "wasted-double", ...
std::vector<std::string_view> lint_names();
// Stage from a file name: x.vert, x.frag, x.comp, x.vert.glsl, ...
std::optional<Stage> stage_from_path(std::string_view path);
bool target_is_es(Target t);
int target_version(Target t);  // 100, 300, 310, 320, 330, 450

}  // namespace doublet
