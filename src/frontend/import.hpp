// Import: glslang's typed AST → doublet's IR (src/ir/ir.hpp).
//
// glslang flattens what the printer needs back: locals declared without an
// initialiser do not appear, `float a = 1.0;` is an assignment, for-loops are a
// sequence of init + loop, constants are folded. place_declarations() rebuilds
// declarations so that the printed code keeps the user's scoping.
#pragma once

#include <vector>

#include "doublet/doublet.hpp"
#include "frontend/frontend.hpp"
#include "ir/ir.hpp"

namespace doublet::frontend {

// Returns false (with diagnostics) for constructs the IR cannot carry.
bool import_module(const ParsedShader& parsed, const Options& options, ir::Module& out,
                   std::vector<Diagnostic>& diagnostics);

}  // namespace doublet::frontend
