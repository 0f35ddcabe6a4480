// rules/core.glsl -- error-free transformations (EFTs) on float: the exact building blocks of
// float-float ("double-word") arithmetic. Each returns an unevaluated pair packed in $DF:
// .hi is the rounded result, .lo the exact rounding error, so hi + lo is the exact answer.
//
// Sources:
//   [Dekker]  T. J. Dekker, "A floating-point technique for extending the available precision",
//             Numerische Mathematik 18(3):224-242, 1971 (Fast2Sum, Veltkamp split, mul12).
//   [Knuth]   D. E. Knuth, The Art of Computer Programming, vol. 2: Seminumerical Algorithms,
//             3rd ed., 1998, section 4.2.2, Theorem B (TwoSum, after O. Moller 1965).
//   [HFPA]    J.-M. Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., Birkhauser,
//             2018, chapter 4 (Algorithms 4.3, 4.4, 4.9, 4.10).
// Notation: u = 2^-24 (binary32 unit roundoff); RN(x) = x rounded to nearest-even float.
// "Exact" assumes no overflow and no underflow of the error term (|result| > ~2^-102;
// vertex and fragment stages flush subnormals on Mesa, compute keeps them).
// Guarding: every float operation is a $PRECISE temporary wrapped in $G(...), see
// docs/rules-format.md. Without it Mesa's inexact algebra folds the error terms to 0.
// FMA is never used: llvmpipe does not fuse fma(), so TwoProd is Dekker's (Veltkamp split).

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
// @widths 1 2 3 4
$DF df_two_sum($F a, $F b) {
  $PRECISE $F s = $G(a + b);
  $PRECISE $F bb = $G(s - a);
  $PRECISE $F ab = $G(s - bb);
  $PRECISE $F da = $G(a - ab);
  $PRECISE $F db = $G(b - bb);
  $PRECISE $F e = $G(da + db);
  return $DF(s, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
// @widths 1 2 3 4
$DF df_fast_two_sum($F a, $F b) {
  $PRECISE $F s = $G(a + b);
  $PRECISE $F z = $G(s - a);
  $PRECISE $F e = $G(b - z);
  return $DF(s, e);
}

// df_split: a == hi + lo exactly, hi and lo each fit in 12 significant bits, so any product
// of two halves is exact in float. Returned as $DF(hi, lo) (not a normalized double-word).
// Algorithm: Veltkamp splitting, C = 2^12 + 1 = 4097 (s = ceil(24/2) = 12)
// Source: Dekker 1971, section 5 (attributed to Veltkamp); HFPA (2018) Algorithm 4.9
// Bound: exact
// Flops: 4
// Steps: g = RN(C*a); d = RN(a-g); hi = RN(g+d); lo = RN(a-hi).
// Range: C*a overflows when |a| > FLT_MAX/4097 (about 8.3e34); the result is then NaN.
// @widths 1 2 3 4
$DF df_split($F a) {
  $PRECISE $F g = $G(a * 4097.0);
  $PRECISE $F d = $G(a - g);
  $PRECISE $F hi = $G(g + d);
  $PRECISE $F lo = $G(a - hi);
  return $DF(hi, lo);
}

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 17
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: needs |a|, |b| <= 8.3e34 (split) and |a*b| <= FLT_MAX; e underflows below ~2^-102.
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (NUMERICS.md).
// @widths 1 2 3 4
$DF df_two_prod($F a, $F b) {
  $PRECISE $F p = $G(a * b);
  $DF sa = df_split(a);
  $DF sb = df_split(b);
  $PRECISE $F hh = $G(sa.hi * sb.hi);
  $PRECISE $F hl = $G(sa.hi * sb.lo);
  $PRECISE $F lh = $G(sa.lo * sb.hi);
  $PRECISE $F ll = $G(sa.lo * sb.lo);
  $PRECISE $F t1 = $G(hh - p);
  $PRECISE $F t2 = $G(t1 + hl);
  $PRECISE $F t3 = $G(t2 + lh);
  $PRECISE $F e = $G(t3 + ll);
  return $DF(p, e);
}
