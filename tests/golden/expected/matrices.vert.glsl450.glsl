#version 450 core
precision highp float;
precision highp int;

uniform mat4 model_hi;
uniform mat4 model_lo;
uniform mat3 normal_basis_hi;
uniform mat3 normal_basis_lo;
uniform mat2 warp_hi[2];
uniform mat2 warp_lo[2];
uniform int column;

struct df_dmat2 {
  mat2 hi;
  mat2 lo;
};
struct df_dmat3 {
  mat3 hi;
  mat3 lo;
};
struct df_dmat4 {
  mat4 hi;
  mat4 lo;
};
// doublet float-float runtime: 47 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
struct df_dvec4 { vec4 hi; vec4 lo; };
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
df_dvec3 df_split(vec3 a) {
  uvec3 bits = floatBitsToUint(a);
  precise vec3 hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  precise vec3 lo = (a - hi);
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
  precise vec3 hh = (sa.hi * sb.hi);
  precise vec3 hl = (sa.hi * sb.lo);
  precise vec3 lh = (sa.lo * sb.hi);
  precise vec3 ll = (sa.lo * sb.lo);
  precise vec3 t1 = (hh - p);
  precise vec3 t2 = (t1 + hl);
  precise vec3 t3 = (t2 + lh);
  precise vec3 e = (t3 + ll);
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
  precise vec3 p = (a * b);
  df_dvec3 sa = df_split(a);
  df_dvec3 sb = df_split(b);
  precise vec3 e = (df_mul12_error(sa, sb, p));
  return df_dvec3(p, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec3 df_fast_two_sum(vec3 a, vec3 b) {
  precise vec3 s = (a + b);
  precise vec3 z = (s - a);
  precise vec3 e = (b - z);
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
  precise float az = (abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  precise float h = (mix(f, z.hi, regular));
  precise float l = (mix(0.0, z.lo, regular));
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
  precise vec3 tl = (a.hi * b.lo);
  precise vec3 th = (a.lo * b.hi);
  precise vec3 cl2 = (th + tl);
  precise vec3 cl3 = (c.lo + cl2);
  df_dvec3 z = df_fast_two_sum(c.hi, cl3);
  df_dvec3 r = df_finish(z, c.hi);
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
df_dvec4 df_split(vec4 a) {
  uvec4 bits = floatBitsToUint(a);
  precise vec4 hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  precise vec4 lo = (a - hi);
  return df_dvec4(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
vec4 df_mul12_error(df_dvec4 sa, df_dvec4 sb, vec4 p) {
  precise vec4 hh = (sa.hi * sb.hi);
  precise vec4 hl = (sa.hi * sb.lo);
  precise vec4 lh = (sa.lo * sb.hi);
  precise vec4 ll = (sa.lo * sb.lo);
  precise vec4 t1 = (hh - p);
  precise vec4 t2 = (t1 + hl);
  precise vec4 t3 = (t2 + lh);
  precise vec4 e = (t3 + ll);
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
df_dvec4 df_two_prod(vec4 a, vec4 b) {
  precise vec4 p = (a * b);
  df_dvec4 sa = df_split(a);
  df_dvec4 sb = df_split(b);
  precise vec4 e = (df_mul12_error(sa, sb, p));
  return df_dvec4(p, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec4 df_fast_two_sum(vec4 a, vec4 b) {
  precise vec4 s = (a + b);
  precise vec4 z = (s - a);
  precise vec4 e = (b - z);
  return df_dvec4(s, e);
}

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
// (width 4: the width-1 df_finish applied to each component)
df_dvec4 df_finish(df_dvec4 z, vec4 f) {
  df_double r0 = df_finish(df_double(z.hi.x, z.lo.x), f.x);
  df_double r1 = df_finish(df_double(z.hi.y, z.lo.y), f.y);
  df_double r2 = df_finish(df_double(z.hi.z, z.lo.z), f.z);
  df_double r3 = df_finish(df_double(z.hi.w, z.lo.w), f.w);
  return df_dvec4(vec4(r0.hi, r1.hi, r2.hi, r3.hi), vec4(r0.lo, r1.lo, r2.lo, r3.lo));
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
df_dvec4 df_mul(df_dvec4 a, df_dvec4 b) {
  df_dvec4 c = df_two_prod(a.hi, b.hi);
  precise vec4 tl = (a.hi * b.lo);
  precise vec4 th = (a.lo * b.hi);
  precise vec4 cl2 = (th + tl);
  precise vec4 cl3 = (c.lo + cl2);
  df_dvec4 z = df_fast_two_sum(c.hi, cl3);
  df_dvec4 r = df_finish(z, c.hi);
  return r;
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

// df_dot: (a.x*b.x + a.y*b.y) + (a.z*b.z + a.w*b.w), pairwise.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then 3 AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 13u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 179
df_double df_dot(df_dvec4 a, df_dvec4 b) {
  df_dvec4 m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_double(m.hi.z, m.lo.z);
  df_double w = df_double(m.hi.w, m.lo.w);
  df_double xy = df_add(x, y);
  df_double zw = df_add(z, w);
  df_double r = df_add(xy, zw);
  return r;
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec4 df_two_sum(vec4 a, vec4 b) {
  precise vec4 s = (a + b);
  precise vec4 bb = (s - a);
  precise vec4 ab = (s - bb);
  precise vec4 da = (a - ab);
  precise vec4 db = (b - bb);
  precise vec4 e = (da + db);
  return df_dvec4(s, e);
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
df_dvec4 df_add(df_dvec4 a, df_dvec4 b) {
  df_dvec4 s = df_two_sum(a.hi, b.hi);
  df_dvec4 t = df_two_sum(a.lo, b.lo);
  precise vec4 c = (s.lo + t.hi);
  df_dvec4 v = df_fast_two_sum(s.hi, c);
  precise vec4 w = (t.lo + v.lo);
  df_dvec4 z = df_fast_two_sum(v.hi, w);
  df_dvec4 r = df_finish(z, s.hi);
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

// df_mul_f: a * b with b a plain float.
// Algorithm: DWTimesFP1 (JMP Algorithm 7) with Dekker's TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 4.1
// Bound: 1.5u^2 + 4u^3
// Flops: 30
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); (th,tl1) = Fast2Sum(ch,cl2);
//        tl2 = RN(tl1+cl1); (zh,zl) = Fast2Sum(th,tl2); df_finish(z, ch).
// Range: any finite operands whose product is within float range (TwoProd scales them).
df_dvec3 df_mul_f(df_dvec3 a, vec3 b) {
  df_dvec3 c = df_two_prod(a.hi, b);
  precise vec3 cl2 = (a.lo * b);
  df_dvec3 t = df_fast_two_sum(c.hi, cl2);
  precise vec3 tl2 = (t.lo + c.lo);
  df_dvec3 z = df_fast_two_sum(t.hi, tl2);
  df_dvec3 r = df_finish(z, c.hi);
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
df_dvec3 df_div(df_dvec3 a, df_dvec3 b) {
  precise vec3 th = (a.hi / b.hi);
  df_dvec3 r = df_mul_f(b, th);
  precise vec3 pih = (a.hi - r.hi);
  precise vec3 dl = (a.lo - r.lo);
  precise vec3 d = (pih + dl);
  precise vec3 tl = (d / b.hi);
  df_dvec3 z = df_fast_two_sum(th, tl);
  df_dvec3 q = df_finish(z, th);
  return q;
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_dvec3 df_neg(df_dvec3 a) {
  precise vec3 h = (-a.hi);
  precise vec3 l = (-a.lo);
  return df_dvec3(h, l);
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec3 df_two_sum(vec3 a, vec3 b) {
  precise vec3 s = (a + b);
  precise vec3 bb = (s - a);
  precise vec3 ab = (s - bb);
  precise vec3 da = (a - ab);
  precise vec3 db = (b - bb);
  precise vec3 e = (da + db);
  return df_dvec3(s, e);
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
  precise vec3 c = (s.lo + t.hi);
  df_dvec3 v = df_fast_two_sum(s.hi, c);
  precise vec3 w = (t.lo + v.lo);
  df_dvec3 z = df_fast_two_sum(v.hi, w);
  df_dvec3 r = df_finish(z, s.hi);
  return r;
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

// df_from_float: the exact double-word (f, 0).
// Algorithm: hi = f, lo = 0
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0
df_dvec3 df_from_float(vec3 f) {
  return df_dvec3(f, vec3(0.0));
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

// df_mul_f: a * b with b a plain float.
// Algorithm: DWTimesFP1 (JMP Algorithm 7) with Dekker's TwoProd, then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 4.1
// Bound: 1.5u^2 + 4u^3
// Flops: 30
// Steps: (ch,cl1) = TwoProd(ah,b); cl2 = RN(al*b); (th,tl1) = Fast2Sum(ch,cl2);
//        tl2 = RN(tl1+cl1); (zh,zl) = Fast2Sum(th,tl2); df_finish(z, ch).
// Range: any finite operands whose product is within float range (TwoProd scales them).
df_dvec2 df_mul_f(df_dvec2 a, vec2 b) {
  df_dvec2 c = df_two_prod(a.hi, b);
  precise vec2 cl2 = (a.lo * b);
  df_dvec2 t = df_fast_two_sum(c.hi, cl2);
  precise vec2 tl2 = (t.lo + c.lo);
  df_dvec2 z = df_fast_two_sum(t.hi, tl2);
  df_dvec2 r = df_finish(z, c.hi);
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
df_dvec2 df_div(df_dvec2 a, df_dvec2 b) {
  precise vec2 th = (a.hi / b.hi);
  df_dvec2 r = df_mul_f(b, th);
  precise vec2 pih = (a.hi - r.hi);
  precise vec2 dl = (a.lo - r.lo);
  precise vec2 d = (pih + dl);
  precise vec2 tl = (d / b.hi);
  df_dvec2 z = df_fast_two_sum(th, tl);
  df_dvec2 q = df_finish(z, th);
  return q;
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

// df_dot: (a.x*b.x + a.y*b.y) + a.z*b.z.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then 2 AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 13u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 129
df_double df_dot(df_dvec3 a, df_dvec3 b) {
  df_dvec3 m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_double(m.hi.z, m.lo.z);
  df_double xy = df_add(x, y);
  df_double r = df_add(xy, z);
  return r;
}

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
vec4 df_to_float(df_dvec4 a) {
  precise vec4 f = (a.hi + a.lo);
  df_dvec4 r = df_finish(df_dvec4(f, vec4(0.0)), a.hi);
  return r.hi;
}

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
vec3 df_to_float(df_dvec3 a) {
  precise vec3 f = (a.hi + a.lo);
  df_dvec3 r = df_finish(df_dvec3(f, vec3(0.0)), a.hi);
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

// df_mul_dmat3_double: df_mul on each element (column by column), so each element has df_mul's bound (rules/arith.glsl).
df_dmat3 df_mul_dmat3_double(df_dmat3 a, df_double b) {
  df_dvec3 c0 = df_mul(df_dvec3(a.hi[0], a.lo[0]), df_dvec3(vec3(b.hi), vec3(b.lo)));
  df_dvec3 c1 = df_mul(df_dvec3(a.hi[1], a.lo[1]), df_dvec3(vec3(b.hi), vec3(b.lo)));
  df_dvec3 c2 = df_mul(df_dvec3(a.hi[2], a.lo[2]), df_dvec3(vec3(b.hi), vec3(b.lo)));
  return df_dmat3(mat3(c0.hi, c1.hi, c2.hi), mat3(c0.lo, c1.lo, c2.lo));
}

// df_transpose_dmat4: exact (words moved).
df_dmat4 df_transpose_dmat4(df_dmat4 m) {
  return df_dmat4(mat4(m.hi[0][0], m.hi[1][0], m.hi[2][0], m.hi[3][0], m.hi[0][1], m.hi[1][1], m.hi[2][1], m.hi[3][1], m.hi[0][2], m.hi[1][2], m.hi[2][2], m.hi[3][2], m.hi[0][3], m.hi[1][3], m.hi[2][3], m.hi[3][3]), mat4(m.lo[0][0], m.lo[1][0], m.lo[2][0], m.lo[3][0], m.lo[0][1], m.lo[1][1], m.lo[2][1], m.lo[3][1], m.lo[0][2], m.lo[1][2], m.lo[2][2], m.lo[3][2], m.lo[0][3], m.lo[1][3], m.lo[2][3], m.lo[3][3]));
}

// df_mul_dmat4_dvec4: (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise
// AccurateDWPlusDW). Bound: 13u^2 * sum_j |m[j][i] v[j]| per component (absolute).
df_dvec4 df_mul_dmat4_dvec4(df_dmat4 m, df_dvec4 v) {
  df_double p0 = df_dot(df_dvec4(vec4(m.hi[0][0], m.hi[1][0], m.hi[2][0], m.hi[3][0]), vec4(m.lo[0][0], m.lo[1][0], m.lo[2][0], m.lo[3][0])), v);
  df_double p1 = df_dot(df_dvec4(vec4(m.hi[0][1], m.hi[1][1], m.hi[2][1], m.hi[3][1]), vec4(m.lo[0][1], m.lo[1][1], m.lo[2][1], m.lo[3][1])), v);
  df_double p2 = df_dot(df_dvec4(vec4(m.hi[0][2], m.hi[1][2], m.hi[2][2], m.hi[3][2]), vec4(m.lo[0][2], m.lo[1][2], m.lo[2][2], m.lo[3][2])), v);
  df_double p3 = df_dot(df_dvec4(vec4(m.hi[0][3], m.hi[1][3], m.hi[2][3], m.hi[3][3]), vec4(m.lo[0][3], m.lo[1][3], m.lo[2][3], m.lo[3][3])), v);
  return df_dvec4(vec4(p0.hi, p1.hi, p2.hi, p3.hi), vec4(p0.lo, p1.lo, p2.lo, p3.lo));
}

// df_mul_dmat4_dmat4: column j of a * b is a * (column j of b) (df_mul_dmat4_dvec4). Bound: 13u^2 * sum_k |a[k][i] b[j][k]| per element (absolute).
df_dmat4 df_mul_dmat4_dmat4(df_dmat4 a, df_dmat4 b) {
  df_dvec4 c0 = df_mul_dmat4_dvec4(a, df_dvec4(b.hi[0], b.lo[0]));
  df_dvec4 c1 = df_mul_dmat4_dvec4(a, df_dvec4(b.hi[1], b.lo[1]));
  df_dvec4 c2 = df_mul_dmat4_dvec4(a, df_dvec4(b.hi[2], b.lo[2]));
  df_dvec4 c3 = df_mul_dmat4_dvec4(a, df_dvec4(b.hi[3], b.lo[3]));
  return df_dmat4(mat4(c0.hi, c1.hi, c2.hi, c3.hi), mat4(c0.lo, c1.lo, c2.lo, c3.lo));
}

// df_add_dmat4_double: df_add on each element (column by column), so each element has df_add's bound (rules/arith.glsl).
df_dmat4 df_add_dmat4_double(df_dmat4 a, df_double b) {
  df_dvec4 c0 = df_add(df_dvec4(a.hi[0], a.lo[0]), df_dvec4(vec4(b.hi), vec4(b.lo)));
  df_dvec4 c1 = df_add(df_dvec4(a.hi[1], a.lo[1]), df_dvec4(vec4(b.hi), vec4(b.lo)));
  df_dvec4 c2 = df_add(df_dvec4(a.hi[2], a.lo[2]), df_dvec4(vec4(b.hi), vec4(b.lo)));
  df_dvec4 c3 = df_add(df_dvec4(a.hi[3], a.lo[3]), df_dvec4(vec4(b.hi), vec4(b.lo)));
  return df_dmat4(mat4(c0.hi, c1.hi, c2.hi, c3.hi), mat4(c0.lo, c1.lo, c2.lo, c3.lo));
}

// df_mul_dvec4_dmat4: (v * m)[j] = df_dot(v, column j of m). Bound: 13u^2 * sum_i |v[i] m[j][i]| per component (absolute).
df_dvec4 df_mul_dvec4_dmat4(df_dvec4 v, df_dmat4 m) {
  df_double p0 = df_dot(v, df_dvec4(m.hi[0], m.lo[0]));
  df_double p1 = df_dot(v, df_dvec4(m.hi[1], m.lo[1]));
  df_double p2 = df_dot(v, df_dvec4(m.hi[2], m.lo[2]));
  df_double p3 = df_dot(v, df_dvec4(m.hi[3], m.lo[3]));
  return df_dvec4(vec4(p0.hi, p1.hi, p2.hi, p3.hi), vec4(p0.lo, p1.lo, p2.lo, p3.lo));
}

// df_inverse_dmat3: adjugate / determinant. Cofactors by expansion (10u^2 * per(|minor|) absolute),
// the determinant from the first row's cofactors (23u^2 * per(|m|)), then df_div (15u^2).
// Relative error of inverse[j][i] <= (10 per(|minor_ij|)/|cof_ij| + 23 per(|m|)/|det| + 15)u^2: it grows with the condition of m.
df_dmat3 df_inverse_dmat3(df_dmat3 m) {
  df_double a00 = df_double(m.hi[0][0], m.lo[0][0]);
  df_double a01 = df_double(m.hi[1][0], m.lo[1][0]);
  df_double a02 = df_double(m.hi[2][0], m.lo[2][0]);
  df_double a10 = df_double(m.hi[0][1], m.lo[0][1]);
  df_double a11 = df_double(m.hi[1][1], m.lo[1][1]);
  df_double a12 = df_double(m.hi[2][1], m.lo[2][1]);
  df_double a20 = df_double(m.hi[0][2], m.lo[0][2]);
  df_double a21 = df_double(m.hi[1][2], m.lo[1][2]);
  df_double a22 = df_double(m.hi[2][2], m.lo[2][2]);
  df_double t0 = df_mul(a11, a22);
  df_double t1 = df_mul(a12, a21);
  df_double t2 = df_sub(t0, t1);
  df_double d12_12 = t2;
  df_double k00 = d12_12;
  df_double t3 = df_mul(a10, a22);
  df_double t4 = df_mul(a12, a20);
  df_double t5 = df_sub(t3, t4);
  df_double d12_02 = t5;
  df_double k01 = df_neg(d12_02);
  df_double t6 = df_mul(a10, a21);
  df_double t7 = df_mul(a11, a20);
  df_double t8 = df_sub(t6, t7);
  df_double d12_01 = t8;
  df_double k02 = d12_01;
  df_double t9 = df_mul(a01, a22);
  df_double t10 = df_mul(a02, a21);
  df_double t11 = df_sub(t9, t10);
  df_double d02_12 = t11;
  df_double k10 = df_neg(d02_12);
  df_double t12 = df_mul(a00, a22);
  df_double t13 = df_mul(a02, a20);
  df_double t14 = df_sub(t12, t13);
  df_double d02_02 = t14;
  df_double k11 = d02_02;
  df_double t15 = df_mul(a00, a21);
  df_double t16 = df_mul(a01, a20);
  df_double t17 = df_sub(t15, t16);
  df_double d02_01 = t17;
  df_double k12 = df_neg(d02_01);
  df_double t18 = df_mul(a01, a12);
  df_double t19 = df_mul(a02, a11);
  df_double t20 = df_sub(t18, t19);
  df_double d01_12 = t20;
  df_double k20 = d01_12;
  df_double t21 = df_mul(a00, a12);
  df_double t22 = df_mul(a02, a10);
  df_double t23 = df_sub(t21, t22);
  df_double d01_02 = t23;
  df_double k21 = df_neg(d01_02);
  df_double t24 = df_mul(a00, a11);
  df_double t25 = df_mul(a01, a10);
  df_double t26 = df_sub(t24, t25);
  df_double d01_01 = t26;
  df_double k22 = d01_01;
  df_double e0 = df_mul(a00, k00);
  df_double e1 = df_mul(a01, k01);
  df_double s1 = df_add(e0, e1);
  df_double e2 = df_mul(a02, k02);
  df_double s2 = df_add(s1, e2);
  df_dvec3 c0 = df_div(df_dvec3(vec3(k00.hi, k01.hi, k02.hi), vec3(k00.lo, k01.lo, k02.lo)), df_dvec3(vec3(s2.hi), vec3(s2.lo)));
  df_dvec3 c1 = df_div(df_dvec3(vec3(k10.hi, k11.hi, k12.hi), vec3(k10.lo, k11.lo, k12.lo)), df_dvec3(vec3(s2.hi), vec3(s2.lo)));
  df_dvec3 c2 = df_div(df_dvec3(vec3(k20.hi, k21.hi, k22.hi), vec3(k20.lo, k21.lo, k22.lo)), df_dvec3(vec3(s2.hi), vec3(s2.lo)));
  return df_dmat3(mat3(c0.hi, c1.hi, c2.hi), mat3(c0.lo, c1.lo, c2.lo));
}

// df_determinant_dmat3: cofactor expansion along the first row, minors shared (df_mul, df_add,
// df_sub). Bound: 23u^2 * per(|m|) (absolute, first order).
df_double df_determinant_dmat3(df_dmat3 m) {
  df_double a00 = df_double(m.hi[0][0], m.lo[0][0]);
  df_double a01 = df_double(m.hi[1][0], m.lo[1][0]);
  df_double a02 = df_double(m.hi[2][0], m.lo[2][0]);
  df_double a10 = df_double(m.hi[0][1], m.lo[0][1]);
  df_double a11 = df_double(m.hi[1][1], m.lo[1][1]);
  df_double a12 = df_double(m.hi[2][1], m.lo[2][1]);
  df_double a20 = df_double(m.hi[0][2], m.lo[0][2]);
  df_double a21 = df_double(m.hi[1][2], m.lo[1][2]);
  df_double a22 = df_double(m.hi[2][2], m.lo[2][2]);
  df_double t0 = df_mul(a11, a22);
  df_double t1 = df_mul(a12, a21);
  df_double t2 = df_sub(t0, t1);
  df_double d12_12 = t2;
  df_double t3 = df_mul(a00, d12_12);
  df_double t4 = df_mul(a10, a22);
  df_double t5 = df_mul(a12, a20);
  df_double t6 = df_sub(t4, t5);
  df_double d12_02 = t6;
  df_double t7 = df_mul(a01, d12_02);
  df_double t8 = df_sub(t3, t7);
  df_double t9 = df_mul(a10, a21);
  df_double t10 = df_mul(a11, a20);
  df_double t11 = df_sub(t9, t10);
  df_double d12_01 = t11;
  df_double t12 = df_mul(a02, d12_01);
  df_double t13 = df_add(t8, t12);
  df_double d012_012 = t13;
  return d012_012;
}

// df_sub_dmat3_dmat3: df_sub on each element (column by column), so each element has df_sub's bound (rules/arith.glsl).
df_dmat3 df_sub_dmat3_dmat3(df_dmat3 a, df_dmat3 b) {
  df_dvec3 c0 = df_sub(df_dvec3(a.hi[0], a.lo[0]), df_dvec3(b.hi[0], b.lo[0]));
  df_dvec3 c1 = df_sub(df_dvec3(a.hi[1], a.lo[1]), df_dvec3(b.hi[1], b.lo[1]));
  df_dvec3 c2 = df_sub(df_dvec3(a.hi[2], a.lo[2]), df_dvec3(b.hi[2], b.lo[2]));
  return df_dmat3(mat3(c0.hi, c1.hi, c2.hi), mat3(c0.lo, c1.lo, c2.lo));
}

df_dvec3 df_assign_column_dmat3(inout df_dmat3 m, int j, df_dvec3 v) {
  m.hi[j] = v.hi;
  m.lo[j] = v.lo;
  return v;
}

df_double df_component_dvec3(df_dvec3 v, int i) {
  return df_double(v.hi[i], v.lo[i]);
}

df_double df_assign_element_dmat3(inout df_dmat3 m, int j, int i, df_double x) {
  m.hi[j][i] = x.hi;
  m.lo[j][i] = x.lo;
  return x;
}

df_dvec4 df_assign_column_dmat4(inout df_dmat4 m, int j, df_dvec4 v) {
  m.hi[j] = v.hi;
  m.lo[j] = v.lo;
  return v;
}

// df_matrix_comp_mult_dmat2: df_mul on each element (column by column), so each element has df_mul's bound (rules/arith.glsl).
df_dmat2 df_matrix_comp_mult_dmat2(df_dmat2 a, df_dmat2 b) {
  df_dvec2 c0 = df_mul(df_dvec2(a.hi[0], a.lo[0]), df_dvec2(b.hi[0], b.lo[0]));
  df_dvec2 c1 = df_mul(df_dvec2(a.hi[1], a.lo[1]), df_dvec2(b.hi[1], b.lo[1]));
  return df_dmat2(mat2(c0.hi, c1.hi), mat2(c0.lo, c1.lo));
}

// df_div_dmat2_double: df_div on each element (column by column), so each element has df_div's bound (rules/arith.glsl).
df_dmat2 df_div_dmat2_double(df_dmat2 a, df_double b) {
  df_dvec2 c0 = df_div(df_dvec2(a.hi[0], a.lo[0]), df_dvec2(vec2(b.hi), vec2(b.lo)));
  df_dvec2 c1 = df_div(df_dvec2(a.hi[1], a.lo[1]), df_dvec2(vec2(b.hi), vec2(b.lo)));
  return df_dmat2(mat2(c0.hi, c1.hi), mat2(c0.lo, c1.lo));
}

// df_neg_dmat2: exact (both words negated).
df_dmat2 df_neg_dmat2(df_dmat2 a) {
  return df_dmat2(-a.hi, -a.lo);
}

// df_inverse_dmat2: adjugate / determinant. Cofactors by expansion (0u^2 * per(|minor|) absolute),
// the determinant from the first row's cofactors (10u^2 * per(|m|)), then df_div (15u^2).
// Relative error of inverse[j][i] <= (0 per(|minor_ij|)/|cof_ij| + 10 per(|m|)/|det| + 15)u^2: it grows with the condition of m.
df_dmat2 df_inverse_dmat2(df_dmat2 m) {
  df_double a00 = df_double(m.hi[0][0], m.lo[0][0]);
  df_double a01 = df_double(m.hi[1][0], m.lo[1][0]);
  df_double a10 = df_double(m.hi[0][1], m.lo[0][1]);
  df_double a11 = df_double(m.hi[1][1], m.lo[1][1]);
  df_double k00 = a11;
  df_double k01 = df_neg(a10);
  df_double k10 = df_neg(a01);
  df_double k11 = a00;
  df_double e0 = df_mul(a00, k00);
  df_double e1 = df_mul(a01, k01);
  df_double s1 = df_add(e0, e1);
  df_dvec2 c0 = df_div(df_dvec2(vec2(k00.hi, k01.hi), vec2(k00.lo, k01.lo)), df_dvec2(vec2(s1.hi), vec2(s1.lo)));
  df_dvec2 c1 = df_div(df_dvec2(vec2(k10.hi, k11.hi), vec2(k10.lo, k11.lo)), df_dvec2(vec2(s1.hi), vec2(s1.lo)));
  return df_dmat2(mat2(c0.hi, c1.hi), mat2(c0.lo, c1.lo));
}

// df_mul_dmat2_dvec2: (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise
// AccurateDWPlusDW). Bound: 10u^2 * sum_j |m[j][i] v[j]| per component (absolute).
df_dvec2 df_mul_dmat2_dvec2(df_dmat2 m, df_dvec2 v) {
  df_double p0 = df_dot(df_dvec2(vec2(m.hi[0][0], m.hi[1][0]), vec2(m.lo[0][0], m.lo[1][0])), v);
  df_double p1 = df_dot(df_dvec2(vec2(m.hi[0][1], m.hi[1][1]), vec2(m.lo[0][1], m.lo[1][1])), v);
  return df_dvec2(vec2(p0.hi, p1.hi), vec2(p0.lo, p1.lo));
}

// df_mul_dmat2_dmat2: column j of a * b is a * (column j of b) (df_mul_dmat2_dvec2). Bound: 10u^2 * sum_k |a[k][i] b[j][k]| per element (absolute).
df_dmat2 df_mul_dmat2_dmat2(df_dmat2 a, df_dmat2 b) {
  df_dvec2 c0 = df_mul_dmat2_dvec2(a, df_dvec2(b.hi[0], b.lo[0]));
  df_dvec2 c1 = df_mul_dmat2_dvec2(a, df_dvec2(b.hi[1], b.lo[1]));
  return df_dmat2(mat2(c0.hi, c1.hi), mat2(c0.lo, c1.lo));
}

// df_add_dmat2_dmat2: df_add on each element (column by column), so each element has df_add's bound (rules/arith.glsl).
df_dmat2 df_add_dmat2_dmat2(df_dmat2 a, df_dmat2 b) {
  df_dvec2 c0 = df_add(df_dvec2(a.hi[0], a.lo[0]), df_dvec2(b.hi[0], b.lo[0]));
  df_dvec2 c1 = df_add(df_dvec2(a.hi[1], a.lo[1]), df_dvec2(b.hi[1], b.lo[1]));
  return df_dmat2(mat2(c0.hi, c1.hi), mat2(c0.lo, c1.lo));
}

// df_mul_dmat3_dvec3: (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise
// AccurateDWPlusDW). Bound: 13u^2 * sum_j |m[j][i] v[j]| per component (absolute).
df_dvec3 df_mul_dmat3_dvec3(df_dmat3 m, df_dvec3 v) {
  df_double p0 = df_dot(df_dvec3(vec3(m.hi[0][0], m.hi[1][0], m.hi[2][0]), vec3(m.lo[0][0], m.lo[1][0], m.lo[2][0])), v);
  df_double p1 = df_dot(df_dvec3(vec3(m.hi[0][1], m.hi[1][1], m.hi[2][1]), vec3(m.lo[0][1], m.lo[1][1], m.lo[2][1])), v);
  df_double p2 = df_dot(df_dvec3(vec3(m.hi[0][2], m.hi[1][2], m.hi[2][2]), vec3(m.lo[0][2], m.lo[1][2], m.lo[2][2])), v);
  return df_dvec3(vec3(p0.hi, p1.hi, p2.hi), vec3(p0.lo, p1.lo, p2.lo));
}

// df_determinant_dmat2: cofactor expansion along the first row, minors shared (df_mul, df_add,
// df_sub). Bound: 10u^2 * per(|m|) (absolute, first order).
df_double df_determinant_dmat2(df_dmat2 m) {
  df_double a00 = df_double(m.hi[0][0], m.lo[0][0]);
  df_double a01 = df_double(m.hi[1][0], m.lo[1][0]);
  df_double a10 = df_double(m.hi[0][1], m.lo[0][1]);
  df_double a11 = df_double(m.hi[1][1], m.lo[1][1]);
  df_double t0 = df_mul(a00, a11);
  df_double t1 = df_mul(a01, a10);
  df_double t2 = df_sub(t0, t1);
  df_double d01_01 = t2;
  return d01_01;
}

df_dvec3 df_make_dvec3_2_1(df_dvec2 a0, df_double a1) {
  return df_dvec3(vec3(a0.hi.x, a0.hi.y, a1.hi), vec3(a0.lo.x, a0.lo.y, a1.lo));
}

// df_equal_dmat4: exact (word-wise: double-word numbers are unique, JMP 2017 Def. 1.4).
bool df_equal_dmat4(df_dmat4 a, df_dmat4 b) {
  return a.hi == b.hi && a.lo == b.lo;
}

// df_to_mat4: each element rounded to float (df_to_float).
mat4 df_to_mat4(df_dmat4 a) {
  return mat4(df_to_float(df_dvec4(a.hi[0], a.lo[0])), df_to_float(df_dvec4(a.hi[1], a.lo[1])), df_to_float(df_dvec4(a.hi[2], a.lo[2])), df_to_float(df_dvec4(a.hi[3], a.lo[3])));
}

df_dmat4 df_resize_dmat3_dmat4(df_dmat3 a) {
  return df_dmat4(mat4(a.hi), mat4(a.lo) - mat4(mat3(0.0)));
}

df_dvec3 df_column_dmat3(df_dmat3 m, int j) {
  return df_dvec3(m.hi[j], m.lo[j]);
}

df_double df_component_dvec2(df_dvec2 v, int i) {
  return df_double(v.hi[i], v.lo[i]);
}

df_dvec4 df_make_dvec4_3_1(df_dvec3 a0, df_double a1) {
  return df_dvec4(vec4(a0.hi.x, a0.hi.y, a0.hi.z, a1.hi), vec4(a0.lo.x, a0.lo.y, a0.lo.z, a1.lo));
}

df_dmat4 model;
df_dmat3 normal_basis;
df_dmat2 warp[2];
in vec4 position_hi;
in vec4 position_lo;
df_dvec4 position;
in vec3 normal;
out vec4 shade;

df_dmat3 scaled(df_dmat3 m, df_double s);

df_dmat3 scaled(df_dmat3 m, df_double s)
{
  return df_mul_dmat3_double(m, s);
}

void main()
{
  model = df_dmat4(model_hi - df_guard[int(df_guard[1])], model_lo - df_guard[int(df_guard[1])]);
  normal_basis = df_dmat3(normal_basis_hi - df_guard[int(df_guard[1])], normal_basis_lo - df_guard[int(df_guard[1])]);
  warp[0] = df_dmat2(warp_hi[0] - df_guard[int(df_guard[1])], warp_lo[0] - df_guard[int(df_guard[1])]);
  warp[1] = df_dmat2(warp_hi[1] - df_guard[int(df_guard[1])], warp_lo[1] - df_guard[int(df_guard[1])]);
  position = df_dvec4(position_hi, position_lo);
  df_dmat4 mvp = df_add_dmat4_double(df_mul_dmat4_dmat4(model, df_transpose_dmat4(model)), df_double(0.5, 0.0));
  df_dvec4 p = df_mul_dmat4_dvec4(mvp, position);
  p = df_add(p, df_mul_dvec4_dmat4(position, mvp));
  df_dmat3 n = df_mul_dmat3_double(df_inverse_dmat3(normal_basis), df_determinant_dmat3(normal_basis));
  n = df_sub_dmat3_dmat3(scaled(n, df_double(2.0, 0.0)), df_dmat3(mat3(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0), mat3(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)));
  df_assign_column_dmat3(n, 1, df_from_float(normal));
  df_assign_element_dmat3(n, 2, column, df_add_f(df_component_dvec3(df_dvec3(n.hi[2], n.lo[2]), column), 3.0));
  df_assign_column_dmat4(mvp, column, p);
  df_dmat2 w = df_div_dmat2_double(df_matrix_comp_mult_dmat2(warp[0], warp[1]), df_double(4.0, 0.0));
  w = df_add_dmat2_dmat2(df_neg_dmat2(w), df_mul_dmat2_dmat2(df_inverse_dmat2(warp[1]), warp[0]));
  df_dvec3 r = df_add(df_mul_dmat3_dvec3(n, df_from_float(normal)), df_make_dvec3_2_1(df_dvec2(w.hi[0], w.lo[0]), df_determinant_dmat2(w)));
  bool same = df_equal_dmat4(model, mvp);
  mat4 demoted = df_to_mat4(mvp);
  shade = vec4(df_to_float(r), same ? 1.0 : 0.0) + demoted[column];
  gl_Position = df_to_float(df_add(df_add(df_mul_dmat4_dvec4(df_resize_dmat3_dmat4(df_dmat3(mat3(demoted), mat3(0.0))), p), df_dvec4(mvp.hi[2], mvp.lo[2])), df_make_dvec4_3_1(df_column_dmat3(n, column), df_component_dvec2(df_dvec2(w.hi[1], w.lo[1]), column - 2 * (column / 2)))));
}
