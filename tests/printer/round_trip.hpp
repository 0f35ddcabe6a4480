// Printer round trip (issue 13): a generated module is printed by emit::print, parsed back by
// glslang (doublet's own front end) and imported into the IR again; the body of main must have the
// same structure as the generated one. A printer that drops parentheses the grammar needs (a
// comma expression as an argument, an assignment as an operand, a nested ternary, ...) changes the
// structure, so the comparison finds it.
//
// The generator builds well-typed expression trees over float, vec2, vec3, int and bool: every
// operator, ternary, comma, assignment (=, op=, on variables and swizzles), ++/--, swizzles and
// indexing of expressions, constructors, built-in and overloaded user calls; statements are
// declarations with initialisers, assignments, an if/else and a for loop whose step is a generated
// expression. Subtrees made of constants only are avoided: glslang folds them, which is not a
// printer bug. Shared by tests/printer (seeded) and fuzz/printer_fuzzer.cpp (libFuzzer's bytes).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"

namespace doublet::roundtrip {

// A source of choices: returns a value in [0, bound), bound >= 1.
using Chooser = std::function<uint32_t(uint32_t bound)>;

// A fragment-shader module: uniforms, overloaded functions f and g, and main with `statements`
// generated statements whose expressions are at most `depth` operators deep.
ir::Module random_module(const Chooser& choose, int statements, int depth);

// A structural description of an expression or a statement (kinds, operators, names, types), with
// the spellings glslang treats alike made equal (v.y and v[1]; (a, b), c and a, b, c).
std::string describe(const ir::ExprPtr& e);
std::string describe(const ir::StmtPtr& s);

// Prints `module` for `target`, parses the text back and imports it. Empty when main's body has
// the generated structure; otherwise the printed text and both descriptions.
std::string round_trip_difference(const ir::Module& module, Target target);

}  // namespace doublet::roundtrip
