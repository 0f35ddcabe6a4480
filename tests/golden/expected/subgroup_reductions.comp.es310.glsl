#version 310 es
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_shuffle : require
#extension GL_KHR_shader_subgroup_arithmetic : enable
#extension GL_KHR_shader_subgroup_basic : enable
#extension GL_KHR_shader_subgroup_clustered : enable
precision highp float;
precision highp int;
layout(local_size_x = 16, local_size_y = 1, local_size_z = 1) in;

struct df_dvec4 {
  vec4 hi;
  vec4 lo;
};
// doublet float-float runtime: 35 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_gt(df_double a, df_double b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo > b.lo))));
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec3 df_two_sum(vec3 a, vec3 b) {
  vec3 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec3 bb = ((s - a) - df_guard[int(df_guard[1])]);
  vec3 ab = (s - bb);
  vec3 da = (a - ab);
  vec3 db = (b - bb);
  vec3 e = (da + db);
  return df_dvec3(s, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec3 df_fast_two_sum(vec3 a, vec3 b) {
  vec3 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec3 z = ((s - a) - df_guard[int(df_guard[1])]);
  vec3 e = (b - z);
  return df_dvec3(s, e);
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

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
// (width 3: the width-1 df_finish applied to each component)
df_dvec3 df_finish(df_dvec3 z, vec3 f) {
  df_double r0 = df_finish(df_double(z.hi.x, z.lo.x), f.x);
  df_double r1 = df_finish(df_double(z.hi.y, z.lo.y), f.y);
  df_double r2 = df_finish(df_double(z.hi.z, z.lo.z), f.z);
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
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
df_dvec3 df_add(df_dvec3 a, df_dvec3 b) {
  df_dvec3 s = df_two_sum(a.hi, b.hi);
  df_dvec3 t = df_two_sum(a.lo, b.lo);
  vec3 c = (s.lo + t.hi);
  df_dvec3 v = df_fast_two_sum(s.hi, c);
  vec3 w = (t.lo + v.lo);
  df_dvec3 z = df_fast_two_sum(v.hi, w);
  df_dvec3 r = df_finish(z, s.hi);
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
df_dvec3 df_split(vec3 a) {
  uvec3 bits = floatBitsToUint(a);
  vec3 hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  vec3 lo = (a - hi);
  return df_dvec3(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
vec3 df_mul12_error(df_dvec3 sa, df_dvec3 sb, vec3 p) {
  vec3 hh = (sa.hi * sb.hi);
  vec3 hl = (sa.hi * sb.lo);
  vec3 lh = (sa.lo * sb.hi);
  vec3 ll = (sa.lo * sb.lo);
  vec3 t1 = (hh - p);
  vec3 t2 = (t1 + hl);
  vec3 t3 = (t2 + lh);
  vec3 e = (t3 + ll);
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
df_dvec3 df_two_prod(vec3 a, vec3 b) {
  vec3 p = ((a * b) - df_guard[int(df_guard[1])]);
  df_dvec3 sa = df_split(a);
  df_dvec3 sb = df_split(b);
  vec3 e = (df_mul12_error(sa, sb, p));
  return df_dvec3(p, e);
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
df_dvec3 df_mul(df_dvec3 a, df_dvec3 b) {
  df_dvec3 c = df_two_prod(a.hi, b.hi);
  vec3 tl = (a.hi * b.lo);
  vec3 th = (a.lo * b.hi);
  vec3 cl2 = (th + tl);
  vec3 cl3 = (c.lo + cl2);
  df_dvec3 z = df_fast_two_sum(c.hi, cl3);
  df_dvec3 r = df_finish(z, c.hi);
  return r;
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_dvec3 df_neg(df_dvec3 a) {
  vec3 h = (-a.hi);
  vec3 l = (-a.lo);
  return df_dvec3(h, l);
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 23
df_dvec3 df_sub(df_dvec3 a, df_dvec3 b) {
  df_dvec3 nb = df_neg(b);
  df_dvec3 z = df_add(a, nb);
  return z;
}

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

// df_lt: a < b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_lt(df_double a, df_double b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo < b.lo))));
}

// df_select: c ? a : b per component, without a branch (mix on a boolean selector, a
// ternary on ES 1.00). Every rule with a data-dependent choice between pairs goes through it: an
// early return or a short-circuit inside a rule that is inlined into a loop body multiplies the
// control flow the browser's shader compilers have to handle (docs/performance.md, "Compile time in
// the browser").
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBType)
// Bound: exact
// Flops: 0
df_double df_select(bool c, df_double a, df_double b) {
  float h = (mix(b.hi, a.hi, c));
  float l = (mix(b.lo, a.lo, c));
  return df_double(h, l);
}

// df_min: component-wise min(a, b) = b < a ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (min); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
df_double df_min(df_double a, df_double b) {
  bool take = df_lt(b, a);
  df_double r = df_select(take, b, a);
  return r;
}

// df_min: component-wise min(a, b) = b < a ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (min); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 2: the width-1 df_min applied to each component)
df_dvec2 df_min(df_dvec2 a, df_dvec2 b) {
  df_double r0 = df_min(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  df_double r1 = df_min(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

// df_max: component-wise max(a, b) = a < b ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (max); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
df_double df_max(df_double a, df_double b) {
  bool take = df_lt(a, b);
  df_double r = df_select(take, b, a);
  return r;
}

// df_max: component-wise max(a, b) = a < b ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (max); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 2: the width-1 df_max applied to each component)
df_dvec2 df_max(df_dvec2 a, df_dvec2 b) {
  df_double r0 = df_max(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  df_double r1 = df_max(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_dvec2 df_neg(df_dvec2 a) {
  vec2 h = (-a.hi);
  vec2 l = (-a.lo);
  return df_dvec2(h, l);
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
  vec2 c = (s.lo + t.hi);
  df_dvec2 v = df_fast_two_sum(s.hi, c);
  vec2 w = (t.lo + v.lo);
  df_dvec2 z = df_fast_two_sum(v.hi, w);
  df_dvec2 r = df_finish(z, s.hi);
  return r;
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 23
df_dvec2 df_sub(df_dvec2 a, df_dvec2 b) {
  df_dvec2 nb = df_neg(b);
  df_dvec2 z = df_add(a, nb);
  return z;
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

// df_mul_pow2: a * p where every component of p is a power of two (+-2^k), exact: scaling by a
// power of two only changes exponents, so hi*p and lo*p are exact and (hi*p, lo*p) is still a
// double-word number. Replaces df_mul (29 flops) and df_div by a power of two.
// Algorithm: exact scaling of both words by a power of two, then df_finish
// Source: HFPA (2018), section 2.2 (multiplication by a power of the radix is exact); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// Range: exact while lo*p stays normal (|lo*p| >= 2^-126) and hi*p does not overflow; an
// overflowing, zero or NaN hi*p gives (hi*p, 0) as df_mul does (df_finish).
df_dvec3 df_mul_pow2(df_dvec3 a, vec3 p) {
  vec3 h = (a.hi * p);
  vec3 l = (a.lo * p);
  df_dvec3 r = df_finish(df_dvec3(h, l), h);
  return r;
}

df_dvec3 df_subgroupAdd_3(df_dvec3 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec3 r = df_dvec3(vec3(0.0), vec3(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec3 x = df_dvec3(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (true) {
      r = started ? df_add(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec3 df_subgroupInclusiveAdd_3(df_dvec3 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec3 r = df_dvec3(vec3(0.0), vec3(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec3 x = df_dvec3(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j <= self) {
      r = started ? df_add(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec3 df_subgroupExclusiveAdd_3(df_dvec3 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec3 r = df_dvec3(vec3(0.0), vec3(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec3 x = df_dvec3(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j < self) {
      r = started ? df_add(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec3 df_splat_dvec3(df_double s) {
  return df_dvec3(vec3(s.hi), vec3(s.lo));
}

df_double df_subgroupMul_1(df_double v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_double r = df_double(float(1.0), float(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_double x = df_double(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (true) {
      r = started ? df_mul(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_double df_subgroupExclusiveMul_1(df_double v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_double r = df_double(float(1.0), float(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_double x = df_double(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j < self) {
      r = started ? df_mul(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupMin_2(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(uintBitsToFloat(0x7F800000u)), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (true) {
      r = started ? df_min(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupInclusiveMax_2(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(uintBitsToFloat(0xFF800000u)), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j <= self) {
      r = started ? df_max(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupExclusiveMin_2(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(uintBitsToFloat(0x7F800000u)), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j < self) {
      r = started ? df_min(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupMax_2(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(uintBitsToFloat(0xFF800000u)), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (true) {
      r = started ? df_max(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupClusteredAdd_2_4u(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(0.0), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j / 4u == self / 4u) {
      r = started ? df_add(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_subgroupClusteredMin_2_2u(df_dvec2 v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_dvec2 r = df_dvec2(vec2(uintBitsToFloat(0x7F800000u)), vec2(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_dvec2 x = df_dvec2(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j / 2u == self / 2u) {
      r = started ? df_min(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_double df_subgroupClusteredMax_1_8u(df_double v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_double r = df_double(float(uintBitsToFloat(0xFF800000u)), float(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_double x = df_double(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j / 8u == self / 8u) {
      r = started ? df_max(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_double df_subgroupClusteredMul_1_2u(df_double v) {
  uvec4 lanes = subgroupBallot(true);
  uint self = gl_SubgroupInvocationID;
  df_double r = df_double(float(1.0), float(0.0));
  bool started = false;
  for (uint j = 0u; j < gl_SubgroupSize; ++j) {
    if (!subgroupBallotBitExtract(lanes, j)) continue;
    df_double x = df_double(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));
    if (j / 2u == self / 2u) {
      r = started ? df_mul(r, x) : x;
      started = true;
    }
  }
  return r;
}

df_dvec2 df_splat_dvec2(df_double s) {
  return df_dvec2(vec2(s.hi), vec2(s.lo));
}

layout(std430, binding = 0) buffer Data {
  df_dvec4 x[];
};
layout(std430, binding = 1) buffer Results {
  df_dvec3 r[];
};
layout(std430, binding = 2) buffer More {
  df_dvec2 s[];
};


void main()
{
  uint i = gl_GlobalInvocationID.x;
  df_dvec3 v = df_dvec3(x[i].hi.xyz, x[i].lo.xyz);
  df_double y = df_double(x[i].hi.w, x[i].lo.w);
  if (df_gt(y, df_double(0.5 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])])))
  {
    return;
  }
  r[i] = df_sub(df_add(df_subgroupAdd_3(v), df_subgroupInclusiveAdd_3(v)), df_mul_pow2(df_subgroupExclusiveAdd_3(v), vec3(0.5)));
  df_double m = df_add(df_subgroupMul_1(df_add_f(y, 1.0)), df_subgroupExclusiveMul_1(y));
  df_dvec2 mm = df_sub(df_add(df_sub(df_subgroupMin_2(df_dvec2(v.hi.xy, v.lo.xy)), df_subgroupInclusiveMax_2(df_dvec2(v.hi.yz, v.lo.yz))), df_subgroupExclusiveMin_2(df_dvec2(v.hi.zx, v.lo.zx))), df_subgroupMax_2(df_dvec2(v.hi.xy, v.lo.xy)));
  mm = df_add(mm, df_add(df_subgroupClusteredAdd_2_4u(df_dvec2(v.hi.yx, v.lo.yx)), df_subgroupClusteredMin_2_2u(df_dvec2(v.hi.zy, v.lo.zy))));
  m = df_sub(m, df_mul(df_subgroupClusteredMax_1_8u(y), df_subgroupClusteredMul_1_2u(df_double(v.hi.x, v.lo.x))));
  s[i] = df_add(mm, df_splat_dvec2(m));
}
