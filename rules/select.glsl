// rules/select.glsl -- branch-free selection between float-float values, the one way rules choose
// between results (docs/rules-format.md, "No branches in a rule").
//
// Sources:
//   [GLSL]  The OpenGL Shading Language 4.60, 2019, section 8.3 (mix with a boolean selector picks
//           each component from one operand, with no arithmetic on either).
//   [ESSL]  The OpenGL ES Shading Language 3.00, 2016, section 8.3 (the same mix, from ES 3.00 on).

// df_select: c ? a : b per component, without a branch (mix on a boolean selector, a
// ternary on ES 1.00). Every rule with a data-dependent choice between pairs goes through it: an
// early return or a short-circuit inside a rule that is inlined into a loop body multiplies the
// control flow the browser's shader compilers have to handle (docs/performance.md, "Compile time in
// the browser").
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBType)
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
// @per-component
$DF df_select($B c, $DF a, $DF b) {
  $PRECISE $F h = $SAFE($SEL(c, a.hi, b.hi));
  $PRECISE $F l = $SAFE($SEL(c, a.lo, b.lo));
  return $DF(h, l);
}
