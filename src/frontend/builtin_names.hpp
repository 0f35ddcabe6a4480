// Spellings of glslang operators and built-in functions, for the importer.
#pragma once

#include <glslang/Include/intermediate.h>

namespace doublet::frontend {

const char* binary_operator_spelling(glslang::TOperator op);
const char* unary_operator_spelling(glslang::TOperator op);
bool is_conversion(glslang::TOperator op);
// GLSL name of a built-in function operator, or nullptr when doublet does not
// know it. `args` disambiguates operators shared by operators and functions.
const char* builtin_function_name(glslang::TOperator op, int args);

}  // namespace doublet::frontend
