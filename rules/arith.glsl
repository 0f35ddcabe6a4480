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
// Special values (IEEE 754-2008 sections 6.1-6.3, 7.2-7.3): the error-free steps turn an
// infinite intermediate into NaN (Inf - Inf inside TwoSum/TwoProd) and a zero result into +0,
// so each rule ends with one df_finish: where the result's hi is zero, infinite or NaN, the
// result is (f, 0) with f the plain float operation on the high words (RN(ah+bh), RN(ah*bh),
// RN(ah/bh)), which has the class and sign IEEE gives the exact operation. See docs/extremes.md.

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
// @widths 1 2 3 4
$DF df_neg($DF a) {
  $PRECISE $F h = $SAFE(-a.hi);
  $PRECISE $F l = $SAFE(-a.lo);
  return $DF(h, l);
}

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
// @widths 1 2 3 4
// @per-component
$DF df_finish($DF z, $F f) {
  $PRECISE $F az = $SAFE(abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  $PRECISE $F h = $SAFE($SEL(regular, z.hi, f));
  $PRECISE $F l = $SAFE($SEL(regular, z.lo, 0.0));
  return $DF(h, l);
}

// df_add: a + b.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 21
// Steps: (sh,sl) = TwoSum(ah,bh); (th,tl) = TwoSum(al,bl); c = RN(sl+th);
//        (vh,vl) = Fast2Sum(sh,c); w = RN(tl+vl); (zh,zl) = Fast2Sum(vh,w); df_finish(z, sh).
// The bound holds for all signs (the "sloppy" 11-flop variant is unbounded under cancellation).
// Special values: sh = RN(ah+bh) is +-Inf, NaN or the signed zero IEEE gives (x + Inf = Inf,
// Inf - Inf = NaN, -0 + -0 = -0, x - x = +0). A finite sum above FLT_MAX is Inf (float's range).
// @widths 1 2 3 4
$DF df_add($DF a, $DF b) {
  $DF s = df_two_sum(a.hi, b.hi);
  $DF t = df_two_sum(a.lo, b.lo);
  $PRECISE $F c = $SAFE(s.lo + t.hi);
  $DF v = df_fast_two_sum(s.hi, c);
  $PRECISE $F w = $SAFE(t.lo + v.lo);
  $DF z = df_fast_two_sum(v.hi, w);
  $DF r = df_finish(z, s.hi);
  return r;
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 23
// @widths 1 2 3 4
$DF df_sub($DF a, $DF b) {
  $DF nb = df_neg(b);
  $DF z = df_add(a, nb);
  return z;
}

// df_add_f: a + b with b a plain float (b need not be a double-word).
// Algorithm: DWPlusFP (JMP Algorithm 4), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,b); v = RN(al+sl); (zh,zl) = Fast2Sum(sh,v); df_finish(z, sh).
// @widths 1 2 3 4
$DF df_add_f($DF a, $F b) {
  $DF s = df_two_sum(a.hi, b);
  $PRECISE $F v = $SAFE(a.lo + s.lo);
  $DF z = df_fast_two_sum(s.hi, v);
  $DF r = df_finish(z, s.hi);
  return r;
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split of scaled operands, C = 4097), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 29
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3); df_finish(z, ch).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: any finite operands whose product is within float range (TwoProd scales them).
// Special values: ch = RN(ah*bh) gives overflow to +-Inf, 0 * Inf = NaN and the sign of a zero.
// @widths 1 2 3 4
$DF df_mul($DF a, $DF b) {
  $DF c = df_two_prod(a.hi, b.hi);
  $PRECISE $F tl = $SAFE(a.hi * b.lo);
  $PRECISE $F th = $SAFE(a.lo * b.hi);
  $PRECISE $F cl2 = $SAFE(th + tl);
  $PRECISE $F cl3 = $SAFE(c.lo + cl2);
  $DF z = df_fast_two_sum(c.hi, cl3);
  $DF r = df_finish(z, c.hi);
  return r;
}

// df_mul_f: a * b with b a plain float.
// Algorithm: DWTimesFP1 (JMP Algorithm 7) with Dekker's TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 4.1
// Bound: 1.5u^2 + 4u^3
// Flops: 30
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); (th,tl1) = Fast2Sum(ch,cl2);
//        tl2 = RN(tl1+cl1); (zh,zl) = Fast2Sum(th,tl2); df_finish(z, ch).
// Range: any finite operands whose product is within float range (TwoProd scales them).
// @widths 1 2 3 4
$DF df_mul_f($DF a, $F b) {
  $DF c = df_two_prod(a.hi, b);
  $PRECISE $F cl2 = $SAFE(a.lo * b);
  $DF t = df_fast_two_sum(c.hi, cl2);
  $PRECISE $F tl2 = $SAFE(t.lo + c.lo);
  $DF z = df_fast_two_sum(t.hi, tl2);
  $DF r = df_finish(z, c.hi);
  return r;
}

// df_div: a / b.
// Algorithm: DWDivDW2 (JMP Algorithm 17; same results as Algorithm 16) with DWTimesFP1, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1
// Bound: 15u^2 + 56u^3
// Flops: 39
// Steps: th = RN(ah/bh); (rh,rl) = DWTimesFP1(bh,bl,th); pih = RN(ah-rh) (exact, Sterbenz);
//        dl = RN(al-rl); d = RN(pih+dl); tl = RN(d/bh); (zh,zl) = Fast2Sum(th,tl);
//        df_finish(z, th).
// The proof assumes a correctly rounded float division; GLSL only promises 2.5 ulp for '/',
// which adds about 2.5u^2 (tl carries the error).
// Special values: th = RN(ah/bh) gives x/+-0 = +-Inf, 0/0 = NaN, x/Inf = +-0, overflow to Inf.
// Range: any finite a, b with the quotient within float range (TwoProd scales its operands).
// @widths 1 2 3 4
$DF df_div($DF a, $DF b) {
  $PRECISE $F th = $G(a.hi / b.hi);
  $DF r = df_mul_f(b, th);
  $PRECISE $F pih = $SAFE(a.hi - r.hi);
  $PRECISE $F dl = $SAFE(a.lo - r.lo);
  $PRECISE $F d = $SAFE(pih + dl);
  $PRECISE $F tl = $SAFE(d / b.hi);
  $DF z = df_fast_two_sum(th, tl);
  $DF q = df_finish(z, th);
  return q;
}
