// The std140/std430 layout of a lowered uniform/storage block, for the manifest: a host that
// filled the block with IEEE doubles must now write hi/lo float pairs at these offsets.
#pragma once

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"

namespace doublet::passes {

// Members (nested struct members with dotted names) of `block`, whose type is already lowered,
// laid out with `packing` ("std140" or "std430").
// True when `t` (before or after lowering) holds doubles anywhere in its members.
bool holds_doubles(const ir::Type& t);

std::vector<BlockMember> block_layout(const ir::Type& block, const std::string& packing);

// Size, alignment and (for an array) element stride of `t` in std140 or std430; a runtime-sized
// array has size 0. The WGSL printer lays std140 blocks out with these (docs/web.md).
struct StdLayout {
  int size = 0, align = 4, stride = 0;
};
StdLayout std_layout(const ir::Type& t, bool std140);

}  // namespace doublet::passes
