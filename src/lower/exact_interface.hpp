// Mode exact's interface (docs/modes.md, "exact"): a double crosses the shader's edge as the
// 32-bit words of its IEEE binary64 pattern, LOW word first, the order of packDouble2x32 and of a
// little-endian host's memory, so the raw bytes of a host double array are the words unchanged.
//   double X  -> uvec2 X                        (x = low word, y = high word)
//   dvec2 X   -> uvec4 X                        (lo0, hi0, lo1, hi1)
//   dvec3 X   -> uvec4 X_xy + uvec2 X_z         (ES 3.00 vertex inputs cannot be arrays, and no
//   dvec4 X   -> uvec4 X_xy + uvec4 X_zw         integer vector has 6 or 8 components)
// Arrays keep their dimensions on each part. Inside the shader the value is the df_* struct of
// uint words (high, low) that rules/exact.glsl computes with; it is joined from the words at the
// start of main and split into them before main returns, as split_interfaces does for hi/lo.
#pragma once

#include <string>
#include <vector>

#include "lower/lower.hpp"

namespace doublet::passes::exact_io {

// The manifest's `encoding` of a variable or block member carried as binary64 words.
inline constexpr const char* kEncoding = "binary64-words";

// The suffixes of the parts of a double vector of `width` components: {""} for double and dvec2,
// {"_xy", "_z"} for dvec3, {"_xy", "_zw"} for dvec4.
std::vector<std::string> part_suffixes(int width);
// The word type of part `part` of a double vector of `width` components: uvec2 or uvec4.
ir::Type part_type(int width, int part);

// The words of one df_* value `value` (a pure expression of type df_dvecW) for part `part`.
ir::ExprPtr words_of(const ir::ExprPtr& value, int width, int part);
// The df_dvecW value of the words in `parts` (one or two pure expressions).
ir::ExprPtr value_of(const std::vector<ir::ExprPtr>& parts, int width);

// Whether an in/out of `stage` passes between two shader stages (every one but a vertex input and
// a fragment output), where words, being integers, must be `flat`.
inline bool between_stages(ir::Storage storage, ir::StageKind stage) {
  if (storage == ir::Storage::In) return stage != ir::StageKind::Vertex;
  return storage == ir::Storage::Out && stage != ir::StageKind::Fragment;
}

}  // namespace doublet::passes::exact_io
