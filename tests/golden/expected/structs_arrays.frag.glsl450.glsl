#version 450 core
precision highp float;
precision highp int;

struct df_dmat2 {
  mat2 hi;
  mat2 lo;
};
// doublet float-float runtime: 22 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct Inner {
  df_double w;
  df_dvec2 uv;
};
struct Outer {
  Inner inner;
  df_double scale[2];
  df_dmat2 m;
};

uniform Outer params;

uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec2 df_two_sum(vec2 a, vec2 b) {
  precise vec2 s = (a + b);
  precise vec2 bb = (s - a);
  precise vec2 ab = (s - bb);
  precise vec2 da = (a - ab);
  precise vec2 db = (b - bb);
  precise vec2 e = (da + db);
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
  precise vec2 s = (a + b);
  precise vec2 z = (s - a);
  precise vec2 e = (b - z);
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
df_dvec2 df_add(df_dvec2 a, df_dvec2 b) {
  df_dvec2 s = df_two_sum(a.hi, b.hi);
  df_dvec2 t = df_two_sum(a.lo, b.lo);
  precise vec2 c = (s.lo + t.hi);
  df_dvec2 v = df_fast_two_sum(s.hi, c);
  precise vec2 w = (t.lo + v.lo);
  df_dvec2 z = df_fast_two_sum(v.hi, w);
  df_dvec2 r = df_finish(z, s.hi);
  return r;
}

// df_from_int: exact for every 32-bit int i.
// Algorithm: 16-bit split of the integer, then TwoSum
// Steps: i = q*65536 + r with q = i/65536, r = i - q*65536 (integer ops, exact);
//   float(q)*65536 and float(r) are exact floats (|q| <= 32768, |r| < 65536), and TwoSum
//   of them is the exact double-word of i (i has at most 32 significant bits <= 48).
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (TwoSum)
// Bound: exact
// Flops: 7 (plus 2 integer ops and 2 conversions)
// Works whatever the rounding of integer division, as long as |q| <= 32768.
df_double df_from_int(int i) {
  int q = i / 65536;
  int r = i - q * 65536;
  precise float qf = (float(q) * 65536.0);
  precise float rf = (float(r));
  df_double z = df_two_sum(qf, rf);
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
df_dvec2 df_split(vec2 a) {
  uvec2 bits = floatBitsToUint(a);
  precise vec2 hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  precise vec2 lo = (a - hi);
  return df_dvec2(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
vec2 df_mul12_error(df_dvec2 sa, df_dvec2 sb, vec2 p) {
  precise vec2 hh = (sa.hi * sb.hi);
  precise vec2 hl = (sa.hi * sb.lo);
  precise vec2 lh = (sa.lo * sb.hi);
  precise vec2 ll = (sa.lo * sb.lo);
  precise vec2 t1 = (hh - p);
  precise vec2 t2 = (t1 + hl);
  precise vec2 t3 = (t2 + lh);
  precise vec2 e = (t3 + ll);
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
df_dvec2 df_two_prod(vec2 a, vec2 b) {
  precise vec2 p = (a * b);
  df_dvec2 sa = df_split(a);
  df_dvec2 sb = df_split(b);
  precise vec2 e = (df_mul12_error(sa, sb, p));
  return df_dvec2(p, e);
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
df_dvec2 df_mul(df_dvec2 a, df_dvec2 b) {
  df_dvec2 c = df_two_prod(a.hi, b.hi);
  precise vec2 tl = (a.hi * b.lo);
  precise vec2 th = (a.lo * b.hi);
  precise vec2 cl2 = (th + tl);
  precise vec2 cl3 = (c.lo + cl2);
  df_dvec2 z = df_fast_two_sum(c.hi, cl3);
  df_dvec2 r = df_finish(z, c.hi);
  return r;
}

// df_dot: a.x*b.x + a.y*b.y.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 10u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 79
df_double df_dot(df_dvec2 a, df_dvec2 b) {
  df_dvec2 m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_add(x, y);
  return z;
}

// df_to_int: truncation toward zero, exact for every double-word whose truncation fits in int.
// Algorithm: truncate hi, correct by floor/ceil of lo when hi is an integer
// Steps: t = trunc(hi) = sign(hi)*floor(|hi|) (exact). If hi is not an integer,
//   |lo| <= ulp(hi)/2 < distance from hi to the nearest integer, so trunc(hi+lo) = t.
//   If hi is an integer, trunc(hi+lo) = hi + floor(lo) for hi > 0 and hi + ceil(lo) for
//   hi < 0, i.e. t + adj with adj = s*floor(s*lo), s = sign(hi) (lo = 0 when hi = 0).
//   t can be 2^31 when the answer is 2^31 - k (hi rounds up), so t is not converted
//   directly: h = int(t/2) (exact, |h| <= 2^30), e = t - 2h in {-1,0,1}, and the result is
//   h + (int(e + adj) + h), which never overflows when the answer fits.
// Source: JMP 2017, Definition 1.4 (abs(lo) <= ulp(hi)/2); Sterbenz 1974 (exact hi - t)
// Bound: exact
// Flops: 15 (float, including sign/abs/floor/step; plus 3 conversions and 2 integer adds)
int df_to_int(df_double a) {
  precise float s = (sign(a.hi));
  precise float ah = (abs(a.hi));
  precise float fh = (floor(ah));
  precise float t = (s * fh);
  precise float d = (a.hi - t);
  precise float ad = (abs(d));
  precise float m = (step(ad, float(0.0)));
  precise float sl = (s * a.lo);
  precise float fl = (floor(sl));
  precise float adj0 = (s * fl);
  precise float adj = (adj0 * m);
  precise float th = (t * 0.5);
  int h = int(th);
  precise float h2 = (float(h) * 2.0);
  precise float e = (t - h2);
  precise float ea = (e + adj);
  int k = int(ea);
  int hk = h + k;
  int z = hk + h;
  return z;
}

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_gt(df_double a, df_double b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo > b.lo))));
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

// df_add_f: a + b with b a plain float (b need not be a double-word).
// Algorithm: DWPlusFP (JMP Algorithm 4), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,b); v = RN(al+sl); (zh,zl) = Fast2Sum(sh,v); df_finish(z, sh).
df_double df_add_f(df_double a, float b) {
  df_double s = df_two_sum(a.hi, b);
  precise float v = (a.lo + s.lo);
  df_double z = df_fast_two_sum(s.hi, v);
  df_double r = df_finish(z, s.hi);
  return r;
}

df_dvec2 df_make_dvec2_1_1(df_double a0, df_double a1) {
  return df_dvec2(vec2(a0.hi, a1.hi), vec2(a0.lo, a1.lo));
}

df_dmat2 df_diagonal_dmat2(df_double s) {
  return df_dmat2(mat2(s.hi), mat2(s.lo));
}

// df_mul_dmat2_dvec2: (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise
// AccurateDWPlusDW). Bound: 10u^2 * sum_j |m[j][i] v[j]| per component (absolute).
df_dvec2 df_mul_dmat2_dvec2(df_dmat2 m, df_dvec2 v) {
  df_double p0 = df_dot(df_dvec2(vec2(m.hi[0][0], m.hi[1][0]), vec2(m.lo[0][0], m.lo[1][0])), v);
  df_double p1 = df_dot(df_dvec2(vec2(m.hi[0][1], m.hi[1][1]), vec2(m.lo[0][1], m.lo[1][1])), v);
  return df_dvec2(vec2(p0.hi, p1.hi), vec2(p0.lo, p1.lo));
}

flat in float depth_hi;
flat in float depth_lo;
df_double depth;
flat in int k;
out vec4 color;
const df_double kTable[3] = df_double[3](df_double(0.5, 0.0), df_double(0.25, 0.0), df_double(0.125, 0.0));

df_double twice(df_double x);
df_dvec2 twice(df_dvec2 x);
Outer make(df_double s);

df_double twice(df_double x)
{
  return df_add(x, x);
}

df_dvec2 twice(df_dvec2 x)
{
  return df_add(x, x);
}

Outer make(df_double s)
{
  Outer o;
  o.inner = Inner(s, df_make_dvec2_1_1(s, df_double(1.0, 0.0)));
  o.scale[0] = s;
  o.scale[1] = twice(s);
  o.m = df_diagonal_dmat2(s);
  return o;
}

void main()
{
  depth = df_double(depth_hi, depth_lo);
  df_double acc[4];
  Outer o = make(depth);
  for (int i = 0; i < 4; ++i)
  {
    acc[i] = df_mul(df_from_int(i), o.scale[i % 2]);
  }
  acc[k] = df_add(acc[k], df_add(df_double[3](df_double(0.5, 0.0), df_double(0.25, 0.0), df_double(0.125, 0.0))[k % 3], df_double(params.scale[1].hi - df_guard[int(df_guard[1])], params.scale[1].lo - df_guard[int(df_guard[1])])));
  df_dvec2 t = df_add(df_add(df_add(twice(o.inner.uv), df_dvec2(o.m.hi[1], o.m.lo[1])), df_mul_dmat2_dvec2(o.m, o.inner.uv)), df_dvec2(params.inner.uv.hi - df_guard[int(df_guard[1])], params.inner.uv.lo - df_guard[int(df_guard[1])]));
  df_double s = df_add(df_add(df_add(df_add(acc[0], acc[1]), acc[2]), acc[3]), df_mul(o.inner.w, df_double(t.hi.x, t.lo.x)));
  switch (df_to_int(s))
  {
  case 0:
    {
      s = df_add_f(s, 1.0);
      break;
    }
  default:
    {
      break;
    }
  }
  if (df_gt(s, df_double(1.0, 0.0)))
  {
    discard;
  }
  color = vec4(df_to_float(s), df_to_float(df_double(t.hi.y, t.lo.y)), 0.25, 1.0);
}
