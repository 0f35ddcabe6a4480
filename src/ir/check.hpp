// The IR's consistency check, run between passes in the test suites (Options::check_ir): a pass
// that leaves a malformed tree is named at once instead of surfacing as a printer crash or an
// invalid output several passes later (docs/architecture.md, "Checking the IR").
#pragma once

#include <string>

#include "ir/ir.hpp"

namespace doublet::ir {

// Empty when the module is consistent, else the first problem found:
//  - every node has the operands its kind needs (unary 1, binary 2, ternary 3, member 1, index 2,
//    a symbol its variable, a declaration its variable, an if its branches, a loop its body);
//  - every local variable a function uses is declared in that function, once; every parameter
//    it uses is one of its own.
std::string check(const Module& module);

}  // namespace doublet::ir
