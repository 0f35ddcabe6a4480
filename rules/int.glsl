// rules/int.glsl -- the integer error-free transformations of mode df64-int (docs/modes.md).
// The chunks marked "@variant int" replace the float EFTs of rules/core.glsl (and df_sqr, which
// inlines a Veltkamp split) when the shader is lowered with --mode df64-int; every other rule is
// shared with df64 and calls them by the same names.
//
// Idea: the float unit still computes the rounded result (s = RN(a+b), p = RN(a*b)); the error
// term is then computed EXACTLY with 32-bit integer arithmetic on the decoded significands and
// exponents (floatBitsToUint), as the residual (a + b) - s or a*b - p. No float expression in
// these rules depends on another one cancelling, so no algebraic rewrite of float code
// (reassociation, x + y - x -> y, contraction, constant folding of a guard) can delete the
// error term: the residual is computed for whatever value the hardware produced for s or p.
// It is exact when s = RN(a + b) (p = RN(a * b)), as IEEE requires; if a rewrite made s a few
// ulps off (fewer than 2^5), the 32-bit modular difference is still the true residual and
// float(n) rounds it to 24 bits, so hi + lo stays within about u^2 of the exact value.
//
// Sources:
//   [Knuth]  D. E. Knuth, The Art of Computer Programming, vol. 2, 3rd ed., 1998, section 4.2.2
//            (the rounding error of a sum is representable; Theorem B).
//   [Dekker] T. J. Dekker, "A floating-point technique for extending the available precision",
//            Numerische Mathematik 18(3):224-242, 1971 (the error of a product is representable).
//   [HFPA]   J.-M. Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., Birkhauser,
//            2018, sections 2.1-2.2 (binary32 encoding, significand and exponent), 4.2-4.4.
//   [Hauser] J. R. Hauser, "Handling floating-point exceptions in numeric programs", ACM TOPLAS
//            18(2):139-174, 1996 (a sum that underflows, whose result is subnormal, is exact).
//   [ESSL]   The OpenGL ES Shading Language 3.00, section 4.1.3 and 5.4.1 (uint arithmetic wraps
//            modulo 2^32; int(uint) keeps the bit pattern); section 8.3 (floatBitsToUint).
// Notation: u = 2^-24. A finite float x is m * 2^E with m a 24-bit integer significand
// (subnormals: no hidden bit, E = -149). Needs ES 3.00 (uint, bit casts).

// df_int_unit: the biased exponent u of x's unit in the last place, x = m * 2^(u - 150) with m the
// integer significand (u = 1 for 0 and subnormals). Callers subtract units; only scaling needs the bias.
// Algorithm: binary32 exponent field, at least 1
// Source: IEEE 754-2008 binary32 encoding; HFPA (2018) section 2.1
// Bound: exact
// Flops: 0 (integer: 1 shift, 1 and, 1 max)
// @min-es 300
int df_int_unit(float x) {
  int field = int((floatBitsToUint(x) >> 23u) & 255u);
  int u = max(field, 1);
  return u;
}

// df_int_magnitude: the 24-bit integer significand m of |x| (hidden bit restored when x is normal).
// Algorithm: binary32 significand field plus the hidden bit (min(field, 1) << 23)
// Source: IEEE 754-2008 binary32 encoding; HFPA (2018) section 2.1
// Bound: exact
// Flops: 0 (integer: 1 shift, 2 ands, 1 min, 1 shift, 1 or; the field shared with df_int_unit)
// @min-es 300
uint df_int_magnitude(float x) {
  uint bits = floatBitsToUint(x);
  uint field = (bits >> 23u) & 255u;
  uint m = (bits & 8388607u) | (min(field, 1u) << 23u);
  return m;
}

// df_int_signed: the integer significand of x with x's sign, two's complement in a uint.
// Algorithm: df_int_magnitude, negated modulo 2^32 by (m ^ s) - s with s the sign bit spread over
// the word (arithmetic shift), no select
// Source: ESSL 3.00 (2012) sections 4.1.3 (uint arithmetic wraps modulo 2^32) and 5.9 (>> of a
// signed int extends the sign)
// Bound: exact
// Flops: 0 (integer: df_int_magnitude, 1 shift, 1 xor, 1 sub)
// @min-es 300
uint df_int_signed(float x) {
  uint m = df_int_magnitude(x);
  uint s = uint(floatBitsToInt(x) >> 31);
  uint r = (m ^ s) - s;
  return r;
}

