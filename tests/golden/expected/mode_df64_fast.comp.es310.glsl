#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

// doublet float-float runtime: 11 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_double df_two_sum(float a, float b) {
  float s = ((a + b) - df_guard[int(df_guard[1])]);
  float bb = ((s - a) - df_guard[int(df_guard[1])]);
  float ab = (s - bb);
  float da = (a - ab);
  float db = (b - bb);
  float e = (da + db);
  return df_double(s, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_double df_fast_two_sum(float a, float b) {
  float s = ((a + b) - df_guard[int(df_guard[1])]);
  float z = ((s - a) - df_guard[int(df_guard[1])]);
  float e = (b - z);
  return df_double(s, e);
}

// df_add_fast: a + b without the second TwoSum of the low words.
// Algorithm: SloppyDWPlusDW (JMP Algorithm 5; Dekker's add2)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Section 3; Yang et al., arXiv:2404.05948, 2024
// Bound: 3u^2 when a and b have the same sign; unbounded relative error for opposite signs (cancellation of the high words)
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,bh); v = RN(al+bl); w = RN(sl+v); (zh,zl) = Fast2Sum(sh,w).
// Under cancellation (ah ~ -bh) the rounding of al+bl is no longer small next to the result:
// the error stays below about u^2 (|a| + |b|) in absolute terms, which can be all of a
// small result. Use df64 where differences of nearly equal values matter.
df_double df_add_fast(df_double a, df_double b) {
  df_double s = df_two_sum(a.hi, b.hi);
  float v = (a.lo + b.lo);
  float w = (s.lo + v);
  df_double z = df_fast_two_sum(s.hi, w);
  return z;
}

// df_sub_fast: a - b = a + (-b) by the sloppy addition; the negation of b is exact.
// Algorithm: SloppyDWPlusDW on (a, -b) (JMP Algorithm 5)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Section 3; Yang et al., arXiv:2404.05948, 2024
// Bound: 3u^2 when a and b have opposite signs; unbounded relative error for equal signs (cancellation of the high words)
// Flops: 12
df_double df_sub_fast(df_double a, df_double b) {
  float nh = (-b.hi);
  df_double s = df_two_sum(a.hi, nh);
  float v = (a.lo - b.lo);
  float w = (s.lo + v);
  df_double z = df_fast_two_sum(s.hi, w);
  return z;
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
df_double df_split(float a) {
  uint bits = floatBitsToUint(a);
  float hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  float lo = (a - hi);
  return df_double(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
float df_mul12_error(df_double sa, df_double sb, float p) {
  float hh = (sa.hi * sb.hi);
  float hl = (sa.hi * sb.lo);
  float lh = (sa.lo * sb.hi);
  float ll = (sa.lo * sb.lo);
  float t1 = (hh - p);
  float t2 = (t1 + hl);
  float t3 = (t2 + lh);
  float e = (t3 + ll);
  return e;
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
df_double df_two_prod(float a, float b) {
  float p = ((a * b) - df_guard[int(df_guard[1])]);
  df_double sa = df_split(a);
  df_double sb = df_split(b);
  float e = (df_mul12_error(sa, sb, p));
  return df_double(p, e);
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
df_double df_mul_fast(df_double a, df_double b) {
  df_double c = df_two_prod(a.hi, b.hi);
  float tl = (a.hi * b.lo);
  float th = (a.lo * b.hi);
  float cl2 = (th + tl);
  float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  return z;
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
  float sh = ((sqrt(a.hi)) - df_guard[int(df_guard[1])]);
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
df_double df_div_fast(df_double a, df_double b) {
  float th = ((a.hi / b.hi) - df_guard[int(df_guard[1])]);
  df_double c = df_two_prod(b.hi, th);
  float cl2 = (b.lo * th);
  float rl = (c.lo + cl2);
  float pih = (a.hi - c.hi);
  float dl = (a.lo - rl);
  float d = (pih + dl);
  float tl = (d / b.hi);
  df_double z = df_fast_two_sum(th, tl);
  return z;
}

layout(std430, binding = 0) buffer Data {
  df_double x[];
};


void main()
{
  uint i = gl_GlobalInvocationID.x;
  df_double a = x[4u * i];
  df_double b = x[4u * i + 1u];
  x[4u * i + 2u] = df_div_fast(df_mul_fast(df_add_fast(a, b), df_sub_fast(a, b)), df_sqrt(a));
  df_double c = x[4u * i + 3u];
  c = df_add_fast(c, a);
  x[4u * i + 3u] = c;
}
