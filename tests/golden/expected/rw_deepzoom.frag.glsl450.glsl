#version 450 core
precision highp float;
precision highp int;

uniform vec2 center_hi;
uniform vec2 center_lo;
uniform float scale_hi;
uniform float scale_lo;
uniform vec2 resolution;

// doublet float-float runtime: 26 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_from_float: the exact double-word (f, 0).
// Algorithm: hi = f, lo = 0
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0
df_double df_from_float(float f) {
  return df_double(f, float(0.0));
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
  precise float cl2 = (a.lo * b);
  df_double t = df_fast_two_sum(c.hi, cl2);
  precise float tl2 = (t.lo + c.lo);
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
  precise float th = (a.hi / b.hi);
  df_double r = df_mul_f(b, th);
  precise float pih = (a.hi - r.hi);
  precise float dl = (a.lo - r.lo);
  precise float d = (pih + dl);
  precise float tl = (d / b.hi);
  df_double z = df_fast_two_sum(th, tl);
  df_double q = df_finish(z, th);
  return q;
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

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_gt(df_double a, df_double b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo > b.lo))));
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
df_dvec2 df_mul_f2(df_dvec2 a, vec2 b) {
  df_dvec2 c = df_two_prod(a.hi, b);
  precise vec2 cl2 = (a.lo * b);
  precise vec2 cl3 = (c.lo + cl2);
  df_dvec2 z = df_fast_two_sum(c.hi, cl3);
  df_dvec2 r = df_finish(z, c.hi);
  return r;
}

// df_mul_pow2: a * p where every component of p is a power of two (+-2^k), exact: scaling by a
// power of two only changes exponents, so hi*p and lo*p are exact and (hi*p, lo*p) is still a
// double-word number. Replaces df_mul (29 flops) and df_div by a power of two.
// Algorithm: exact scaling of both words by a power of two, then df_finish
// Source: HFPA (2018), section 2.2 (multiplication by a power of the radix is exact); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// Range: exact while lo*p stays normal (|lo*p| >= 2^-126) and hi*p does not overflow; an
// overflowing, zero or NaN hi*p gives (hi*p, 0) as df_mul does (df_finish).
df_double df_mul_pow2(df_double a, float p) {
  precise float h = (a.hi * p);
  precise float l = (a.lo * p);
  df_double r = df_finish(df_double(h, l), h);
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
df_double df_sqr(df_double a) {
  precise float p = (a.hi * a.hi);
  df_double s = df_split(a.hi);
  precise float hh = (s.hi * s.hi);
  precise float hl = (s.hi * s.lo);
  precise float hl2 = (hl + hl);
  precise float ll = (s.lo * s.lo);
  precise float t1 = (hh - p);
  precise float t2 = (t1 + hl2);
  precise float e = (t2 + ll);
  precise float c = (a.hi * a.lo);
  precise float c2 = (c + c);
  precise float cl3 = (e + c2);
  df_double z = df_fast_two_sum(p, cl3);
  df_double r = df_finish(z, p);
  return r;
}

df_dvec2 df_make_dvec2_1_1(df_double a0, df_double a1) {
  return df_dvec2(vec2(a0.hi, a1.hi), vec2(a0.lo, a1.lo));
}

df_dvec2 df_splat_dvec2(df_double s) {
  return df_dvec2(vec2(s.hi), vec2(s.lo));
}

df_dvec2 center;
df_double scale;
uniform sampler2D palette;
in vec2 v_uv;
df_double pixel_size;
int escaped_at = 0;
layout(location = 0) out highp vec4 df_frag_color;

bool iterate(inout df_dvec2 z, df_dvec2 c);

bool iterate(inout df_dvec2 z, df_dvec2 c)
{
  z = df_add(df_make_dvec2_1_1(df_sub(df_sqr(df_double(z.hi.x, z.lo.x)), df_sqr(df_double(z.hi.y, z.lo.y))), df_mul(df_mul_pow2(df_double(z.hi.x, z.lo.x), 2.0), df_double(z.hi.y, z.lo.y))), c);
  return df_gt(df_dot(z, z), df_double(4.0, 0.0));
}

void main()
{
  center = df_dvec2(center_hi - df_guard[int(df_guard[1])], center_lo - df_guard[int(df_guard[1])]);
  scale = df_double(scale_hi - df_guard[int(df_guard[1])], scale_lo - df_guard[int(df_guard[1])]);
  pixel_size = df_div(scale, df_from_float(resolution.y));
  df_dvec2 c = df_add(center, df_mul_f2(df_splat_dvec2(pixel_size), gl_FragCoord.xy - 0.5 * resolution));
  df_dvec2 z = df_dvec2(vec2(0.0), vec2(0.0));
  for (int n = 0; n < 256; n++)
  {
    if (iterate(z, c))
    {
      escaped_at = n;
      break;
    }
  }
  df_frag_color = texture(palette, vec2(float(escaped_at) / 256.0, 0.5)) * float(v_uv.x >= 0.0);
}
