// Rebuilds local declarations lost by glslang and makes names unambiguous.
#pragma once

#include <vector>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"

namespace doublet::frontend {

// - `v = e` becomes `T v = e` where that point's scope covers every use of v;
//   other locals are declared at the top of their function;
// - locals that would clash with another name in scope are renamed `name_N`;
// - user identifiers with doublet's reserved prefix `df_` are errors.
bool place_declarations(ir::Module& module, const Options& options, std::vector<Diagnostic>& diagnostics);

}  // namespace doublet::frontend
