// Generated helpers for double matrices: see matrix_helpers.hpp for the representation.
// Bounds are first order in u = 2^-24 and follow from the rules called: df_add/df_sub
// 3u^2, df_mul 7u^2, df_div 15u^2, df_dot of width W (7 + 3*ceil(log2 W))u^2 * sum|a_i b_i|
// (rules/geometric.glsl). per(|A|) is the permanent of |A| (the sum of |products| that the
// determinant adds with signs): determinants and inverses cancel, so their bounds are absolute.
#include "lower/matrix_helpers.hpp"

#include "lower/matrix_helpers_exact.hpp"

#include <functional>
#include <map>

namespace doublet::passes::matrix {

namespace {

std::string n(int i) { return std::to_string(i); }
std::string vec(int w) { return w == 1 ? "float" : "vec" + n(w); }
std::string dvec(int w) { return df_type_name(w); }
std::string suffix(int cols, int rows) { return type_name(cols, rows).substr(3); }  // dmat4
char letter(int i) { return "xyzw"[i]; }

// `df_dvecR(m.hi[j], m.lo[j])`
std::string col(const std::string& m, const std::string& j, int rows) {
  return dvec(rows) + "(" + m + ".hi[" + j + "], " + m + ".lo[" + j + "])";
}
std::string col(const std::string& m, int j, int rows) { return col(m, n(j), rows); }
// `df_double(m.hi[j][i], m.lo[j][i])`
std::string elem(const std::string& m, int j, int i) {
  return "df_double(" + m + ".hi[" + n(j) + "][" + n(i) + "], " + m + ".lo[" + n(j) + "][" + n(i) + "])";
}
// df_dmatCxR from column df vectors named c0..c{C-1}.
std::string from_columns(const std::string& prefix, int cols, int rows) {
  std::string hi, lo;
  for (int j = 0; j < cols; ++j) {
    hi += (j ? ", " : "") + prefix + n(j) + ".hi";
    lo += (j ? ", " : "") + prefix + n(j) + ".lo";
  }
  std::string m = float_type_name(cols, rows);
  return type_name(cols, rows) + "(" + m + "(" + hi + "), " + m + "(" + lo + "))";
}
// df_dvecW from df_double temporaries named p0..p{W-1}.
std::string from_scalars(const std::string& prefix, int w) {
  if (w == 1) return prefix + "0";
  std::string hi, lo;
  for (int i = 0; i < w; ++i) {
    hi += (i ? ", " : "") + prefix + n(i) + ".hi";
    lo += (i ? ", " : "") + prefix + n(i) + ".lo";
  }
  return dvec(w) + "(" + vec(w) + "(" + hi + "), " + vec(w) + "(" + lo + "))";
}

int dot_constant(int w) { return w == 1 ? 7 : w == 2 ? 10 : 13; }

// Mode exact and rte-exact store double matrices as binary64 words (matrix_helpers_exact).
bool exact_mode(const Context& ctx) { return ctx.config.binary64_words(); }

// df64-int's products are long (an integer residual per TwoSum and TwoProd), so its matrix products
// keep one df_dot in a loop over the rows or columns instead of one per row: drivers compile a quarter
// of the code for a dmat4, with the same operations in the same order (docs/performance.md, "df64-int:
// matrix products as loops"). The index counts down from a counter, as mode exact's loops do
// (matrix_helpers_exact.cpp: Mesa's GLSL compiler unrolls a loop whose counter indexes an array of
// as many elements as it has iterations). df64-int needs ES 3.00, where such indexing is allowed.
bool loop_products(const Context& ctx) { return ctx.config.integer_eft; }

// The body of a product that stores df_dot(a(idx), b(idx)) as component idx of `p`, for idx from
// count - 1 down to 0, in a loop.
std::string dot_loop(int count, const std::string& result_type, const std::string& a, const std::string& b) {
  return "  " + result_type + " p;\n" + loop_down("idx", count, "  ") + "    df_double d = df_dot(" + a + ", " + b +
         ");\n" + store_column("p", "idx", "d", "    ") + "  }\n  return p;\n}\n";
}

}  // namespace

std::string loop_down(const std::string& index, int count, const std::string& pad, const std::string& counter) {
  return pad + "for (int " + counter + " = 0; " + counter + " < " + n(count) + "; ++" + counter + ") {\n" + pad + "  int " +
         index + " = " + n(count - 1) + " - " + counter + ";\n";
}
std::string store_column(const std::string& m, const std::string& at, const std::string& value, const std::string& pad) {
  return pad + m + ".hi[" + at + "] = " + value + ".hi;\n" + pad + m + ".lo[" + at + "] = " + value + ".lo;\n";
}

std::string type_name(int cols, int rows) {
  return cols == rows ? "df_dmat" + n(cols) : "df_dmat" + n(cols) + "x" + n(rows);
}
std::string float_type_name(int cols, int rows) { return cols == rows ? "mat" + n(cols) : "mat" + n(cols) + "x" + n(rows); }

ir::Type type(int cols, int rows) {
  ir::Type t;
  t.base = ir::Base::Struct;
  t.name = type_name(cols, rows);
  return t;
}

bool is_matrix(const ir::Type& t) {
  return t.base == ir::Base::Struct && !t.is_array() && t.name.rfind("df_dmat", 0) == 0;
}
int cols(const ir::Type& t) { return t.name[7] - '0'; }
int rows(const ir::Type& t) { return t.name.size() > 8 ? t.name[9] - '0' : cols(t); }

std::string elementwise(Context& ctx, const std::string& rule, int c, int r, Operand a, Operand b) {
  if (exact_mode(ctx)) return exact::elementwise(ctx, rule, c, r, a, b);
  auto spell = [&](Operand o) { return o == Operand::Matrix ? suffix(c, r) : std::string("double"); };
  std::string name = rule + "_" + spell(a) + "_" + spell(b);
  // df_mul_dmatN_dmatN is the linear-algebra product (times_matrix); component-wise is matrixCompMult.
  if (rule == "df_mul" && a == Operand::Matrix && b == Operand::Matrix) name = "df_matrix_comp_mult_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule(rule, r);
  ctx.use_matrix(c, r);
  auto arg = [&](Operand o, const std::string& v, int j) {
    return o == Operand::Matrix ? col(v, j, r) : r == 1 ? v : dvec(r) + "(" + vec(r) + "(" + v + ".hi), " + vec(r) + "(" + v + ".lo))";
  };
  auto param = [&](Operand o, const std::string& v) {
    return (o == Operand::Matrix ? type_name(c, r) : std::string("df_double")) + " " + v;
  };
  std::string body = "// " + name + ": " + rule + " on each element (column by column), so each element has " +
                     rule + "'s bound (rules/arith.glsl).\n" + type_name(c, r) + " " + name + "(" + param(a, "a") + ", " +
                     param(b, "b") + ") {\n";
  for (int j = 0; j < c; ++j)
    body += "  " + dvec(r) + " c" + n(j) + " = " + rule + "(" + arg(a, "a", j) + ", " + arg(b, "b", j) + ");\n";
  body += "  return " + from_columns("c", c, r) + ";\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string negate(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::negate(ctx, c, r);
  std::string name = "df_neg_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.add_helper(name, "// " + name + ": exact (both words negated).\n" + type_name(c, r) + " " + name + "(" +
                           type_name(c, r) + " a) {\n  return " + type_name(c, r) + "(-a.hi, -a.lo);\n}\n");
  return name;
}

