// Mode exact's double-matrix helpers (matrix_helpers_exact.cpp): the interface of
// matrix_helpers.hpp on `struct df_dmatCxR { uvecR hi[C]; uvecR lo[C]; }`, in native fp64's order
// of operations. matrix_helpers.cpp forwards to these when the mode is exact.
#pragma once

#include <string>
#include <vector>

#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"

namespace doublet::passes::matrix::exact {

std::string elementwise(Context& ctx, const std::string& rule, int cols, int rows, Operand a, Operand b);
std::string negate(Context& ctx, int cols, int rows);
std::string times_vector(Context& ctx, int cols, int rows);
std::string vector_times(Context& ctx, int cols, int rows);
std::string times_matrix(Context& ctx, int inner, int rows, int cols);
std::string outer_product(Context& ctx, int cols, int rows);
std::string transpose(Context& ctx, int cols, int rows);
std::string determinant(Context& ctx, int n);
std::string inverse(Context& ctx, int n);
std::string equal(Context& ctx, int cols, int rows, bool negated);
std::string from_components(Context& ctx, int cols, int rows, const std::vector<int>& widths);
std::string diagonal(Context& ctx, int cols, int rows);
std::string resize(Context& ctx, int from_cols, int from_rows, int cols, int rows);
std::string to_float(Context& ctx, int cols, int rows);
std::string from_float(Context& ctx, int cols, int rows);  // dmatCxR(matCxR): each element widened

}  // namespace doublet::passes::matrix::exact
