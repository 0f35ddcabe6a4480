#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

struct df_dvec4 {
  vec4 hi;
  vec4 lo;
};
// doublet float-float runtime: 13 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
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

// df_add_f: a + b with b a plain float (b need not be a double-word).
// Algorithm: DWPlusFP (JMP Algorithm 4), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,b); v = RN(al+sl); (zh,zl) = Fast2Sum(sh,v); df_finish(z, sh).
df_double df_add_f(df_double a, float b) {
  df_double s = df_two_sum(a.hi, b);
  float v = (a.lo + s.lo);
  df_double z = df_fast_two_sum(s.hi, v);
  df_double r = df_finish(z, s.hi);
  return r;
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec2 df_two_sum(vec2 a, vec2 b) {
  vec2 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec2 bb = ((s - a) - df_guard[int(df_guard[1])]);
  vec2 ab = (s - bb);
  vec2 da = (a - ab);
  vec2 db = (b - bb);
  vec2 e = (da + db);
  return df_dvec2(s, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec2 df_fast_two_sum(vec2 a, vec2 b) {
  vec2 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec2 z = ((s - a) - df_guard[int(df_guard[1])]);
  vec2 e = (b - z);
  return df_dvec2(s, e);
}

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
// (width 2: the width-1 df_finish applied to each component)
df_dvec2 df_finish(df_dvec2 z, vec2 f) {
  df_double r0 = df_finish(df_double(z.hi.x, z.lo.x), f.x);
  df_double r1 = df_finish(df_double(z.hi.y, z.lo.y), f.y);
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

// df_add_f: a + b with b a plain float (b need not be a double-word).
// Algorithm: DWPlusFP (JMP Algorithm 4), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,b); v = RN(al+sl); (zh,zl) = Fast2Sum(sh,v); df_finish(z, sh).
df_dvec2 df_add_f(df_dvec2 a, vec2 b) {
  df_dvec2 s = df_two_sum(a.hi, b);
  vec2 v = (a.lo + s.lo);
  df_dvec2 z = df_fast_two_sum(s.hi, v);
  df_dvec2 r = df_finish(z, s.hi);
  return r;
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

// df_mul_f2: a * b with b a plain float (the lo word of the double operand known to be zero).
// Cheaper than df_mul (29) and more accurate (3u^2 against 7u^2).
// Algorithm: DWTimesFP2 (JMP Algorithm 8) with Dekker's TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, section 4
// Bound: 3u^2
// Flops: 27
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3);
//        df_finish(z, ch).
// Range and special values: as df_mul (the same TwoProd, the same df_finish).
df_double df_mul_f2(df_double a, float b) {
  df_double c = df_two_prod(a.hi, b);
  float cl2 = (a.lo * b);
  float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
  return r;
}

df_dvec4 df_make_dvec4_1_1_1_1(df_double a0, df_double a1, df_double a2, df_double a3) {
  return df_dvec4(vec4(a0.hi, a1.hi, a2.hi, a3.hi), vec4(a0.lo, a1.lo, a2.lo, a3.lo));
}

df_double df_assign_dvec4_z(inout df_dvec4 v, df_double x) {
  v.hi.z = x.hi;
  v.lo.z = x.lo;
  return x;
}

df_dvec2 df_assign_dvec4_zw(inout df_dvec4 v, df_dvec2 x) {
  v.hi.zw = x.hi;
  v.lo.zw = x.lo;
  return x;
}

df_double df_assign_dvec4_y(inout df_dvec4 v, df_double x) {
  v.hi.y = x.hi;
  v.lo.y = x.lo;
  return x;
}

df_double df_assign_dvec4_w(inout df_dvec4 v, df_double x) {
  v.hi.w = x.hi;
  v.lo.w = x.lo;
  return x;
}

layout(std430, binding = 0) buffer B {
  df_double r[];
};


void main()
{
  df_dvec4 v = df_make_dvec4_1_1_1_1(r[0], r[1], r[2], r[3]);
  df_assign_dvec4_z(v, df_double(7.0 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]));
  df_assign_dvec4_zw(v, df_add_f(df_dvec2(v.hi.zw, v.lo.zw), vec2(1.0, 2.0)));
  df_assign_dvec4_y(v, df_mul_f2(df_double(v.hi.y, v.lo.y), 3.0));
  df_assign_dvec4_w(v, df_add_f(df_double(v.hi.w, v.lo.w), 1.0));
  r[4] = df_add(df_add(df_add(df_double(v.hi.x, v.lo.x), df_double(v.hi.y, v.lo.y)), df_double(v.hi.z, v.lo.z)), df_double(v.hi.w, v.lo.w));
}
