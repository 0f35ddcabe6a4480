// Generated GLSL helpers for double matrices.
//
// Representation: a dmatCxR becomes `struct df_dmatCxR { matCxR hi; matCxR lo; }` (hi/lo
// matrices, like df_dvecN's hi/lo vectors) rather than a struct of column df vectors:
//   - a double matrix uniform splits into two float matrix uniforms, M_hi and M_lo, joined by
//     one constructor `df_dmat4(M_hi, M_lo)`, and printing needs no per-column fields;
//   - column j is `df_dvecR(m.hi[j], m.lo[j])` and element (j, i) `m.hi[j][i]`, so constant and
//     dynamic indexing are ordinary GLSL indexing on every target (ES 1.00 included);
//   - ES 1.00 has only square matrices, so dmatCxR with C != R is diagnosed there.
// The helpers move words only (no float arithmetic of their own); every rounding step is a call
// into rules/ (df_add, df_mul, df_dot, df_div, ...), so the optimizer guard of those rules
// protects them. Each helper's header states the algorithm and the error bound that follows
// from the rules it calls (docs/rules.md, "Generated matrix helpers").
#pragma once

#include <string>
#include <vector>

#include "lower/lower.hpp"

namespace doublet::passes::matrix {

std::string type_name(int cols, int rows);      // df_dmat4, df_dmat2x3
std::string float_type_name(int cols, int rows);  // mat4, mat2x3
ir::Type type(int cols, int rows);
bool is_matrix(const ir::Type& t);              // a df_dmat* struct (not an array of them)
int cols(const ir::Type& t);
int rows(const ir::Type& t);

// Each function adds the helper (and what it calls) to the context once and returns its name.
enum class Operand { Matrix, Scalar };
// rule ∈ df_add df_sub df_mul df_div: component-wise on (a, b); a scalar operand is applied to
// every element. `df_neg` with one operand.
std::string elementwise(Context& ctx, const std::string& rule, int cols, int rows, Operand a, Operand b);
std::string negate(Context& ctx, int cols, int rows);
std::string times_vector(Context& ctx, int cols, int rows);        // dmatCxR * dvecC -> dvecR
std::string vector_times(Context& ctx, int cols, int rows);        // dvecR * dmatCxR -> dvecC
std::string times_matrix(Context& ctx, int inner, int rows, int cols);  // (inner x rows) * (cols x inner)
std::string outer_product(Context& ctx, int cols, int rows);       // dvecR, dvecC -> dmatCxR
std::string transpose(Context& ctx, int cols, int rows);
std::string determinant(Context& ctx, int n);
std::string inverse(Context& ctx, int n);
std::string equal(Context& ctx, int cols, int rows, bool negated);
std::string column(Context& ctx, int cols, int rows);              // m[j] with dynamic j
std::string assign_column(Context& ctx, int cols, int rows);       // m[j] = v
std::string assign_element(Context& ctx, int cols, int rows);      // m[j][i] = x
// Constructors: from df scalars/vectors (widths of the arguments), the diagonal of one df
// scalar, another df matrix (resize), and conversion to a float matrix.
std::string from_components(Context& ctx, int cols, int rows, const std::vector<int>& widths);
std::string diagonal(Context& ctx, int cols, int rows);
std::string resize(Context& ctx, int from_cols, int from_rows, int cols, int rows);
std::string to_float(Context& ctx, int cols, int rows);

// Text pieces of the helpers that run as loops (mode exact's, df64-int's products;
// docs/performance.md, "Mode exact: vector and matrix operations as loops"):
// `for` over `count` values of `index`, from count - 1 down to 0, at indentation `pad`; the caller
// closes the brace. The index is computed from the counter, not the counter itself: Mesa's GLSL
// compiler unrolls, whatever its size, a loop whose counter indexes an array with as many elements as
// the loop has iterations (counting up, mode exact's dmat4 determinant compiled in 931 ms on Mesa GLES
// instead of 386 ms).
std::string loop_down(const std::string& index, int count, const std::string& pad, const std::string& counter = "k");
// Statements storing the df vector or scalar `value` as column (component) `at` of `m`.
std::string store_column(const std::string& m, const std::string& at, const std::string& value, const std::string& pad);

}  // namespace doublet::passes::matrix
