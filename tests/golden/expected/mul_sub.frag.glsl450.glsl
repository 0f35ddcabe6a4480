#version 450 core
precision highp float;
precision highp int;

uniform float a_hi;
uniform float a_lo;
uniform float b_hi;
uniform float b_lo;

// doublet float-float runtime: 11 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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
  precise float hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  precise float lo = (a - hi);
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
  precise float hh = (sa.hi * sb.hi);
  precise float hl = (sa.hi * sb.lo);
  precise float lh = (sa.lo * sb.hi);
  precise float ll = (sa.lo * sb.lo);
  precise float t1 = (hh - p);
  precise float t2 = (t1 + hl);
  precise float t3 = (t2 + lh);
  precise float e = (t3 + ll);
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
  precise float p = (a * b);
  df_double sa = df_split(a);
  df_double sb = df_split(b);
  precise float e = (df_mul12_error(sa, sb, p));
  return df_double(p, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_double df_fast_two_sum(float a, float b) {
  precise float s = (a + b);
  precise float z = (s - a);
  precise float e = (b - z);
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
  precise float az = (abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  precise float h = (mix(f, z.hi, regular));
  precise float l = (mix(0.0, z.lo, regular));
  return df_double(h, l);
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
  precise float tl = (a.hi * b.lo);
  precise float th = (a.lo * b.hi);
  precise float cl2 = (th + tl);
  precise float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
  return r;
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_double df_neg(df_double a) {
  precise float h = (-a.hi);
  precise float l = (-a.lo);
  return df_double(h, l);
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_double df_two_sum(float a, float b) {
  precise float s = (a + b);
  precise float bb = (s - a);
  precise float ab = (s - bb);
  precise float da = (a - ab);
  precise float db = (b - bb);
  precise float e = (da + db);
  return df_double(s, e);
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
  precise float c = (s.lo + t.hi);
  df_double v = df_fast_two_sum(s.hi, c);
  precise float w = (t.lo + v.lo);
  df_double z = df_fast_two_sum(v.hi, w);
  df_double r = df_finish(z, s.hi);
  return r;
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

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
float df_to_float(df_double a) {
  precise float f = (a.hi + a.lo);
  df_double r = df_finish(df_double(f, float(0.0)), a.hi);
  return r.hi;
}

df_double a;
df_double b;
out vec4 color;


void main()
{
  a = df_double(a_hi - df_guard[int(df_guard[1])], a_lo - df_guard[int(df_guard[1])]);
  b = df_double(b_hi - df_guard[int(df_guard[1])], b_lo - df_guard[int(df_guard[1])]);
  df_double p = df_sub(df_mul(a, b), a);
  color = vec4(df_to_float(p), 0.0, 0.0, 1.0);
}