std::string times_vector(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::times_vector(ctx, c, r);
  std::string name = "df_mul_" + suffix(c, r) + "_" + dvec(c).substr(3);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_dot", c);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise\n"
                     "// AccurateDWPlusDW). Bound: " + n(dot_constant(c)) +
                     "u^2 * sum_j |m[j][i] v[j]| per component (absolute).\n" + dvec(r) + " " + name + "(" +
                     type_name(c, r) + " m, " + dvec(c) + " v) {\n";
  auto row = [&](const std::string& i) {
    std::string hi, lo;
    for (int j = 0; j < c; ++j) {
      hi += (j ? ", " : "") + std::string("m.hi[") + n(j) + "][" + i + "]";
      lo += (j ? ", " : "") + std::string("m.lo[") + n(j) + "][" + i + "]";
    }
    return dvec(c) + "(" + vec(c) + "(" + hi + "), " + vec(c) + "(" + lo + "))";
  };
  if (loop_products(ctx) && r > 1) {
    body += dot_loop(r, dvec(r), row("idx"), "v");
  } else {
    for (int i = 0; i < r; ++i) body += "  df_double p" + n(i) + " = df_dot(" + row(n(i)) + ", v);\n";
    body += "  return " + from_scalars("p", r) + ";\n}\n";
  }
  ctx.add_helper(name, body);
  return name;
}

