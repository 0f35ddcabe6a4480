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
// Guarding: every float operation is a $PRECISE temporary wrapped in $G(...) or, where no later
// step cancels against it, $SAFE(...) (no Uniform guard subtraction), see
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
  $PRECISE $F ab = $SAFE(s - bb);
  $PRECISE $F da = $SAFE(a - ab);
  $PRECISE $F db = $SAFE(b - bb);
  $PRECISE $F e = $SAFE(da + db);
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
  $PRECISE $F e = $SAFE(b - z);
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
// df_two_prod scales its operands by powers of two so that it never splits such a value.
// @widths 1 2 3 4
$DF df_split($F a) {
  $PRECISE $F g = $G(a * 4097.0);
  $PRECISE $F d = $G(a - g);
  $PRECISE $F hi = $SAFE(g + d);
  $PRECISE $F lo = $SAFE(a - hi);
  return $DF(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
// @widths 1 2 3 4
$F df_mul12_error($DF sa, $DF sb, $F p) {
  $PRECISE $F hh = $SAFE(sa.hi * sb.hi);
  $PRECISE $F hl = $SAFE(sa.hi * sb.lo);
  $PRECISE $F lh = $SAFE(sa.lo * sb.hi);
  $PRECISE $F ll = $SAFE(sa.lo * sb.lo);
  $PRECISE $F t1 = $SAFE(hh - p);
  $PRECISE $F t2 = $SAFE(t1 + hl);
  $PRECISE $F t3 = $SAFE(t2 + lh);
  $PRECISE $F e = $SAFE(t3 + ll);
  return e;
}

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves of power-of-two scaled operands
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10; Boldo, "Pitfalls of a full floating-point proof", IJCAR 2006 (overflow of the split)
// Bound: exact
// Flops: 21 (plus 2 comparisons and 2 selects)
// Steps: p = RN(a*b); as = a*k, bs = b/k with k = 2^-13 when |a| > 1e34, 2^13 when |b| > 1e34,
//        else 1 (exact: as*bs == a*b); (ah,al) = split(as); (bh,bl) = split(bs);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: when a*b is finite and one operand exceeds 1e34 the other is below 3.5e4, so both
// scaled operands stay below FLT_MAX/4097 and nothing underflows; the split never overflows.
// Exact when |a*b| <= FLT_MAX (minus an ulp); e underflows below ~2^-102. When a*b overflows
// (or an operand is Inf or NaN) p is the IEEE result and e is not finite: the callers'
// df_finish then returns (p, 0). The scale factors are selects, not a branch: a branch here
// let lavapipe's vertex stage delete the error terms under the Uniform guard (stages_test).
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (docs/numerics.md).
// @widths 1 2 3 4
// @per-component
$DF df_two_prod($F a, $F b) {
  $PRECISE $F p = $G(a * b);
  $PRECISE $F aa = $SAFE(abs(a));
  $PRECISE $F ab = $SAFE(abs(b));
  bool big_a = aa > 1.0e34;
  bool big_b = ab > 1.0e34;
  $PRECISE $F ka = $SAFE($SEL(big_a, 1.220703125e-4, $SEL(big_b, 8192.0, 1.0)));
  $PRECISE $F kb = $SAFE($SEL(big_a, 8192.0, $SEL(big_b, 1.220703125e-4, 1.0)));
  $PRECISE $F as = $SAFE(a * ka);
  $PRECISE $F bs = $SAFE(b * kb);
  $DF sa = df_split(as);
  $DF sb = df_split(bs);
  $PRECISE $F e = $SAFE(df_mul12_error(sa, sb, p));
  return $DF(p, e);
}

// df_split (bit-casts): a == hi + lo exactly, hi and lo each fit in 12 significant bits, as
// Veltkamp's split gives them, from a's bit pattern instead of the constant 4097 (3 flops fewer,
// no range limit, nothing an algebraic optimizer can fold: hi is not a float expression of a).
// Algorithm: binary32 pattern rounded to 12 significant bits, (bits + 2^11) & ~(2^12 - 1) (ties
// away from zero; a carry into the exponent field is the rounding up to the next binade), except
// where that would carry past FLT_MAX: there the pattern is truncated; lo = a - hi
// Source: Dekker 1971, section 5 (mul12 is exact for halves of at most 12 bits); IEEE 754-2008
// binary32 encoding; HFPA (2018) section 4.4.2 (splitting)
// Bound: exact
// Flops: 1 (plus 4 integer operations)
// Steps: hi = uintBitsToFloat(min(bits + 0x800u, bits | 0x7F7FF800u) & 0xFFFFF000u), bits the
//        pattern of a; lo = RN(a - hi), exact (hi is a on a coarser grid: |lo| <= 2^11 ulp(a)).
//        The min: with a's magnitude m, bits | 0x7F7FF800 exceeds bits + 0x800 while m <
//        0x7F7FF000, equals it up to 0x7F7FF7FF, and is the pattern itself from 0x7F7FF800 (all of
//        0x7F7FF800's bits are set there), so only those magnitudes are truncated; the sign bit is
//        the same on both sides. One unsigned min: float min/max or clamp cost about 20% of a loop
//        on SwiftShader (docs/performance.md).
// Range: no limit. From |a| = 0x7F7FF800 (3.4024e38) hi is a truncated to 12 bits and lo has 12
// bits (0 <= |lo| < 2^12 ulp(a)); mul12 stays exact there (df_two_prod below). +-Inf: hi = +-Inf,
// lo = NaN; NaN: lo is NaN (the callers' df_finish then returns the plain product).
// @widths 1 2 3 4
// @min-es 300
// @variant bit-casts
$DF df_split($F a) {
  $U bits = floatBitsToUint(a);
  $PRECISE $F hi = $SAFE(uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  $PRECISE $F lo = $SAFE(a - hi);
  return $DF(hi, lo);
}

// df_two_prod (bit-casts): p + e == a * b exactly, with p = RN(a * b): Dekker's product on the
// halves of the split by bits, which needs no scaling of the operands (no range limit).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on halves split by their bit patterns
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 11 (plus 8 integer operations)
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b) (df_split, bit-casts);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
// Exactness, with a = A*2^i, b = B*2^j (A, B 24-bit integers), ah = AH*2^(i+12), al = AL*2^i and
// likewise for b, in units of 2^(i+j): t1 = AB - p - AL*BH*2^12 - AH*BL*2^12 - AL*BL is a multiple of
// 2^23 below 2^37; t2 = t1 + AH*BL*2^12 a multiple of 2^12 below 2^36; t3 = AB - p - AL*BL an integer
// of at most 2^24; e = AB - p. Each fits in 24 bits when |AL|, |BL| <= 2^11 (rounded halves), and
// still when one of them is below 2^12 (the truncated split of |a| >= 0x7F7FF800: a finite product
// then has |b| < 2, whose split is rounded). So the pairs are those of the Veltkamp version.
// Range: exact when |a*b| <= FLT_MAX; e underflows below ~2^-102. When a*b overflows, or an
// operand is Inf or NaN, p is the IEEE result and the callers' df_finish returns (p, 0).
// @widths 1 2 3 4
// @min-es 300
// @variant bit-casts
$DF df_two_prod($F a, $F b) {
  $PRECISE $F p = $G(a * b);
  $DF sa = df_split(a);
  $DF sb = df_split(b);
  $PRECISE $F e = $SAFE(df_mul12_error(sa, sb, p));
  return $DF(p, e);
}
