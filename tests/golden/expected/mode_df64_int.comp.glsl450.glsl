#version 450 core
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

// doublet float-float runtime: 18 functions from rules/*.glsl, guard: none (unprotected), error-free transformations: integer (df64-int)
struct df_double { float hi; float lo; };

// df_int_unit: the biased exponent u of x's unit in the last place, x = m * 2^(u - 150) with m the
// integer significand (u = 1 for 0 and subnormals). Callers subtract units; only scaling needs the bias.
// Algorithm: binary32 exponent field, at least 1
// Source: IEEE 754-2008 binary32 encoding; HFPA (2018) section 2.1
// Bound: exact
// Flops: 0 (integer: 1 shift, 1 and, 1 max)
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
uint df_int_signed(float x) {
  uint m = df_int_magnitude(x);
  uint s = uint(floatBitsToInt(x) >> 31);
  uint r = (m ^ s) - s;
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
  float f = (float(n) * 1.1920928955078125e-7);
  float e = (f * uintBitsToFloat(uint(umin) << 23u));
  float r = (mix(e, 0.0, exact));
  return r;
}

// df_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); e by integers.
// Algorithm: TwoSum with the error term as the integer residual df_int_sum_error
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (the error is representable)
// Bound: exact
// Flops: 4
df_double df_two_sum(float a, float b) {
  float s = (a + b);
  float e = (df_int_sum_error(a, b, s));
  return df_double(s, e);
}