std::string vector_times(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::vector_times(ctx, c, r);
  std::string name = "df_mul_" + dvec(r).substr(3) + "_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_dot", r);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": (v * m)[j] = df_dot(v, column j of m). Bound: " + n(dot_constant(r)) +
                     "u^2 * sum_i |v[i] m[j][i]| per component (absolute).\n" + dvec(c) + " " + name + "(" + dvec(r) +
                     " v, " + type_name(c, r) + " m) {\n";
  if (loop_products(ctx) && c > 1) {
    body += dot_loop(c, dvec(c), "v", col("m", "idx", r));
  } else {
    for (int j = 0; j < c; ++j) body += "  df_double p" + n(j) + " = df_dot(v, " + col("m", j, r) + ");\n";
    body += "  return " + from_scalars("p", c) + ";\n}\n";
  }
  ctx.add_helper(name, body);
  return name;
}

std::string times_matrix(Context& ctx, int inner, int r, int c) {
  if (exact_mode(ctx)) return exact::times_matrix(ctx, inner, r, c);
  std::string name = "df_mul_" + suffix(inner, r) + "_" + suffix(c, inner);
  if (ctx.helpers.count(name)) return name;
  std::string mv = times_vector(ctx, inner, r);
  ctx.use_matrix(c, inner);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": column j of a * b is a * (column j of b) (" + mv + "). Bound: " +
                     n(dot_constant(inner)) + "u^2 * sum_k |a[k][i] b[j][k]| per element (absolute).\n" +
                     type_name(c, r) + " " + name + "(" + type_name(inner, r) + " a, " + type_name(c, inner) + " b) {\n";
  if (loop_products(ctx)) {
    body += "  " + type_name(c, r) + " m;\n" + loop_down("idx", c, "  ") + "    " + dvec(r) + " cj = " + mv + "(a, " +
            col("b", "idx", inner) + ");\n" + store_column("m", "idx", "cj", "    ") + "  }\n  return m;\n}\n";
  } else {
    for (int j = 0; j < c; ++j) body += "  " + dvec(r) + " c" + n(j) + " = " + mv + "(a, " + col("b", j, inner) + ");\n";
    body += "  return " + from_columns("c", c, r) + ";\n}\n";
  }
  ctx.add_helper(name, body);
  return name;
}