// df_int_scale: n * 2^k, exact whenever the result is a float (one rounding below 2^-126 otherwise).
// Algorithm: conversion of n (at most 24 significant bits, so exact), then two multiplications by
// powers of two built from their bit patterns, k split in halves (k >> 1 and the rest) so neither
// factor leaves the normal range and the first product cannot underflow or overflow
// Source: HFPA (2018) section 2.2 (multiplication by a power of the radix is exact)
// Bound: exact
// Flops: 3
// Range: -252 <= k <= 253, which the callers guarantee wherever their result is used.
// @min-es 300
float df_int_scale(int n, int k) {
  int k1 = k >> 1;
  int k2 = k - k1;
  $PRECISE float p1 = $SAFE(uintBitsToFloat(uint(k1 + 127) << 23u));
  $PRECISE float p2 = $SAFE(uintBitsToFloat(uint(k2 + 127) << 23u));
  $PRECISE float f = $SAFE(float(n));
  $PRECISE float f1 = $SAFE(f * p1);
  $PRECISE float r = $SAFE(f1 * p2);
  return r;
}

// df_int_sum_error: (a + b) - s exactly, for s the float sum the hardware computed.
// Algorithm: all three are integer multiples of 2^Emin (Emin the smaller exponent of a and b;
// s too unless s has a smaller exponent, and then a + b was exact); the residual in units of
// 2^Emin is ma<<da + mb<<db - ms<<ds, computed modulo 2^32: its true value is below 2^25
// because |(a+b) - s| <= ulp(s)/2 and ds <= 26, so the modular result is exact
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 (the error of RN(a+b) is a float); ESSL 3.00 (2012) 4.1.3
// Bound: exact
// Flops: 3 (integer: about 40 operations)
// Steps: shifts are clamped to 31. When the exponents differ by more than 25 the smaller operand
// is below a quarter ulp of the larger, so s is the larger: s and the larger operand get the same
// clamped shift, cancel exactly, and the residual is the smaller operand with no special case.
// Inf/NaN s, or s whose exponent field is below both operands' units (zero and subnormal s
// included: a sum that small is exact, Hauser 1996): 0. So s is decoded as a normal number (its
// field, the hidden bit always set). Scaling: n * 2^-23 (exact: n is an integer below 2^25), then
// times 2^(Emin - 127), a normal power of two built from Emin's bits: one rounding, where e is
// below 2^-126, as the float TwoSum's; no overflow, since |e| <= 2^103.
// @min-es 300
float df_int_sum_error(float a, float b, float s) {
  int ua = df_int_unit(a);
  int ub = df_int_unit(b);
  int umin = min(ua, ub);
  uint ta = df_int_signed(a) << min(uint(ua - umin), 31u);
  uint tb = df_int_signed(b) << min(uint(ub - umin), 31u);
  uint bs = floatBitsToUint(s);
  int fs = int((bs >> 23u) & 255u);
  uint sign = uint(floatBitsToInt(s) >> 31);
  uint ms = (bs & 8388607u) | 8388608u;
  uint ts = ((ms ^ sign) - sign) << min(uint(fs - umin), 31u);
  int n = int(ta + tb - ts);
  bool exact = any(bvec2(fs == 255, fs < umin));
  $PRECISE float f = $SAFE(float(n) * 1.1920928955078125e-7);
  $PRECISE float e = $SAFE(f * uintBitsToFloat(uint(umin) << 23u));
  $PRECISE float r = $SAFE($SEL(exact, 0.0, e));
  return r;
}