// df_fast_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); no precondition on a, b
// (the integer residual does not need |a| >= |b|).
// Algorithm: Fast2Sum replaced by TwoSum with the integer residual df_int_sum_error
// Source: Dekker 1971, Theorem 4.3 (the error is representable); Knuth, TAOCP vol. 2, 1998, 4.2.2
// Bound: exact
// Flops: 4
df_double df_fast_two_sum(float a, float b) {
  float s = (a + b);
  float e = (df_int_sum_error(a, b, s));
  return df_double(s, e);
}

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
df_double df_finish(df_double z, float f) {
  float az = (abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  float h = (mix(f, z.hi, regular));
  float l = (mix(0.0, z.lo, regular));
  return df_double(h, l);
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
df_double df_add(df_double a, df_double b) {
  df_double s = df_two_sum(a.hi, b.hi);
  df_double t = df_two_sum(a.lo, b.lo);
  float c = (s.lo + t.hi);
  df_double v = df_fast_two_sum(s.hi, c);
  float w = (t.lo + v.lo);
  df_double z = df_fast_two_sum(v.hi, w);
  df_double r = df_finish(z, s.hi);
  return r;
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_double df_neg(df_double a) {
  float h = (-a.hi);
  float l = (-a.lo);
  return df_double(h, l);
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 23
df_double df_sub(df_double a, df_double b) {
  df_double nb = df_neg(b);
  df_double z = df_add(a, nb);
  return z;
}

// df_int_scale: n * 2^k, exact whenever the result is a float (one rounding below 2^-126 otherwise).
// Algorithm: conversion of n (at most 24 significant bits, so exact), then two multiplications by
// powers of two built from their bit patterns, k split in halves (k >> 1 and the rest) so neither
// factor leaves the normal range and the first product cannot underflow or overflow
// Source: HFPA (2018) section 2.2 (multiplication by a power of the radix is exact)
// Bound: exact
// Flops: 3
// Range: -252 <= k <= 253, which the callers guarantee wherever their result is used.
float df_int_scale(int n, int k) {
  int k1 = k >> 1;
  int k2 = k - k1;
  float p1 = (uintBitsToFloat(uint(k1 + 127) << 23u));
  float p2 = (uintBitsToFloat(uint(k2 + 127) << 23u));
  float f = (float(n));
  float f1 = (f * p1);
  float r = (f1 * p2);
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
  float e = (df_int_scale(sn, ua + ub - 300));
  float r = (mix(e, 0.0, none));
  return r;
}

// df_two_prod (df64-int): p + e == a * b exactly, p = RN(a * b); e by integers (no split,
// so no range limit from Veltkamp's constant).
// Algorithm: TwoProd with the error term as the integer residual df_int_prod_error
// Source: Dekker 1971, mul12 (the error is representable); HFPA (2018) section 4.4
// Bound: exact
// Flops: 4
// Range: exact while e >= 2^-126; p Inf/NaN/overflowed gives e = 0 and df_finish returns (p, 0).
df_double df_two_prod(float a, float b) {
  float p = (a * b);
  float e = (df_int_prod_error(a, b, p));
  return df_double(p, e);
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
df_double df_mul(df_double a, df_double b) {
  df_double c = df_two_prod(a.hi, b.hi);
  float tl = (a.hi * b.lo);
  float th = (a.lo * b.hi);
  float cl2 = (th + tl);
  float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
  return r;
}

// df_sqrt: sqrt(a) for a >= 0; sqrt(+-0) = +-0, sqrt(+Inf) = +Inf, sqrt(a < 0) and sqrt(NaN) = NaN
// (IEEE 754-2008 section 5.4.1; GLSL leaves a < 0 undefined, the drivers give NaN).
// Algorithm: SQRTDWtoDW (LLMPR Algorithm 8), FMA step replaced by an exact Dekker square, then df_finish
// Source: Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023, Algorithm 8 and its theorem
// Bound: 25/8 u^2
// Flops: 31
// Steps (LLMPR Algorithm 8, our no-FMA form):
//   sh   = RN(sqrt(ah))
//   (p,e)= TwoProd(sh, sh)           p + e == sh^2 exactly
//   r0   = RN(ah - p)                exact: ah/2 <= p <= 2ah (Sterbenz)
//   rho1 = RN(r0 - e)                == RN(ah - sh^2), the value fma(-sh, sh, ah) returns
//   rho2 = RN(al + rho1)
//   sl   = RN(rho2 / (2 sh))
//   (zh,zl) = Fast2Sum(sh, sl)
// sh is guarded too: Mesa rewrites sqrt(x)*sqrt(x) to |x|, which would zero the residual.
// So every value equals the FMA version's and the 25/8 u^2 bound carries over, given a
// correctly rounded float sqrt and division (x86 llvmpipe). With a k-ulp sqrt (GLSL permits a
// few ulp) the step is still a Newton correction: about (25/8 + k + k^2/2) u^2 (estimate,
// not proved). Special values end in df_finish(z, sh): a = +-0 gives sl = 0/0 = NaN and so
// (sh, 0) = (+-0, 0); Inf, NaN and negative a give (sqrt(ah), 0) = (Inf or NaN, 0).
// Range: every finite a >= 0; within an ulp of FLT_MAX sh*sh overflows and the result is sh alone.
df_double df_sqrt(df_double a) {
  float sh = (sqrt(a.hi));
  df_double sq = df_two_prod(sh, sh);
  float r0 = (a.hi - sq.hi);
  float rho1 = (r0 - sq.lo);
  float rho2 = (a.lo + rho1);
  float sh2 = (sh * 2.0);
  float sl = (rho2 / sh2);
  df_double z = df_fast_two_sum(sh, sl);
  df_double r = df_finish(z, sh);
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
df_double df_mul_f(df_double a, float b) {
  df_double c = df_two_prod(a.hi, b);
  float cl2 = (a.lo * b);
  df_double t = df_fast_two_sum(c.hi, cl2);
  float tl2 = (t.lo + c.lo);
  df_double z = df_fast_two_sum(t.hi, tl2);
  df_double r = df_finish(z, c.hi);
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
df_double df_div(df_double a, df_double b) {
  float th = (a.hi / b.hi);
  df_double r = df_mul_f(b, th);
  float pih = (a.hi - r.hi);
  float dl = (a.lo - r.lo);
  float d = (pih + dl);
  float tl = (d / b.hi);
  df_double z = df_fast_two_sum(th, tl);
  df_double q = df_finish(z, th);
  return q;
}

// df_sqr (df64-int): a * a, DWTimesDW1 with the integer TwoProd (the df64 df_sqr inlines a
// float Veltkamp split).
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with a = b and the integer TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 11 (with the integer TwoProd's and Fast2Sum's 4 each)
// Steps: (ch,cl1) = TwoProd(ah,ah); c = RN(ah*al); cl3 = RN(cl1 + 2c); (zh,zl) = Fast2Sum(ch,cl3);
//        df_finish(z, ch).
df_double df_sqr(df_double a) {
  df_double c = df_two_prod(a.hi, a.hi);
  float x = (a.hi * a.lo);
  float x2 = (x + x);
  float cl3 = (c.lo + x2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
  return r;
}

layout(std430, binding = 0) buffer Data {
  df_double x[];
};


void main()
{
  uint i = gl_GlobalInvocationID.x;
  df_double a = x[4u * i];
  df_double b = x[4u * i + 1u];
  x[4u * i + 2u] = df_div(df_mul(df_add(a, b), df_sub(a, b)), df_sqrt(a));
  df_double c = x[4u * i + 3u];
  c = df_add(c, df_sqr(a));
  x[4u * i + 3u] = c;
}
