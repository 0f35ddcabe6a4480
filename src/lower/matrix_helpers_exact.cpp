// Generated helpers for double matrices in mode exact (rules/exact.glsl): the same interface as
// matrix_helpers.cpp, on the representation
//   struct df_dmatCxR { uvecR hi[C]; uvecR lo[C]; }
// (GLSL has no uint matrices), so column j is still `df_dvecR(m.hi[j], m.lo[j])` and element
// (j, i) `m.hi[j][i]`. Every product, sum and quotient is one binary64 rounding in native fp64's
// order on lavapipe, as spirv_to_nir builds it and Mesa's optimizer reorders it (measured against
// candidate orders; tests/exact/exact_matrix_test.cpp checks the results bit for bit):
//   m * v: r[i] = fma(m[0][i], v[0], fma(m[1][i], v[1], ... m[C-1][i] * v[C-1])), the last
//          column first (vtn_alu.c matrix_multiply), each fma rounding twice as native's does;
//   v * m: the same on the rows of m (native transposes m); m * n: m times each column of n;
//   determinant: ex_det2_bits, ex_det3_bits, and for 4x4 ((p0 + (p2 - p3)) - p1) with
//          p_i = det3(rows != i of columns 1-3) * m[0][i] (vtn_glsl450.c build_mat4_det, reordered);
//   inverse: the adjugate (signed sub-determinants, vtn_glsl450.c matrix_inverse) times
//          1 / determinant (one division, then a product per element).
// Sources: Mesa src/compiler/spirv/vtn_alu.c and vtn_glsl450.c, read as a fact source, not copied.
#include <functional>

#include "lower/matrix_helpers.hpp"
#include "lower/matrix_helpers_exact.hpp"

