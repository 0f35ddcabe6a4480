// rules/arith.glsl -- float-float add, sub, mul, div, neg (and the mixed float-float/float
// forms df_add_f, df_mul_f). Inputs are double-word numbers: hi = RN(hi + lo). Every result
// is renormalized by a final Fast2Sum, so outputs are double-word numbers too.
//
// Sources:
//   [JMP]  M. Joldes, J.-M. Muller, V. Popescu, "Tight and rigorous error bounds for basic
//          building blocks of double-word arithmetic", ACM TOMS 44(2), 2017.
//          Algorithm numbers below are the paper's.
//   [MR]   J.-M. Muller, L. Rideau, "Formalization of double-word arithmetic, and comments on
//          'Tight and rigorous error bounds for basic building blocks of double-word
//          arithmetic'", ACM TOMS 48(1), article 9, 2022 (Coq proofs; DWTimesDW1 bound 5u^2).
//   [Dekker] T. J. Dekker, Numerische Mathematik 18, 1971 (the original add2/mul2/div2).
// Notation: u = 2^-24; bounds are on the relative error |z - x op y| / |x op y| and assume
// IEEE round-to-nearest +,-,*,/ and no overflow/underflow in any intermediate.
// No-FMA variants only (FMA is not fused on llvmpipe; ES < 3.20 has none).

// df_neg: -a, exact. Under the Uniform guard a zero result is +0 (x + 0 turns -0 into +0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
// @widths 1 2 3 4
$DF df_neg($DF a) {
  $PRECISE $F h = $G(-a.hi);
  $PRECISE $F l = $G(-a.lo);
  return $DF(h, l);
}

// df_add: a + b.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 20
// Steps: (sh,sl) = TwoSum(ah,bh); (th,tl) = TwoSum(al,bl); c = RN(sl+th);
//        (vh,vl) = Fast2Sum(sh,c); w = RN(tl+vl); (zh,zl) = Fast2Sum(vh,w).
// The bound holds for all signs (the "sloppy" 11-flop variant is unbounded under cancellation).
// @widths 1 2 3 4
$DF df_add($DF a, $DF b) {
  $DF s = df_two_sum(a.hi, b.hi);
  $DF t = df_two_sum(a.lo, b.lo);
  $PRECISE $F c = $G(s.lo + t.hi);
  $DF v = df_fast_two_sum(s.hi, c);
  $PRECISE $F w = $G(t.lo + v.lo);
  $DF z = df_fast_two_sum(v.hi, w);
  return z;
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 22
// @widths 1 2 3 4
$DF df_sub($DF a, $DF b) {
  $DF nb = df_neg(b);
  $DF z = df_add(a, nb);
  return z;
}

// df_add_f: a + b with b a plain float (b need not be a double-word).
// Algorithm: DWPlusFP (JMP Algorithm 4)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 10
// Steps: (sh,sl) = TwoSum(ah,b); v = RN(al+sl); (zh,zl) = Fast2Sum(sh,v).
// @widths 1 2 3 4
$DF df_add_f($DF a, $F b) {
  $DF s = df_two_sum(a.hi, b);
  $PRECISE $F v = $G(a.lo + s.lo);
  $DF z = df_fast_two_sum(s.hi, v);
  return z;
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split, C = 4097)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 24
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: |ah|, |bh| <= 8.3e34 (the split multiplies by 4097); beyond that the result is NaN.
// @widths 1 2 3 4
$DF df_mul($DF a, $DF b) {
  $DF c = df_two_prod(a.hi, b.hi);
  $PRECISE $F tl = $G(a.hi * b.lo);
  $PRECISE $F th = $G(a.lo * b.hi);
  $PRECISE $F cl2 = $G(th + tl);
  $PRECISE $F cl3 = $G(c.lo + cl2);
  $DF z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_mul_f: a * b with b a plain float.
// Algorithm: DWTimesFP1 (JMP Algorithm 7) with Dekker's TwoProd
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 4.1
// Bound: 1.5u^2 + 4u^3
// Flops: 25
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); (th,tl1) = Fast2Sum(ch,cl2);
//        tl2 = RN(tl1+cl1); (zh,zl) = Fast2Sum(th,tl2).
// Range: |ah|, |b| <= 8.3e34 (split).
// @widths 1 2 3 4
$DF df_mul_f($DF a, $F b) {
  $DF c = df_two_prod(a.hi, b);
  $PRECISE $F cl2 = $G(a.lo * b);
  $DF t = df_fast_two_sum(c.hi, cl2);
  $PRECISE $F tl2 = $G(t.lo + c.lo);
  $DF z = df_fast_two_sum(t.hi, tl2);
  return z;
}

// df_div: a / b.
// Algorithm: DWDivDW2 (JMP Algorithm 17; same results as Algorithm 16) with DWTimesFP1
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1
// Bound: 15u^2 + 56u^3
// Flops: 33
// Steps: th = RN(ah/bh); (rh,rl) = DWTimesFP1(bh,bl,th); pih = RN(ah-rh) (exact, Sterbenz);
//        dl = RN(al-rl); d = RN(pih+dl); tl = RN(d/bh); (zh,zl) = Fast2Sum(th,tl).
// The proof assumes a correctly rounded float division; GLSL only promises 2.5 ulp for '/',
// which adds about 2.5u^2 (tl carries the error). b == 0 gives NaN (the split of Inf), not Inf.
// Range: |th| and |bh| <= 8.3e34 (split).
// @widths 1 2 3 4
$DF df_div($DF a, $DF b) {
  $PRECISE $F th = $G(a.hi / b.hi);
  $DF r = df_mul_f(b, th);
  $PRECISE $F pih = $G(a.hi - r.hi);
  $PRECISE $F dl = $G(a.lo - r.lo);
  $PRECISE $F d = $G(pih + dl);
  $PRECISE $F tl = $G(d / b.hi);
  $DF z = df_fast_two_sum(th, tl);
  return z;
}
