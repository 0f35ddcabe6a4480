// rules/minmax.glsl -- abs, min, max of float-float values (exact: no rounding happens).
//
// Sources:
//   [JMP]  M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017, Definition 1.4:
//          in a double-word number the sign of the value is the sign of hi (lo = 0 when hi = 0).
//   [GLSL] The OpenGL ES Shading Language 3.20, section 8.3: min(x, y) = y < x ? y : x,
//          max(x, y) = x < y ? y : x (component-wise); results with NaN are undefined.

// df_abs: |a|. Both words are multiplied by sign(hi) (exactly -1, 0 or +1).
// Algorithm: sign of hi applied to both words
// Source: JMP 2017, Definition 1.4 (sign of a double-word number is the sign of hi)
// Bound: exact
// Flops: 3
// @widths 1 2 3 4
$DF df_abs($DF a) {
  $PRECISE $F s = $G(sign(a.hi));
  $PRECISE $F h = $G(abs(a.hi));
  $PRECISE $F l = $G(a.lo * s);
  return $DF(h, l);
}

// df_min: component-wise min(a, b) = b < a ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (min); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
$DF df_min($DF a, $DF b) {
  bool take = df_lt(b, a);
  $DF r = df_select(take, b, a);
  return r;
}

// df_max: component-wise max(a, b) = a < b ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (max); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
$DF df_max($DF a, $DF b) {
  bool take = df_lt(a, b);
  $DF r = df_select(take, b, a);
  return r;
}
