// The float-float runtime: GLSL rule files from rules/, embedded at build time,
// instantiated per vector width and guard style, emitted on demand.
//
// Rule file format (see docs/rules-format.md): each function is a "chunk"
// (its comment header + definition). Placeholders, substituted per width W:
//   $DF  df_double | df_dvec2 | df_dvec3 | df_dvec4   (the float-float type)
//   $F   float | vec2 | vec3 | vec4                   (the float type)
//   $B   bool  | bvec2 | bvec3 | bvec4
//   $I   int   | ivec2 | ivec3 | ivec4
//   $U   uint  | uvec2 | uvec3 | uvec4
//   $W   1 | 2 | 3 | 4
//   $PRECISE   `precise` when the guard is Precise; otherwise empty, and the space after it is dropped
//   $G(expr)   `(expr)` when Precise or None, `((expr) - df_guard)` when Uniform (x - 0 keeps -0),
//              `((expr) - df_guard[int(df_guard[1])])` when the guard is indexed
// Annotations in the chunk's header comment:
//   // @widths 1 2 3 4        widths this chunk is instantiated for (default: 1)
//   // @min-es 300            lowest ES version that may use it (default 100)
//   // @per-component         widths > 1 are generated: the width-1 rule applied to
//                             each component (for rules that need a per-component branch)
//   // @uses df_add:1         callee widths, when not the chunk's own width
//   // @variant int           replaces the same-named chunk when EmitRequest::integer_eft
//   // @variant integer-functions   replaces the same-named chunk when
//                             EmitRequest::integer_functions (umulExtended, findMSB: ES 3.10+, GLSL 4.00+)
//   // @variant bit-casts    replaces the same-named chunk when EmitRequest::bit_casts
//                             (floatBitsToUint and friends: every target but ES 1.00)
//   When several apply, "int" wins over "integer-functions", which wins over "bit-casts".
// Required header lines: "Algorithm:", "Source:", "Bound:", "Flops:".
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace doublet::rules {

enum class GuardStyle { Precise, Uniform, None };

struct RuleRef {
  std::string name;  // e.g. "df_add"
  int width = 1;     // 1..4
  bool operator==(const RuleRef&) const = default;
};

// `struct NAME { HI; LO; };` — the one spelling of a hi/lo pair type (df_double, ff_dvec2, df_dmat3,
// ...): `hi` and `lo` are the member declarations ("vec2 hi", "uvec3 hi[3]"). `one_line` is the
// rule library's compact form; the runtime linker writes the types it adds one member per line.
std::string pair_struct_definition(const std::string& name, const std::string& hi, const std::string& lo, bool one_line);

// Elements of the indexed guard (`float df_guard[2]`): element 0 is read at the index element 1 holds.
constexpr int kIndexedGuardElements = 2;

struct EmitRequest {
  std::vector<RuleRef> used;        // what the lowered code calls directly
  GuardStyle guard = GuardStyle::Uniform;
  std::string guard_uniform = "df_guard";
  // The uniform guard as `float df_guard[2]`, read as df_guard[int(df_guard[1])]: out of reach of
  // a driver's uniform inliner (docs/accuracy.md). Off where a uniform array may not be indexed by
  // a non-constant (ES 1.00 fragment shaders) and for WGSL (its uniform buffer holds one float).
  bool indexed_guard = false;
  int es_version = 300;             // 100/300/310/320; desktop targets pass 320
  bool integer_eft = false;         // df64-int: the "@variant int" chunks (rules/int.glsl) replace
                                    // the same-named float EFTs
  // The target has GLSL's integer functions (umulExtended, findMSB, ...: ES 3.10+, GLSL 4.00+):
  // the "@variant integer-functions" chunks (rules/exact.glsl) replace the same-named ones.
  bool integer_functions = false;
  // The target has floatBitsToUint/uintBitsToFloat (every target but ES 1.00): the
  // "@variant bit-casts" chunks (TwoProd's split by bits, rules/core.glsl) replace the same-named ones.
  bool bit_casts = false;
  // Mode exact: the df_* structs hold uint words (binary64 high and low words), not floats. A
  // float-float rule that an exact rule calls (the transcendental bridges) is emitted with its
  // types renamed ff_double/ff_dvecN (float words) and with the integer EFTs (as integer_eft).
  bool exact_words = false;
};

struct EmitResult {
  bool ok = false;
  std::string text;            // struct definitions, guard uniform, functions: dependency order
  size_t types_end = 0;        // where in `text` the struct definitions end (the guard or functions begin)
  std::string error;           // e.g. "df_to_uint is not available on ES 1.00"
  std::string error_rule;      // the requested rule the error is about (to place the diagnostic)
};

// What one chunk's header says (for documentation and tests).
struct RuleInfo {
  std::string name;
  std::vector<int> widths;
  int min_es = 100;
  bool per_component = false;
  std::string variant;    // the "@variant" kind ("int", "integer-functions", "bit-casts"), else empty
  std::string file;       // e.g. "arith.glsl"
  std::string algorithm;  // the "Algorithm:" line
  std::string source;     // the "Source:" line
  std::string bound;      // the "Bound:" line, e.g. "3u^2 + 13u^3" or "exact"
  std::string flops;      // the "Flops:" line
  std::string header;     // the whole header comment, annotations removed
};

class RuleLibrary {
 public:
  // The library built from the embedded rules/ files (parsed once, thread-safe).
  static const RuleLibrary& builtin();
  // Parse rule sources given as {file name, text}; for tests.
  static std::optional<RuleLibrary> parse(const std::vector<std::pair<std::string, std::string>>& files,
                                          std::string* error);

  bool has(const RuleRef& ref) const;
  // Each parameter's qualifier in the rule `name` (any width): "", "out" or "inout"; empty when no
  // rule has that name.
  std::vector<std::string> parameter_qualifiers(const std::string& name) const;
  // Emits the transitive closure of `used` (plus the df_* struct types they
  // need), each function exactly once, callees before callers.
  EmitResult emit(const EmitRequest& request) const;
  // Every {name,width} the library defines (for tests that instantiate all).
  std::vector<RuleRef> all() const;
  // One entry per chunk, in file order.
  std::vector<RuleInfo> info() const;

  RuleLibrary();
  ~RuleLibrary();
  RuleLibrary(RuleLibrary&&) noexcept;
  RuleLibrary& operator=(RuleLibrary&&) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace doublet::rules
