// rules/fast.glsl -- the cheaper float-float arithmetic of mode df64-fast (docs/modes.md):
// df_add_fast, df_sub_fast, df_mul_fast, df_div_fast. Inputs and outputs are double-word
// numbers (hi = RN(hi + lo)), as in rules/arith.glsl, so fast and accurate code mix freely.
//
// Sources:
//   [JMP]  M. Joldes, J.-M. Muller, V. Popescu, "Tight and rigorous error bounds for basic
//          building blocks of double-word arithmetic", ACM TOMS 44(2), 2017.
//          Algorithm numbers below are the paper's.
//   [YLHLQL] Y. Yang, X. Lyu, S. He, X. Lu, J. Qi, Z. Li, "On the robustness of double-word
//          addition algorithms", arXiv:2404.05948, 2024 (the sloppy addition's relative error
//          exceeds 3u^2 only when the high words cancel in the Sterbenz sense).
//   [Dekker] T. J. Dekker, "A floating-point technique for extending the available precision",
//          Numerische Mathematik 18, 1971 (add2, mul2, div2).
// Notation: u = 2^-24; bounds are on the relative error and assume IEEE round-to-nearest
// +,-,*,/ and no overflow/underflow in any intermediate. No FMA (see rules/arith.glsl).
// Unlike rules/arith.glsl these rules do not fix up special values (no df_finish): Inf and NaN
// operands, and results that overflow, may give NaN where IEEE gives Inf.

// df_add_fast: a + b without the second TwoSum of the low words.
// Algorithm: SloppyDWPlusDW (JMP Algorithm 5; Dekker's add2)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Section 3; Yang et al., arXiv:2404.05948, 2024
// Bound: 3u^2 when a and b have the same sign; unbounded relative error for opposite signs (cancellation of the high words)
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,bh); v = RN(al+bl); w = RN(sl+v); (zh,zl) = Fast2Sum(sh,w).
// Under cancellation (ah ~ -bh) the rounding of al+bl is no longer small next to the result:
// the error stays below about u^2 (|a| + |b|) in absolute terms, which can be all of a
// small result. Use df64 where differences of nearly equal values matter.
// @widths 1 2 3 4
$DF df_add_fast($DF a, $DF b) {
  $DF s = df_two_sum(a.hi, b.hi);
  $PRECISE $F v = $SAFE(a.lo + b.lo);
  $PRECISE $F w = $SAFE(s.lo + v);
  $DF z = df_fast_two_sum(s.hi, w);
  return z;
}

// df_sub_fast: a - b = a + (-b) by the sloppy addition; the negation of b is exact.
// Algorithm: SloppyDWPlusDW on (a, -b) (JMP Algorithm 5)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Section 3; Yang et al., arXiv:2404.05948, 2024
// Bound: 3u^2 when a and b have opposite signs; unbounded relative error for equal signs (cancellation of the high words)
// Flops: 12
// @widths 1 2 3 4
$DF df_sub_fast($DF a, $DF b) {
  $PRECISE $F nh = $SAFE(-b.hi);
  $DF s = df_two_sum(a.hi, nh);
  $PRECISE $F v = $SAFE(a.lo - b.lo);
  $PRECISE $F w = $SAFE(s.lo + v);
  $DF z = df_fast_two_sum(s.hi, w);
  return z;
}

// df_mul_fast: a * b. Without FMA no product cheaper than DWTimesDW1 has a proved bound (its
// one Fast2Sum is what keeps the result a double-word number for comparisons and
// conversions), so the arithmetic is df_mul's; what df64-fast drops is df_mul's special-value
// fix-up (df_finish): an overflowing product or an Inf/NaN operand gives NaN instead of the
// IEEE result.
// Algorithm: DWTimesDW1 (JMP Algorithm 10; Dekker's mul2) with Dekker's TwoProd, no special-value fix-up
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2); Dekker 1971 (mul2)
// Bound: 7u^2
// Flops: 28 (with df_two_prod's 21 of ES 1.00; 18 with its split by bits, rules/core.glsl)
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
// @widths 1 2 3 4
$DF df_mul_fast($DF a, $DF b) {
  $DF c = df_two_prod(a.hi, b.hi);
  $PRECISE $F tl = $SAFE(a.hi * b.lo);
  $PRECISE $F th = $SAFE(a.lo * b.hi);
  $PRECISE $F cl2 = $SAFE(th + tl);
  $PRECISE $F cl3 = $SAFE(c.lo + cl2);
  $DF z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_div_fast: a / b as df_div, but the remainder's product b*th is not renormalised: the
// two Fast2Sums of DWTimesFP1 are dropped (6 flops).
// Algorithm: DWDivDW2 (JMP Algorithm 17) with the product (bh + bl) * th left as TwoProd(bh,th) + RN(bl*th), unrenormalised
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Algorithm 17 and Theorem 7.1 (15u^2 + 56u^3 for the renormalised form); Dekker 1971 (div2)
// Bound: about 15u^2 + 2u^2 (estimate, not proved: the dropped renormalisation adds one rounding of size u^2 to the remainder)
// Flops: 31 (with df_two_prod's 21 of ES 1.00; 21 with its split by bits, rules/core.glsl)
// Steps: th = RN(ah/bh); (ch,cl1) = TwoProd(bh,th); cl2 = RN(bl*th); rl = RN(cl1+cl2);
//        pih = RN(ah-ch) (exact, Sterbenz: ch is within a factor 2 of ah); dl = RN(al-rl);
//        d = RN(pih+dl); tl = RN(d/bh); (zh,zl) = Fast2Sum(th,tl).
// b == 0 gives NaN, as df_div. Range: |th| and |bh| <= 8.3e34 (split).
// @widths 1 2 3 4
$DF df_div_fast($DF a, $DF b) {
  $PRECISE $F th = $G(a.hi / b.hi);
  $DF c = df_two_prod(b.hi, th);
  $PRECISE $F cl2 = $SAFE(b.lo * th);
  $PRECISE $F rl = $SAFE(c.lo + cl2);
  $PRECISE $F pih = $SAFE(a.hi - c.hi);
  $PRECISE $F dl = $SAFE(a.lo - rl);
  $PRECISE $F d = $SAFE(pih + dl);
  $PRECISE $F tl = $SAFE(d / b.hi);
  $DF z = df_fast_two_sum(th, tl);
  return z;
}