std::string outer_product(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::outer_product(ctx, c, r);
  std::string name = "df_outer_product_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_mul", r);
  ctx.use_width(c);
  ctx.use_matrix(c, r);
  std::string body = "// " + name + ": column j is a * b[j] (df_mul, DWTimesDW1). Bound: 7u^2 per element.\n" +
                     type_name(c, r) + " " + name + "(" + dvec(r) + " a, " + dvec(c) + " b) {\n";
  for (int j = 0; j < c; ++j) {
    std::string h = c == 1 ? "b.hi" : std::string("b.hi.") + letter(j), l = c == 1 ? "b.lo" : std::string("b.lo.") + letter(j);
    body += "  " + dvec(r) + " c" + n(j) + " = df_mul(a, " + dvec(r) + "(" + vec(r) + "(" + h + "), " + vec(r) + "(" + l +
            ")));\n";
  }
  body += "  return " + from_columns("c", c, r) + ";\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string transpose(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::transpose(ctx, c, r);
  std::string name = "df_transpose_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.use_matrix(r, c);
  // Spelled out element by element: ES 1.00 has no transpose().
  auto words = [&](const std::string& w) {
    std::string s = float_type_name(r, c) + "(";
    for (int i = 0; i < r; ++i)
      for (int j = 0; j < c; ++j) s += std::string(i || j ? ", " : "") + "m." + w + "[" + n(j) + "][" + n(i) + "]";
    return s + ")";
  };
  ctx.add_helper(name, "// " + name + ": exact (words moved).\n" + type_name(r, c) + " " + name + "(" + type_name(c, r) +
                           " m) {\n  return " + type_name(r, c) + "(" + words("hi") + ", " + words("lo") + ");\n}\n");
  return name;
}

namespace {

// Emits statements computing determinants of square submatrices of `m` by cofactor expansion
// along the submatrix's first row, sharing minors; returns the temporary holding one.
class DeterminantWriter {
 public:
  explicit DeterminantWriter(std::string& body) : body_(body) {}

  std::string det(const std::vector<int>& rows, const std::vector<int>& cols) {
    if (rows.size() == 1) return "a" + n(rows[0]) + n(cols[0]);
    std::string key;
    for (int r : rows) key += n(r);
    key += "_";
    for (int c : cols) key += n(c);
    if (auto it = done_.find(key); it != done_.end()) return it->second;
    std::vector<int> rest(rows.begin() + 1, rows.end());
    std::string sum;
    for (size_t k = 0; k < cols.size(); ++k) {
      std::vector<int> other;
      for (size_t q = 0; q < cols.size(); ++q)
        if (q != k) other.push_back(cols[q]);
      std::string minor = det(rest, other);
      std::string term = "t" + n(counter_++);
      body_ += "  df_double " + term + " = df_mul(a" + n(rows[0]) + n(cols[k]) + ", " + minor + ");\n";
      if (sum.empty()) {
        sum = term;
      } else {
        std::string s = "t" + n(counter_++);
        body_ += "  df_double " + s + " = " + (k % 2 ? "df_sub(" : "df_add(") + sum + ", " + term + ");\n";
        sum = s;
      }
    }
    std::string name = "d" + key;
    body_ += "  df_double " + name + " = " + sum + ";\n";
    done_[key] = name;
    return name;
  }

 private:
  std::string& body_;
  std::map<std::string, std::string> done_;
  int counter_ = 0;
};

// aRC = element (row R, column C) of m, as df_double temporaries.
std::string load_elements(int size) {
  std::string s;
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) s += "  df_double a" + n(r) + n(c) + " = " + elem("m", c, r) + ";\n";
  return s;
}

std::vector<int> iota(int size) {
  std::vector<int> v;
  for (int i = 0; i < size; ++i) v.push_back(i);
  return v;
}

// First-order absolute bound of the cofactor expansion, in u^2 * per(|A|): a 1x1 minor is exact;
// an n x n determinant multiplies each (n-1)-minor (7u^2) and adds n terms (n - 1 additions, 3u^2
// each, every partial sum below per(|A|)).
int det_constant(int size) { return size == 1 ? 0 : det_constant(size - 1) + 7 + 3 * (size - 1); }

}  // namespace

