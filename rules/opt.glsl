// rules/opt.glsl -- cheaper forms that the whole-shader optimizer (src/lower/optimize_df.cpp)
// substitutes for general rule calls when it can see something about the operands: a product by
// a power of two, a square, an operand whose lo word is known to be zero (a float widened to
// double, a double constant that is exactly a float). Each is as accurate as the form it
// replaces (same or smaller bound) and uses fewer float operations.
//
// Sources:
//   [JMP]    M. Joldes, J.-M. Muller, V. Popescu, "Tight and rigorous error bounds for basic
//            building blocks of double-word arithmetic", ACM TOMS 44(2), 2017.
//   [MR]     J.-M. Muller, L. Rideau, "Formalization of double-word arithmetic", ACM TOMS 48(1),
//            2022 (DWTimesDW1 bound 5u^2).
//   [Dekker] T. J. Dekker, "A floating-point technique for extending the available precision",
//            Numerische Mathematik 18(3):224-242, 1971 (mul12; the square is mul12 with a = b).
//   [HFPA]   J.-M. Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., 2018, ch. 4.
// Notation: u = 2^-24; bounds are relative errors assuming round-to-nearest and no
// overflow/underflow in any intermediate (as in rules/arith.glsl).

// df_mul_pow2: a * p where every component of p is a power of two (+-2^k), exact: scaling by a
// power of two only changes exponents, so hi*p and lo*p are exact and (hi*p, lo*p) is still a
// double-word number. Replaces df_mul (29 flops) and df_div by a power of two.
// Algorithm: exact scaling of both words by a power of two, then df_finish
// Source: HFPA (2018), section 2.2 (multiplication by a power of the radix is exact); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// Range: exact while lo*p stays normal (|lo*p| >= 2^-126) and hi*p does not overflow; an
// overflowing, zero or NaN hi*p gives (hi*p, 0) as df_mul does (df_finish).
// @widths 1 2 3 4
$DF df_mul_pow2($DF a, $F p) {
  $PRECISE $F h = $SAFE(a.hi * p);
  $PRECISE $F l = $SAFE(a.lo * p);
  $DF r = df_finish($DF(h, l), h);
  return r;
}

// df_sqr: a * a. Dekker's mul12 with both operands equal needs one Veltkamp split instead of
// two and its two cross products are equal (one product, doubled exactly), and DWTimesDW1's two
// terms ah*al and al*ah are equal too. Every rounding is the one df_mul(a, a) performs, so the
// result is bit-identical to df_mul(a, a) (wherever a*a is finite) with 10 fewer operations.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with a = b, Dekker's TwoProd specialised to a square, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2); Dekker 1971
// Bound: 7u^2
// Flops: 19
// Steps: p = RN(ah*ah); (sh,sl) = split(ah); t1 = RN(sh*sh - p); t2 = RN(t1 + 2*(sh*sl));
//        e = RN(t2 + sl*sl) (exact: the partial sums of mul12); c = RN(ah*al);
//        cl3 = RN(e + 2c); (zh,zl) = Fast2Sum(p, cl3); df_finish(z, p).
// Range and special values: as df_mul. The split is not scaled: whenever a*a is finite,
// |a| < 1.9e19 is far below the split's limit (8.3e34); when it overflows, p is Inf and
// df_finish returns (Inf, 0) as df_mul does.
// @widths 1 2 3 4
$DF df_sqr($DF a) {
  $PRECISE $F p = $G(a.hi * a.hi);
  $DF s = df_split(a.hi);
  $PRECISE $F hh = $SAFE(s.hi * s.hi);
  $PRECISE $F hl = $SAFE(s.hi * s.lo);
  $PRECISE $F hl2 = $SAFE(hl + hl);
  $PRECISE $F ll = $SAFE(s.lo * s.lo);
  $PRECISE $F t1 = $SAFE(hh - p);
  $PRECISE $F t2 = $SAFE(t1 + hl2);
  $PRECISE $F e = $SAFE(t2 + ll);
  $PRECISE $F c = $SAFE(a.hi * a.lo);
  $PRECISE $F c2 = $SAFE(c + c);
  $PRECISE $F cl3 = $SAFE(e + c2);
  $DF z = df_fast_two_sum(p, cl3);
  $DF r = df_finish(z, p);
  return r;
}

// df_mul_f2: a * b with b a plain float (the lo word of the double operand known to be zero).
// Cheaper than df_mul (29) and more accurate (3u^2 against 7u^2).
// Algorithm: DWTimesFP2 (JMP Algorithm 8) with Dekker's TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, section 4
// Bound: 3u^2
// Flops: 27
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3);
//        df_finish(z, ch).
// Range and special values: as df_mul (the same TwoProd, the same df_finish).
// @widths 1 2 3 4
$DF df_mul_f2($DF a, $F b) {
  $DF c = df_two_prod(a.hi, b);
  $PRECISE $F cl2 = $SAFE(a.lo * b);
  $PRECISE $F cl3 = $SAFE(c.lo + cl2);
  $DF z = df_fast_two_sum(c.hi, cl3);
  $DF r = df_finish(z, c.hi);
  return r;
}