namespace doublet::passes::matrix::exact {

namespace {

std::string n(int i) { return std::to_string(i); }
std::string uvec(int w) { return w == 1 ? "uint" : "uvec" + n(w); }
std::string dvec(int w) { return df_type_name(w); }
std::string suffix(int cols, int rows) { return type_name(cols, rows).substr(3); }  // dmat4
const char* kOne = "uvec2(0u, 0x3FF00000u)";

// The binary64 pattern (uvec2 low, high) of element (column j, row i); j and i may be expressions.
std::string elem(const std::string& m, const std::string& j, const std::string& i) {
  return "uvec2(" + m + ".lo[" + j + "][" + i + "], " + m + ".hi[" + j + "][" + i + "])";
}
std::string elem(const std::string& m, int j, int i) { return elem(m, n(j), n(i)); }

// The value `t` of 0..size-2 skipping `skipped` (an expression): t below it, t + 1 from it on.
std::string skipping(int t, const std::string& skipped) {
  return "(" + n(t) + " < " + skipped + " ? " + n(t) + " : " + n(t + 1) + ")";
}
// Component i of a df vector of width w, as a pattern.
std::string comp(const std::string& v, int w, int i) {
  if (w == 1) return "uvec2(" + v + ".lo, " + v + ".hi)";
  return "uvec2(" + v + ".lo[" + n(i) + "], " + v + ".hi[" + n(i) + "])";
}
std::string col(const std::string& m, const std::string& j, int rows) {
  return dvec(rows) + "(" + m + ".hi[" + j + "], " + m + ".lo[" + j + "])";
}
std::string col(const std::string& m, int j, int rows) { return col(m, n(j), rows); }
// Statements storing the pattern `value` (uvec2 low, high) as `target.hi<at>` and `target.lo<at>`.
std::string store_pattern(const std::string& target, const std::string& at, const std::string& value, const std::string& pad) {
  return pad + target + ".hi" + at + " = " + value + ".y;\n" + pad + target + ".lo" + at + " = " + value + ".x;\n";
}
// df_dmatCxR from column df vectors named prefix0..prefix{C-1}.
std::string from_columns(const std::string& prefix, int cols, int rows) {
  std::string hi, lo;
  for (int j = 0; j < cols; ++j) {
    hi += (j ? ", " : "") + prefix + n(j) + ".hi";
    lo += (j ? ", " : "") + prefix + n(j) + ".lo";
  }
  const std::string array = uvec(rows) + "[" + n(cols) + "]";
  return type_name(cols, rows) + "(" + array + "(" + hi + "), " + array + "(" + lo + "))";
}
// df_dmatCxR from element patterns given by `at(j, i)`.
std::string from_elements(int cols, int rows, const std::function<std::string(int, int)>& at) {
  std::string hi, lo;
  for (int j = 0; j < cols; ++j) {
    std::string h, l;
    for (int i = 0; i < rows; ++i) {
      h += (i ? ", " : "") + at(j, i) + ".y";
      l += (i ? ", " : "") + at(j, i) + ".x";
    }
    hi += (j ? ", " : "") + uvec(rows) + "(" + h + ")";
    lo += (j ? ", " : "") + uvec(rows) + "(" + l + ")";
  }
  const std::string array = uvec(rows) + "[" + n(cols) + "]";
  return type_name(cols, rows) + "(" + array + "(" + hi + "), " + array + "(" + lo + "))";
}
void use_bits(Context& ctx, std::initializer_list<const char*> rules) {
  for (const char* r : rules) ctx.use_rule(r, 1);
}

// Statements leaving fma(a(0), b(0), fma(a(1), b(1), ... a(len-1) * b(len-1))) in the pattern `s`:
// native's matrix-product chain, last term first, the fmas in a loop over t (its counter indexes
// arrays of len elements len - 1 times, so drivers keep the loop).
std::string chain(int len, const std::function<std::string(const std::string&)>& a,
                  const std::function<std::string(const std::string&)>& b, const std::string& pad) {
  std::string s = pad + "uvec2 s = ex_mul_first(" + a(n(len - 1)) + ", " + b(n(len - 1)) + ");\n";
  if (len > 1)
    s += pad + "for (int t = " + n(len - 2) + "; t >= 0; --t) s = ex_fma_bits(" + a("t") + ", " + b("t") + ", s);\n";
  return s;
}

}  // namespace

std::string elementwise(Context& ctx, const std::string& rule, int c, int r, Operand a, Operand b) {
  const std::string ex_rule = "ex_" + rule.substr(3);
  auto spell = [&](Operand o) { return o == Operand::Matrix ? suffix(c, r) : std::string("double"); };
  std::string name = ex_rule + "_" + spell(a) + "_" + spell(b);
  if (rule == "df_mul" && a == Operand::Matrix && b == Operand::Matrix) name = "ex_matrix_comp_mult_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule(ex_rule, r);
  ctx.use_matrix(c, r);
  auto arg = [&](Operand o, const std::string& v, const std::string& j) {
    return o == Operand::Matrix ? col(v, j, r) : dvec(r) + "(" + uvec(r) + "(" + v + ".hi), " + uvec(r) + "(" + v + ".lo))";
  };
  auto param = [&](Operand o, const std::string& v) {
    return (o == Operand::Matrix ? type_name(c, r) : std::string("df_double")) + " " + v;
  };
  // A matrix times a scalar (either order) passes on the matrix element's NaN first, as native's
  // per-column product does: the scalar goes first into ex_mul, which prefers its second operand.
  // A matrix divided by a scalar is, in native's SPIR-V, the matrix times the scalar's reciprocal.
  const bool by_reciprocal = rule == "df_div" && a == Operand::Matrix && b == Operand::Scalar;
  const std::string op = by_reciprocal ? "ex_mul" : ex_rule;
  if (by_reciprocal) {
    ctx.use_rule("ex_mul", r);
    ctx.use_rule("ex_div", 1);
  }
  const bool scalar_first = (rule == "df_mul" || by_reciprocal) && (a == Operand::Scalar || b == Operand::Scalar);
  const std::string first = scalar_first && b == Operand::Scalar ? "b" : "a", second = first == "a" ? "b" : "a";
  const Operand first_kind = first == "a" ? a : b, second_kind = first == "a" ? b : a;
  std::string body = "// " + name + ": " + ex_rule + " on each element (column by column), as native's per-column operation" +
                     (by_reciprocal ? " (m / s = m * (1 / s), as native)" : "") + ".\n" + type_name(c, r) + " " + name +
                     "(" + param(a, "a") + ", " + param(b, "b") + ") {\n";
  if (by_reciprocal) body += "  b = ex_div(df_double(0x3FF00000u, 0u), b);\n";
  body += "  " + type_name(c, r) + " m;\n" + loop_down("j", c, "  ") + "    " + dvec(r) + " cj = " + op + "(" +
          arg(first_kind, first, "j") + ", " + arg(second_kind, second, "j") + ");\n" + store_column("m", "j", "cj", "    ") +
          "  }\n  return m;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string negate(Context& ctx, int c, int r) {
  std::string name = "ex_neg_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  std::string hi;
  for (int j = 0; j < c; ++j) hi += (j ? ", " : "") + std::string("a.hi[") + n(j) + "] ^ " + uvec(r) + "(0x80000000u)";
  ctx.add_helper(name, "// " + name + ": exact (sign bits flipped, NaN included, as native's negation).\n" +
                           type_name(c, r) + " " + name + "(" + type_name(c, r) + " a) {\n  return " + type_name(c, r) + "(" +
                           uvec(r) + "[" + n(c) + "](" + hi + "), a.lo);\n}\n");
  return name;
}

std::string times_vector(Context& ctx, int c, int r) {
  std::string name = "ex_mul_" + suffix(c, r) + "_" + dvec(c).substr(3);
  if (ctx.helpers.count(name)) return name;
  use_bits(ctx, {"ex_mul_first", "ex_fma_bits"});
  ctx.use_matrix(c, r);
  ctx.use_width(c);
  ctx.use_width(r);
  std::string body = "// " + name + ": (m * v)[i] = fma(m[0][i], v[0], fma(m[1][i], v[1], ...)), the last column\n"
                     "// first, every step rounded as native's (each fma twice).\n" +
                     dvec(r) + " " + name + "(" + type_name(c, r) + " m, " + dvec(c) + " v) {\n  " + dvec(r) + " p;\n" +
                     loop_down("i", r, "  ") +
                     chain(c, [](const std::string& j) { return elem("m", j, "i"); },
                           [](const std::string& j) { return "uvec2(v.lo[" + j + "], v.hi[" + j + "])"; }, "    ") +
                     store_pattern("p", "[i]", "s", "    ") + "  }\n  return p;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string vector_times(Context& ctx, int c, int r) {
  std::string name = "ex_mul_" + dvec(r).substr(3) + "_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  use_bits(ctx, {"ex_mul_first", "ex_fma_bits"});
  ctx.use_matrix(c, r);
  ctx.use_width(c);
  ctx.use_width(r);
  std::string body = "// " + name + ": (v * m)[j] = fma(m[j][0], v[0], fma(m[j][1], v[1], ...)), the last row first,\n"
                     "// as native's product with the transposed matrix.\n" +
                     dvec(c) + " " + name + "(" + dvec(r) + " v, " + type_name(c, r) + " m) {\n  " + dvec(c) + " p;\n" +
                     loop_down("j", c, "  ") +
                     chain(r, [](const std::string& i) { return elem("m", "j", i); },
                           [](const std::string& i) { return "uvec2(v.lo[" + i + "], v.hi[" + i + "])"; }, "    ") +
                     store_pattern("p", "[j]", "s", "    ") + "  }\n  return p;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string times_matrix(Context& ctx, int inner, int r, int c) {
  std::string name = "ex_mul_" + suffix(inner, r) + "_" + suffix(c, inner);
  if (ctx.helpers.count(name)) return name;
  std::string mv = times_vector(ctx, inner, r);
  ctx.use_matrix(c, inner);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": column j of a * b is a * (column j of b) (" + mv + ").\n" + type_name(c, r) + " " +
                     name + "(" + type_name(inner, r) + " a, " + type_name(c, inner) + " b) {\n";
  body += "  " + type_name(c, r) + " m;\n" + loop_down("j", c, "  ") + "    " + dvec(r) + " cj = " + mv + "(a, " +
          col("b", "j", inner) + ");\n" + store_column("m", "j", "cj", "    ") + "  }\n  return m;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string outer_product(Context& ctx, int c, int r) {
  std::string name = "ex_outer_product_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  use_bits(ctx, {"ex_mul_bits"});
  ctx.use_width(c);
  ctx.use_width(r);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": element (j, i) = a[i] * b[j], one rounding.\n" + type_name(c, r) + " " + name + "(" +
                     dvec(r) + " a, " + dvec(c) + " b) {\n  " + type_name(c, r) + " m;\n" + loop_down("j", c, "  ") +
                     loop_down("i", r, "    ", "l") +
                     "      uvec2 e = ex_mul_bits(uvec2(a.lo[i], a.hi[i]), uvec2(b.lo[j], b.hi[j]));\n" +
                     store_pattern("m", "[j][i]", "e", "      ") + "    }\n  }\n  return m;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string transpose(Context& ctx, int c, int r) {
  std::string name = "ex_transpose_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.use_matrix(r, c);
  ctx.add_helper(name, "// " + name + ": exact (words moved).\n" + type_name(r, c) + " " + name + "(" + type_name(c, r) +
                           " m) {\n  return " + from_elements(r, c, [&](int j, int i) { return elem("m", i, j); }) +
                           ";\n}\n");
  return name;
}

namespace {

// The patterns of the elements of m outside row `skip_row` and column `skip_col`, column-major.
std::vector<std::string> minor_elements(int size, int skip_row, int skip_col) {
  std::vector<std::string> out;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      if (j != skip_col && i != skip_row) out.push_back(elem("m", j, i));
  return out;
}

std::string call(const std::string& f, const std::vector<std::string>& args) {
  std::string s = f + "(";
  for (size_t k = 0; k < args.size(); ++k) s += (k ? ", " : "") + args[k];
  return s + ")";
}

// The determinant of an size x size submatrix given by its element patterns, column-major.
std::string det_of(const std::vector<std::string>& e) {
  if (e.size() == 1) return e[0];
  return call(e.size() == 4 ? "ex_det2_bits" : "ex_det3_bits", e);
}

// The patterns of the (size - 1)^2 elements of m outside row `skip_row` and column `skip_col` (int
// expressions), column-major, through the index variables j0, j1, ... (columns) and i0, i1, ...
// (rows) whose declarations are appended to `indices`.
std::vector<std::string> minor_elements(int size, const std::string& skip_row, const std::string& skip_col,
                                        std::string& indices, const std::string& pad) {
  std::vector<std::string> out;
  for (int t = 0; t + 1 < size; ++t)
    indices += pad + "int j" + n(t) + " = " + skipping(t, skip_col) + ", i" + n(t) + " = " + skipping(t, skip_row) + ";\n";
  for (int j = 0; j + 1 < size; ++j)
    for (int i = 0; i + 1 < size; ++i) out.push_back(elem("m", "j" + n(j), "i" + n(i)));
  return out;
}

// Statements that leave the determinant of m (size x size) in the pattern `det`; for 4 x 4 the four
// products p[r] of a 3 x 3 sub-determinant and m[0][r] in a loop.
std::string determinant_statements(int size) {
  if (size < 4) return "  uvec2 det = " + det_of(minor_elements(size, -1, -1)) + ";\n";
  std::string s = "  uvec2 p[4];\n" + loop_down("r", 4, "  ");
  // Rows other than r of columns 1-3: the minor of row r and column 0.
  std::vector<std::string> e;
  for (int j = 1; j < 4; ++j)
    for (int t = 0; t < 3; ++t) e.push_back(elem("m", n(j), "i" + n(t)));
  for (int t = 0; t < 3; ++t) s += "    int i" + n(t) + " = " + skipping(t, "r") + ";\n";
  s += "    p[r] = ex_mul_first(" + det_of(e) + ", " + elem("m", "0", "r") + ");\n  }\n";
  return s + "  uvec2 det = ex_sub_bits(ex_add_first(p[0], ex_sub_bits(p[2], p[3])), p[1]);\n";
}

void use_determinant_rules(Context& ctx) {
  use_bits(ctx, {"ex_det2_bits", "ex_det3_bits", "ex_mul_first", "ex_add_first", "ex_sub_bits"});
}

}  // namespace

std::string determinant(Context& ctx, int size) {
  std::string name = "ex_determinant_" + suffix(size, size);
  if (ctx.helpers.count(name)) return name;
  use_determinant_rules(ctx);
  use_bits(ctx, {"ex_from_bits"});
  ctx.use_matrix(size, size);
  ctx.add_helper(name, "// " + name + ": native's determinant (spirv_to_nir's expansion in Mesa's order).\ndf_double " + name +
                           "(" + type_name(size, size) + " m) {\n" + determinant_statements(size) +
                           "  return ex_from_bits(det);\n}\n");
  return name;
}

std::string inverse(Context& ctx, int size) {
  std::string name = "ex_inverse_" + suffix(size, size);
  if (ctx.helpers.count(name)) return name;
  use_determinant_rules(ctx);
  use_bits(ctx, {"ex_div_bits", "ex_neg_bits", "ex_mul_bits"});
  ctx.use_matrix(size, size);
  // Element (column c, row r) = (-1)^(r+c) det(m without row c and column r) * (1 / det): an even
  // cofactor is the first operand of the product, an odd (negated) one the second, as native's NaN choice says.
  // One loop over the elements: q counts them down, c = q / size, r = q % size; one product with the
  // operands swapped by selects (ex_mul_first(x, y) is ex_mul_bits(y, x)).
  std::string indices;
  const std::string e = det_of(minor_elements(size, "c", "r", indices, "    "));
  std::string body = "// " + name + ": the adjugate times 1 / determinant, as native computes it.\n" +
                     type_name(size, size) + " " + name + "(" + type_name(size, size) + " m) {\n" +
                     determinant_statements(size) + "  uvec2 inv = ex_div_bits(" + kOne + ", det);\n  " +
                     type_name(size, size) + " a;\n" + loop_down("q", size * size, "  ") + "    int c = q / " + n(size) +
                     ", r = q - c * " + n(size) + ";\n" + indices + "    uvec2 d = " + e + ";\n" +
                     "    bool odd = ((c + r) & 1) != 0;\n"
                     "    uvec2 e = ex_mul_bits(odd ? ex_neg_bits(d) : inv, odd ? inv : d);\n" +
                     store_pattern("a", "[c][r]", "e", "    ") + "  }\n  return a;\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string equal(Context& ctx, int c, int r, bool negated) {
  std::string name = std::string(negated ? "ex_not_equal_" : "ex_equal_") + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("ex_equal", r);
  ctx.use_matrix(c, r);
  std::string test;
  for (int j = 0; j < c; ++j) test += (j ? " && " : "") + std::string("ex_equal(") + col("a", j, r) + ", " + col("b", j, r) + ")";
  ctx.add_helper(name, "// " + name + ": every element equal (false with a NaN, -0 == +0), as native's ==.\nbool " + name +
                           "(" + type_name(c, r) + " a, " + type_name(c, r) + " b) {\n  return " +
                           (negated ? "!(" + test + ")" : test) + ";\n}\n");
  return name;
}

std::string from_components(Context& ctx, int c, int r, const std::vector<int>& widths) {
  std::string name = "ex_make_" + suffix(c, r);
  for (int w : widths) name += "_" + n(w);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  std::string params;
  std::vector<std::string> parts;  // element patterns, column-major
  for (size_t k = 0; k < widths.size(); ++k) {
    ctx.use_width(widths[k]);
    const std::string p = "a" + n(static_cast<int>(k));
    params += (k ? ", " : "") + dvec(widths[k]) + " " + p;
    for (int i = 0; i < widths[k]; ++i) parts.push_back(comp(p, widths[k], i));
  }
  ctx.add_helper(name, type_name(c, r) + " " + name + "(" + params + ") {\n  return " +
                           from_elements(c, r, [&](int j, int i) { return parts[size_t(j * r + i)]; }) + ";\n}\n");
  return name;
}

std::string diagonal(Context& ctx, int c, int r) {
  std::string name = "ex_diagonal_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.add_helper(name, type_name(c, r) + " " + name + "(df_double s) {\n  uvec2 d = uvec2(s.lo, s.hi);\n  return " +
                           from_elements(c, r, [](int j, int i) { return i == j ? std::string("d") : "uvec2(0u)"; }) +
                           ";\n}\n");
  return name;
}

std::string resize(Context& ctx, int fc, int fr, int c, int r) {
  std::string name = "ex_resize_" + suffix(fc, fr) + "_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(fc, fr);
  ctx.use_matrix(c, r);
  // GLSL: the elements the source has, else the identity's.
  ctx.add_helper(name, type_name(c, r) + " " + name + "(" + type_name(fc, fr) + " a) {\n  return " +
                           from_elements(c, r, [&](int j, int i) {
                             if (j < fc && i < fr) return elem("a", j, i);
                             return i == j ? std::string(kOne) : std::string("uvec2(0u)");
                           }) +
                           ";\n}\n");
  return name;
}

std::string to_float(Context& ctx, int c, int r) {
  std::string name = "ex_to_" + float_type_name(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("ex_to_float", r);
  ctx.use_matrix(c, r);
  std::string cols;
  for (int j = 0; j < c; ++j) cols += (j ? ", " : "") + std::string("ex_to_float(") + col("a", j, r) + ")";
  ctx.add_helper(name, "// " + name + ": each element rounded to float (ex_to_float).\n" + float_type_name(c, r) + " " + name +
                           "(" + type_name(c, r) + " a) {\n  return " + float_type_name(c, r) + "(" + cols + ");\n}\n");
  return name;
}

std::string from_float(Context& ctx, int c, int r) {
  std::string name = "ex_from_" + float_type_name(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("ex_from_float", r);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": each element widened exactly (ex_from_float).\n" + type_name(c, r) + " " + name + "(" +
                     float_type_name(c, r) + " f) {\n";
  for (int j = 0; j < c; ++j) body += "  " + dvec(r) + " c" + n(j) + " = ex_from_float(f[" + n(j) + "]);\n";
  body += "  return " + from_columns("c", c, r) + ";\n}\n";
  ctx.add_helper(name, body);
  return name;
}

}  // namespace doublet::passes::matrix::exact