std::string determinant(Context& ctx, int size) {
  if (exact_mode(ctx)) return exact::determinant(ctx, size);
  std::string name = "df_determinant_" + suffix(size, size);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_mul", 1);
  ctx.use_rule("df_add", 1);
  ctx.use_rule("df_sub", 1);
  ctx.use_matrix(size, size);
  std::string body = "// " + name + ": cofactor expansion along the first row, minors shared (df_mul, df_add,\n"
                     "// df_sub). Bound: " + n(det_constant(size)) + "u^2 * per(|m|) (absolute, first order).\n"
                     "df_double " + name + "(" + type_name(size, size) + " m) {\n" + load_elements(size);
  DeterminantWriter writer(body);
  std::string d = writer.det(iota(size), iota(size));
  body += "  return " + d + ";\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string inverse(Context& ctx, int size) {
  if (exact_mode(ctx)) return exact::inverse(ctx, size);
  std::string name = "df_inverse_" + suffix(size, size);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_mul", 1);
  ctx.use_rule("df_add", 1);
  ctx.use_rule("df_sub", 1);
  ctx.use_rule("df_neg", 1);
  ctx.use_rule("df_div", size);
  ctx.use_matrix(size, size);
  std::string body = "// " + name + ": adjugate / determinant. Cofactors by expansion (" +
                     n(det_constant(size - 1)) + "u^2 * per(|minor|) absolute),\n// the determinant from the first "
                     "row's cofactors (" + n(det_constant(size)) + "u^2 * per(|m|)), then df_div (15u^2).\n"
                     "// Relative error of inverse[j][i] <= (" + n(det_constant(size - 1)) + " per(|minor_ij|)/|cof_ij| + " +
                     n(det_constant(size)) + " per(|m|)/|det| + 15)u^2: it grows with the condition of m.\n" +
                     type_name(size, size) + " " + name + "(" + type_name(size, size) + " m) {\n" + load_elements(size);
  DeterminantWriter writer(body);
  // cof[r][c] = (-1)^(r+c) det(m without row r and column c).
  std::vector<std::vector<std::string>> cof(size, std::vector<std::string>(size));
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      std::vector<int> rows, cols;
      for (int i = 0; i < size; ++i) {
        if (i != r) rows.push_back(i);
        if (i != c) cols.push_back(i);
      }
      std::string minor = writer.det(rows, cols);
      std::string name_rc = "k" + n(r) + n(c);
      body += "  df_double " + name_rc + " = " + ((r + c) % 2 ? "df_neg(" + minor + ")" : minor) + ";\n";
      cof[r][c] = name_rc;
    }
  std::string det;
  for (int c = 0; c < size; ++c) {
    std::string term = "e" + n(c);
    body += "  df_double " + term + " = df_mul(a0" + n(c) + ", " + cof[0][c] + ");\n";
    if (det.empty()) {
      det = term;
    } else {
      body += "  df_double s" + n(c) + " = df_add(" + det + ", " + term + ");\n";
      det = "s" + n(c);
    }
  }
  std::string splat = dvec(size) + "(" + vec(size) + "(" + det + ".hi), " + vec(size) + "(" + det + ".lo))";
  // inverse[j][i] (column j, row i) = cof[j][i] / det.
  for (int j = 0; j < size; ++j) {
    std::string hi, lo;
    for (int i = 0; i < size; ++i) {
      hi += (i ? ", " : "") + cof[j][i] + ".hi";
      lo += (i ? ", " : "") + cof[j][i] + ".lo";
    }
    body += "  " + dvec(size) + " c" + n(j) + " = df_div(" + dvec(size) + "(" + vec(size) + "(" + hi + "), " + vec(size) +
            "(" + lo + ")), " + splat + ");\n";
  }
  body += "  return " + from_columns("c", size, size) + ";\n}\n";
  ctx.add_helper(name, body);
  return name;
}

std::string equal(Context& ctx, int c, int r, bool negated) {
  if (exact_mode(ctx)) return exact::equal(ctx, c, r, negated);
  std::string name = std::string(negated ? "df_not_equal_" : "df_equal_") + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  std::string test = negated ? "a.hi != b.hi || a.lo != b.lo" : "a.hi == b.hi && a.lo == b.lo";
  ctx.add_helper(name, "// " + name + ": exact (word-wise: double-word numbers are unique, JMP 2017 Def. 1.4).\nbool " +
                           name + "(" + type_name(c, r) + " a, " + type_name(c, r) + " b) {\n  return " + test + ";\n}\n");
  return name;
}