// df_int_prod_error: a*b - p exactly, for p the float product the hardware computed.
// Algorithm: a*b = ma*mb * 2^(Ea+Eb) and p = mp * 2^Ep with k = Ep - Ea - Eb in 0..25; the
// residual in units of 2^(Ea+Eb) is ma*mb - mp<<k, below 2^24 in magnitude, so the low 32 bits
// of the 48-bit product (uint multiplication wraps) give it exactly; p's sign is applied by
// (n ^ s) - s
// Source: Dekker 1971 (the error of RN(a*b) is a float); ESSL 3.00 (2012) 4.1.3 (uint multiplication wraps modulo 2^32)
// Bound: exact
// Flops: 3 (df_int_scale; integer: about 35 operations)
// Steps: p zero, subnormal, Inf or NaN (its field minus 1 is 254 or more as a uint): 0 (a*b
// underflowed, overflowed or was special; the callers' df_finish returns (p, 0) for the last
// three, as in df64). k outside 0..31 (k < 0: the product had fewer than 24 bits, p is exact): 0.
// Range: e below 2^-126 is rounded (df_int_scale), as the float TwoProd's error term underflows;
// where e is used, Ea + Eb >= Ep - 31 >= -180, within df_int_scale's range.
// @min-es 300
float df_int_prod_error(float a, float b, float p) {
  uint bp = floatBitsToUint(p);
  int fp = int((bp >> 23u) & 255u);
  int ua = df_int_unit(a);
  int ub = df_int_unit(b);
  int k = fp - ua - ub + 150;
  bool none = any(bvec2(uint(fp - 1) >= 254u, uint(k) > 31u));
  uint low = df_int_magnitude(a) * df_int_magnitude(b);
  uint shifted = ((bp & 8388607u) | 8388608u) << min(uint(k), 31u);
  int n = int(low - shifted);
  int sign = floatBitsToInt(p) >> 31;
  int sn = (n ^ sign) - sign;
  $PRECISE float e = $SAFE(df_int_scale(sn, ua + ub - 300));
  $PRECISE float r = $SAFE($SEL(none, 0.0, e));
  return r;
}

// df_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); e by integers.
// Algorithm: TwoSum with the error term as the integer residual df_int_sum_error
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (the error is representable)
// Bound: exact
// Flops: 4
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @variant int
$DF df_two_sum($F a, $F b) {
  $PRECISE $F s = $G(a + b);
  $PRECISE $F e = $SAFE(df_int_sum_error(a, b, s));
  return $DF(s, e);
}

// df_fast_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); no precondition on a, b
// (the integer residual does not need |a| >= |b|).
// Algorithm: Fast2Sum replaced by TwoSum with the integer residual df_int_sum_error
// Source: Dekker 1971, Theorem 4.3 (the error is representable); Knuth, TAOCP vol. 2, 1998, 4.2.2
// Bound: exact
// Flops: 4
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @variant int
$DF df_fast_two_sum($F a, $F b) {
  $PRECISE $F s = $G(a + b);
  $PRECISE $F e = $SAFE(df_int_sum_error(a, b, s));
  return $DF(s, e);
}

// df_two_prod (df64-int): p + e == a * b exactly, p = RN(a * b); e by integers (no split,
// so no range limit from Veltkamp's constant).
// Algorithm: TwoProd with the error term as the integer residual df_int_prod_error
// Source: Dekker 1971, mul12 (the error is representable); HFPA (2018) section 4.4
// Bound: exact
// Flops: 4
// Range: exact while e >= 2^-126; p Inf/NaN/overflowed gives e = 0 and df_finish returns (p, 0).
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @variant int
$DF df_two_prod($F a, $F b) {
  $PRECISE $F p = $G(a * b);
  $PRECISE $F e = $SAFE(df_int_prod_error(a, b, p));
  return $DF(p, e);
}

// df_sqr (df64-int): a * a, DWTimesDW1 with the integer TwoProd (the df64 df_sqr inlines a
// float Veltkamp split).
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with a = b and the integer TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 11 (with the integer TwoProd's and Fast2Sum's 4 each)
// Steps: (ch,cl1) = TwoProd(ah,ah); c = RN(ah*al); cl3 = RN(cl1 + 2c); (zh,zl) = Fast2Sum(ch,cl3);
//        df_finish(z, ch).
// @widths 1 2 3 4
// @min-es 300
// @variant int
$DF df_sqr($DF a) {
  $DF c = df_two_prod(a.hi, a.hi);
  $PRECISE $F x = $SAFE(a.hi * a.lo);
  $PRECISE $F x2 = $SAFE(x + x);
  $PRECISE $F cl3 = $SAFE(c.lo + x2);
  $DF z = df_fast_two_sum(c.hi, cl3);
  $DF r = df_finish(z, c.hi);
  return r;
}
