// rules/compare.glsl -- comparisons of float-float values.
// For double-word numbers (hi = RN(hi + lo)) the pair is unique for a value, and the order of
// values is the lexicographic order of (hi, lo): if hi_a < hi_b then a < b, because
// |lo| <= ulp(hi)/2 cannot bridge the gap between two distinct floats hi. So no arithmetic is
// needed and the results are exact. NaN in hi makes every ordered comparison false and
// df_not_equal true, like IEEE doubles. -0 == +0.
//
// Sources:
//   [JMP]  M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017, Definition 1.4
//          (double-word number) -- uniqueness of the representation.
//   [Knuth] D. E. Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 (comparing unevaluated sums).

// df_lt: a < b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
// @widths 1
bool df_lt($DF a, $DF b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo < b.lo))));
}

// df_le: a <= b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
// @widths 1
bool df_le($DF a, $DF b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo <= b.lo))));
}

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
// @widths 1
bool df_gt($DF a, $DF b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo > b.lo))));
}

// df_ge: a >= b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
// @widths 1
bool df_ge($DF a, $DF b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo >= b.lo))));
}

// df_equal: a == b for the whole value (all components), like GLSL == on dvecN.
// Algorithm: word-wise equality (GLSL vector == is already whole-vector)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 vector comparisons)
// @widths 1 2 3 4
bool df_equal($DF a, $DF b) {
  return all(bvec2(a.hi == b.hi, a.lo == b.lo));
}

// df_not_equal: a != b for the whole value (any component differs), like GLSL != on dvecN.
// Algorithm: word-wise inequality
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 vector comparisons)
// @widths 1 2 3 4
bool df_not_equal($DF a, $DF b) {
  return any(bvec2(a.hi != b.hi, a.lo != b.lo));
}

// df_less_than: lessThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
// @uses df_lt:1
$B df_less_than($DF a, $DF b) {
  return df_lt(a, b);
}

// df_less_than_equal: lessThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
// @uses df_le:1
$B df_less_than_equal($DF a, $DF b) {
  return df_le(a, b);
}

// df_greater_than: greaterThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
// @uses df_gt:1
$B df_greater_than($DF a, $DF b) {
  return df_gt(a, b);
}

// df_greater_than_equal: greaterThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// @widths 1 2 3 4
// @per-component
// @uses df_ge:1
$B df_greater_than_equal($DF a, $DF b) {
  return df_ge(a, b);
}

// df_equal_components: equal(a, b) per component (word-wise).
// Algorithm: word-wise equality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
// @widths 1 2 3 4
// @per-component
$B df_equal_components($DF a, $DF b) {
  return all(bvec2(a.hi == b.hi, a.lo == b.lo));
}

// df_not_equal_components: notEqual(a, b) per component (word-wise).
// Algorithm: word-wise inequality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
// @widths 1 2 3 4
// @per-component
$B df_not_equal_components($DF a, $DF b) {
  return any(bvec2(a.hi != b.hi, a.lo != b.lo));
}