std::string column(Context& ctx, int c, int r) {
  std::string name = "df_column_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.use_width(r);
  ctx.add_helper(name, dvec(r) + " " + name + "(" + type_name(c, r) + " m, int j) {\n  return " + dvec(r) +
                           "(m.hi[j], m.lo[j]);\n}\n");
  return name;
}

std::string assign_column(Context& ctx, int c, int r) {
  std::string name = "df_assign_column_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.use_width(r);
  ctx.add_helper(name, dvec(r) + " " + name + "(inout " + type_name(c, r) + " m, int j, " + dvec(r) +
                           " v) {\n  m.hi[j] = v.hi;\n  m.lo[j] = v.lo;\n  return v;\n}\n");
  return name;
}

std::string assign_element(Context& ctx, int c, int r) {
  std::string name = "df_assign_element_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  ctx.add_helper(name, "df_double " + name + "(inout " + type_name(c, r) +
                           " m, int j, int i, df_double x) {\n  m.hi[j][i] = x.hi;\n  m.lo[j][i] = x.lo;\n  return x;\n}\n");
  return name;
}

std::string from_components(Context& ctx, int c, int r, const std::vector<int>& widths) {
  if (exact_mode(ctx)) return exact::from_components(ctx, c, r, widths);
  std::string name = "df_make_" + suffix(c, r);
  for (int w : widths) name += "_" + n(w);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  std::string params, hi, lo;
  for (size_t i = 0; i < widths.size(); ++i) {
    ctx.use_width(widths[i]);
    std::string p = "a" + n(static_cast<int>(i));
    params += (i ? ", " : "") + dvec(widths[i]) + " " + p;
    hi += (i ? ", " : "") + p + ".hi";
    lo += (i ? ", " : "") + p + ".lo";
  }
  std::string m = float_type_name(c, r);
  ctx.add_helper(name, type_name(c, r) + " " + name + "(" + params + ") {\n  return " + type_name(c, r) + "(" + m + "(" + hi +
                           "), " + m + "(" + lo + "));\n}\n");
  return name;
}

std::string diagonal(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::diagonal(ctx, c, r);
  std::string name = "df_diagonal_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(c, r);
  std::string m = float_type_name(c, r);
  ctx.add_helper(name, type_name(c, r) + " " + name + "(df_double s) {\n  return " + type_name(c, r) + "(" + m +
                           "(s.hi), " + m + "(s.lo));\n}\n");
  return name;
}

std::string resize(Context& ctx, int fc, int fr, int c, int r) {
  if (exact_mode(ctx)) return exact::resize(ctx, fc, fr, c, r);
  std::string name = "df_resize_" + suffix(fc, fr) + "_" + suffix(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_matrix(fc, fr);
  ctx.use_matrix(c, r);
  std::string m = float_type_name(c, r), f = float_type_name(fc, fr);
  // GLSL fills the new diagonal with 1: right for hi, and m(f(0.0)) removes it from lo.
  ctx.add_helper(name, type_name(c, r) + " " + name + "(" + type_name(fc, fr) + " a) {\n  return " + type_name(c, r) + "(" +
                           m + "(a.hi), " + m + "(a.lo) - " + m + "(" + f + "(0.0)));\n}\n");
  return name;
}

std::string to_float(Context& ctx, int c, int r) {
  if (exact_mode(ctx)) return exact::to_float(ctx, c, r);
  std::string name = "df_to_" + float_type_name(c, r);
  if (ctx.helpers.count(name)) return name;
  ctx.use_rule("df_to_float", r);
  ctx.use_matrix(c, r);
  std::string cols;
  for (int j = 0; j < c; ++j) cols += (j ? ", " : "") + std::string("df_to_float(") + col("a", j, r) + ")";
  ctx.add_helper(name, "// " + name + ": each element rounded to float (df_to_float).\n" + float_type_name(c, r) + " " +
                           name + "(" + type_name(c, r) + " a) {\n  return " + float_type_name(c, r) + "(" + cols + ");\n}\n");
  return name;
}

}  // namespace doublet::passes::matrix
