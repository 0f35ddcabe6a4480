#version 330 core
precision highp float;
precision highp int;

uniform float scale_hi;
uniform float scale_lo;
uniform vec3 light_hi;
uniform vec3 light_lo;

// doublet float-float runtime: 82 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
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

// df_norm_scale: (s, 1/s), powers of two that bring the largest component of hi into
// [2^-36, 2^60] (as hypot does): s = 2^-90 when some |hi_i| > 2^60, 2^90 when every |hi_i| < 2^-36,
// else 1. Then the squares of the scaled vector neither overflow (4 * 2^120 < 2^128) nor lose
// their error terms to underflow (the largest square is >= 2^-72, its low words >= ~2^-120),
// and scaling is exact. Values in [2^-36, 2^60] take s = 1: bit for bit the unscaled result.
// +-Inf scales to +-Inf; NaN fails both tests and is not scaled.
// Algorithm: two threshold tests on abs(hi), selection of power-of-two constants
// Source: IEEE 754-2008 section 9.2 (hypot: scaling to avoid spurious overflow and underflow); Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023, section 5 (scaled norms)
// Bound: exact
// Flops: 4 (W = 4: one abs per component; plus 2 vector comparisons and 4 selects)
vec2 df_norm_scale(vec3 h) {
  vec3 ah = (abs(h));
  bool big = any(greaterThan(ah, vec3(1.152921504606846976e18)));
  bool small = all(lessThan(ah, vec3(1.4551915228366851806640625e-11)));
  float down = (mix(1.0, 8.0779356694631608874161005085933746e-28, big));
  float s = (mix(down, 1.237940039285380274899124224e27, small));
  float up = (mix(1.0, 1.237940039285380274899124224e27, big));
  float back = (mix(up, 8.0779356694631608874161005085933746e-28, small));
  return vec2(s, back);
}

// df_scale_pow2: a * s for a power of two s: both words scaled, exact while no word over- or
// underflows.
// Algorithm: scaling of hi and lo by a power of two
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 2 (per component)
df_dvec3 df_scale_pow2(df_dvec3 a, float s) {
  vec3 h = (a.hi * s);
  vec3 l = (a.lo * s);
  return df_dvec3(h, l);
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
  vec3 cl2 = (a.lo * b);
  df_dvec3 t = df_fast_two_sum(c.hi, cl2);
  vec3 tl2 = (t.lo + c.lo);
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
  vec3 th = ((a.hi / b.hi) - df_guard[int(df_guard[1])]);
  df_dvec3 r = df_mul_f(b, th);
  vec3 pih = (a.hi - r.hi);
  vec3 dl = (a.lo - r.lo);
  vec3 d = (pih + dl);
  vec3 tl = (d / b.hi);
  df_dvec3 z = df_fast_two_sum(th, tl);
  df_dvec3 q = df_finish(z, th);
  return q;
}

// df_normalize: a / length(a) per component (width 1: sign(a), exact), computed on a scaled by
// df_norm_scale (a / |a| does not change when a is scaled by a power of two), so every vector
// whose components are within float range normalizes, however long or short.
// Algorithm: df_norm_scale, df_dot, SQRTDWtoDW (LLMPR Algorithm 8), then DWDivDW2 (JMP Algorithm 17) per component
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 24.625u^2
// Flops: 378 (W = 4)
df_dvec3 df_normalize(df_dvec3 a) {
  vec2 k = (df_norm_scale(a.hi));
  df_dvec3 b = df_scale_pow2(a, k.x);
  df_double d = df_dot(b, b);
  df_double n = df_sqrt(d);
  df_dvec3 r = df_div(b, df_dvec3(vec3(n.hi), vec3(n.lo)));
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

// df_fract: x - floor(x). hi an integer: lo - floor(lo), exact by TwoSum. Otherwise
// TwoSum(hi, -floor(hi)) is exact and lo is added with DWPlusFP (exact when hi >= 0 or
// |hi| >= 1, where hi - floor(hi) is a float). Special values: for +-Inf, hi is an "integer"
// and lo - floor(lo) is 0; df_finish then returns (hi - floor(hi), 0) = (NaN, 0), native's
// x - floor(x) (and +0 for every other integer, as before).
// Algorithm: TwoSum of the fractional words, then DWPlusFP (JMP Algorithm 4); df_finish for integers
// Source: Knuth TAOCP vol. 2, 1998, 4.2.2 Theorem B; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 29
df_double df_fract(df_double a) {
  float f = ((floor(a.hi)) - df_guard[int(df_guard[1])]);
  bool integer = f == a.hi;
  float g = ((floor(a.lo)) - df_guard[int(df_guard[1])]);
  float ng = ((0.0 - g) - df_guard[int(df_guard[1])]);
  df_double r = df_two_sum(a.lo, ng);
  float d = ((a.hi - f) - df_guard[int(df_guard[1])]);
  df_double q = df_finish(r, d);
  float nf = ((0.0 - f) - df_guard[int(df_guard[1])]);
  df_double t = df_two_sum(a.hi, nf);
  df_double s = df_add_f(t, a.lo);
  df_double z = df_select(integer, q, s);
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
  float th = ((a.hi / b.hi) - df_guard[int(df_guard[1])]);
  df_double r = df_mul_f(b, th);
  float pih = (a.hi - r.hi);
  float dl = (a.lo - r.lo);
  float d = (pih + dl);
  float tl = (d / b.hi);
  df_double z = df_fast_two_sum(th, tl);
  df_double q = df_finish(z, th);
  return q;
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

// df_clamp: min(max(x, lo), hi).
// Algorithm: df_max then df_min (lexicographic compare and select)
// Source: GLSL 4.60 (2019) section 8.3 (clamp); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (6 comparisons per component)
df_double df_clamp(df_double x, df_double lo, df_double hi) {
  df_double m = df_max(x, lo);
  df_double r = df_min(m, hi);
  return r;
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

// df_smoothstep: t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2t). t has relative error
// 3 + 3 + 15 = 21u^2 (each subtraction is one AccurateDWPlusDW of exact inputs); the cubic's
// slope is at most 1.5 and its evaluation adds 7 + 9 + 7 u^2 on [0, 1].
// Algorithm: AccurateDWPlusDW, DWDivDW2, clamp, DWTimesDW1
// Source: GLSL 4.60 (2019) section 8.3 (smoothstep); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 55u^2 (absolute; the result is in [0, 1])
// Flops: 190
df_double df_smoothstep(df_double e0, df_double e1, df_double x) {
  df_double n = df_sub(x, e0);
  df_double d = df_sub(e1, e0);
  df_double q = df_div(n, d);
  df_double t = df_clamp(q, df_double(float(0.0), float(0.0)), df_double(float(1.0), float(0.0)));
  df_double s = df_mul(t, t);
  df_double t2 = df_add(t, t);
  df_double c = df_sub(df_double(float(3.0), float(0.0)), t2);
  df_double r = df_mul(s, c);
  return r;
}

// df_floor: largest integer <= x. hi not an integer: floor(hi); else hi + floor(lo), joined by
// Fast2Sum (|floor(lo)| <= |hi| since |lo| <= ulp(hi)/2 and |hi| >= 1).
// Special values: +-0 and +-Inf are integers whose lo is 0 (or, for an input Inf, NaN): they
// are returned as (hi, 0), as native floor does; the Fast2Sum would give +0 for -0 and
// Inf - Inf = NaN in lo. NaN fails f == hi and gives (NaN, 0).
// Algorithm: floor of hi, or Fast2Sum(hi, floor(lo)) when hi is a nonzero finite integer
// Source: JMP 2017, Definition 1.4; Dekker 1971, Theorem 4.3 (Fast2Sum); IEEE 754-2008 section 5.9
// Bound: exact
// Flops: 6 (plus 2 comparisons)
df_double df_floor(df_double a) {
  float f = ((floor(a.hi)) - df_guard[int(df_guard[1])]);
  float af = (abs(f));
  bool integer = all(bvec3(f == a.hi, af > 0.0, af <= 3.40282347e38));
  float g = ((floor(a.lo)) - df_guard[int(df_guard[1])]);
  df_double r = df_fast_two_sum(a.hi, g);
  float h = (mix(f, r.hi, integer));
  float l = (mix(0.0, r.lo, integer));
  return df_double(h, l);
}

// df_mod: x - y * floor(x / y) (GLSL's definition). Where x / y is within df_div's error of an
// integer, floor may pick the neighbouring integer, and the result is off by y (the function is
// discontinuous there, in native fp64 as well). Otherwise the product has 7u^2 abs(y q) <=
// 7u^2 (abs(x) + abs(y)) and the subtraction 3u^2 abs(r).
// Algorithm: DWDivDW2, df_floor, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.3 (mod); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 10u^2 * (abs(x) + abs(y)) (absolute) when floor(x / y) is exact
// Flops: 97
df_double df_mod(df_double a, df_double b) {
  df_double q = df_div(a, b);
  df_double f = df_floor(q);
  df_double p = df_mul(b, f);
  df_double r = df_sub(a, p);
  return r;
}

// df_step: 0.0 if x < edge, else 1.0.
// Algorithm: lexicographic compare (df_lt)
// Source: GLSL 4.60 (2019) section 8.3 (step); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons)
df_double df_step(df_double edge, df_double x) {
  bool below = df_lt(x, edge);
  float h = (mix(1.0, 0.0, below));
  return df_double(h, 0.0);
}

// df_ceil: smallest integer >= x, as -floor(-x): negation is exact, and the zero results get
// native's signs (ceil(-0.5) = -0, ceil(-1 + 2^-30) = -0), which hi + ceil(lo) would give as +0.
// Algorithm: df_neg, df_floor, df_neg
// Source: JMP 2017, Definition 1.4; IEEE 754-2008 section 5.9 (ceil(x) = -floor(-x))
// Bound: exact
// Flops: 10 (plus 2 comparisons)
df_double df_ceil(df_double a) {
  df_double n = df_neg(a);
  df_double f = df_floor(n);
  df_double r = df_neg(f);
  return r;
}

// df_trunc: the integer nearest x toward zero: ceil for negative x, floor otherwise, both computed
// and one selected. (Selecting the operand instead, floor(x < 0 ? -x : x), is one floor less, but
// Mesa's GLES compiler folds that select into abs(x), which turns trunc(-0) into +0.)
// Algorithm: df_ceil and df_floor, selected by the sign of hi
// Source: JMP 2017, Definition 1.4; GLSL 4.60 (2019) section 8.3 (trunc)
// Bound: exact
// Flops: 16
df_double df_trunc(df_double a) {
  bool negative = a.hi < 0.0;
  df_double c = df_ceil(a);
  df_double f = df_floor(a);
  df_double r = df_select(negative, c, f);
  return r;
}

// df_modf_fraction: x - i for i = trunc(x), with x's sign (GLSL: "the same sign as x"): for
// negative x it is -(i - x), the mirror image of x - i, so a zero fraction is -0 (modf(-3) = -0);
// for +-0 it is x itself; +-Inf gives NaN (Inf - Inf), as native fp64 does.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6) of x and -i, or of i and -x then df_neg
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1; GLSL 4.60 (2019) section 8.3 (modf); IEEE 754-2008 section 6.3
// Bound: 3u^2
// Flops: 25
// The branches are selects around one df_sub: its operands are swapped and its result negated
// for negative x.
df_double df_modf_fraction(df_double a, df_double i) {
  bool negative = a.hi < 0.0;
  bool zero = a.hi == 0.0;
  df_double x = df_select(negative, i, a);
  df_double y = df_select(negative, a, i);
  df_double d = df_sub(x, y);
  df_double n = df_neg(d);
  df_double m = df_select(negative, n, d);
  float zh = (a.hi);
  df_double z = df_double(zh, float(0.0));
  df_double r = df_select(zero, z, m);
  return r;
}

// df_modf: integer part (toward zero) into i, fraction x - i returned, both with x's sign
// (modf(-3) = (-0, -3), modf(-0) = (-0, -0); native fp64 on Mesa gives +0 for both parts of -0).
// Algorithm: df_trunc, then df_modf_fraction (AccurateDWPlusDW)
// Source: GLSL 4.60 (2019) section 8.3 (modf); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2
// Flops: 41
df_double df_modf(df_double a, out df_double i) {
  i = df_trunc(a);
  df_double r = df_modf_fraction(a, i);
  return r;
}

// df_next_integer: f + 1 for an integer-valued f, with the sign of zero native round gives:
// f = -1 (x in [-1, 0) rounded up) gives -0. Computed as -((-f) - 1): negation is exact and
// (-f) - 1 is the mirror image of f + 1, whose zero is +0 (IEEE 754-2008 section 6.3).
// Algorithm: df_neg, DWPlusFP (JMP Algorithm 4), df_neg
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2; IEEE 754-2008 section 6.3
// Bound: exact
// Flops: 15
// Range: exact for the integers df_floor returns (f + 1 is a double-word integer).
df_double df_next_integer(df_double f) {
  df_double n = df_neg(f);
  df_double m = df_add_f(n, float(-1.0));
  df_double r = df_neg(m);
  return r;
}

// df_round: nearest integer, halves away from zero (GLSL lets the implementation choose).
// A result of zero has the sign of x (round(-0.3) = -0), as native fp64 gives.
// Algorithm: floor(x) plus 1 (df_next_integer) when fract(x) > 1/2 (>= 1/2 for x >= 0)
// Source: GLSL 4.60 (2019) section 8.3 (round); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 50
// Range: the decision uses df_fract (2u^2): exact for x >= 0 or |x| >= 1.
df_double df_round(df_double a) {
  df_double f = df_floor(a);
  df_double d = df_fract(a);
  bool above = any(bvec2(d.hi > 0.5, all(bvec2(d.hi == 0.5, d.lo > 0.0))));
  bool tie = all(bvec2(d.hi == 0.5, d.lo == 0.0));
  bool up = any(bvec2(above, all(bvec2(tie, a.hi >= 0.0))));
  df_double u = df_next_integer(f);
  df_double r = df_select(up, u, f);
  return r;
}

// df_round_even: nearest integer, halves to the even neighbour (roundEven). A result of zero
// has the sign of x (roundEven(-0.5) = -0), as native fp64 gives.
// Algorithm: floor(x) plus 1 (df_next_integer) when fract(x) > 1/2, or = 1/2 and floor(x) is odd
// Source: GLSL 4.60 (2019) section 8.3 (roundEven); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 56
// Range: the parity of floor(x) = fh + fl is the parity of fh + fl taken word by word
// (one of them is even: fl != 0 only when ulp(fh) >= 2).
df_double df_round_even(df_double a) {
  df_double f = df_floor(a);
  df_double d = df_fract(a);
  float h2 = ((f.hi * 0.5) - df_guard[int(df_guard[1])]);
  float fh2 = ((floor(h2)) - df_guard[int(df_guard[1])]);
  float ph = ((h2 - fh2) - df_guard[int(df_guard[1])]);
  float l2 = ((f.lo * 0.5) - df_guard[int(df_guard[1])]);
  float fl2 = ((floor(l2)) - df_guard[int(df_guard[1])]);
  float pl = ((l2 - fl2) - df_guard[int(df_guard[1])]);
  float parity = ((ph + pl) - df_guard[int(df_guard[1])]);
  bool above = any(bvec2(d.hi > 0.5, all(bvec2(d.hi == 0.5, d.lo > 0.0))));
  bool tie = all(bvec2(d.hi == 0.5, d.lo == 0.0));
  bool up = any(bvec2(above, all(bvec2(tie, parity == 0.5))));
  df_double u = df_next_integer(f);
  df_double r = df_select(up, u, f);
  return r;
}

// df_fma: a * b + c. Not fused: the product is rounded (DWTimesDW1), then added.
// Algorithm: DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r) + 7u^2 * abs(a * b) (absolute, first order)
// Flops: 50
df_double df_fma(df_double a, df_double b, df_double c) {
  df_double p = df_mul(a, b);
  df_double r = df_add(p, c);
  return r;
}

// df_mix_bool: a ? y : x per component (mix with a boolean selector).
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBDType)
// Bound: exact
// Flops: 0
df_double df_mix_bool(df_double x, df_double y, bool a) {
  df_double r = df_select(a, y, x);
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

// df_reflect: i - 2 dot(n, i) n. With S = sum |n_j i_j|: the dot has 13u^2 S, doubling is exact,
// the product adds 7u^2, the subtraction 3u^2 of the result r_i.
// Algorithm: df_dot, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.5 (reflect); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r_i) + 20u^2 * 2S abs(n_i) (absolute per component, first order)
// Flops: 245 (W = 4)
df_dvec3 df_reflect(df_dvec3 i, df_dvec3 n) {
  df_double d = df_dot(n, i);
  df_double d2 = df_add(d, d);
  df_dvec3 p = df_mul(df_dvec3(vec3(d2.hi), vec3(d2.lo)), n);
  df_dvec3 r = df_sub(i, p);
  return r;
}

// df_cross: a.yzx * b.zxy - a.zxy * b.yzx (two DWTimesDW1 and one AccurateDWPlusDW per component).
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 10u^2 * (abs(a_j b_k) + abs(a_k b_j)) per component (absolute, first order)
// Flops: 81
df_dvec3 df_cross(df_dvec3 a, df_dvec3 b) {
  df_dvec3 p = df_mul(df_dvec3(a.hi.yzx, a.lo.yzx), df_dvec3(b.hi.zxy, b.lo.zxy));
  df_dvec3 q = df_mul(df_dvec3(a.hi.zxy, a.lo.zxy), df_dvec3(b.hi.yzx, b.lo.yzx));
  df_dvec3 r = df_sub(p, q);
  return r;
}

// df_mix: x + a * (y - x), as GLSL defines mix (r is the result).
// Algorithm: AccurateDWPlusDW, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.3 (mix); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r) + 10u^2 * abs(a * (y - x)) (absolute, first order)
// Flops: 73
df_dvec3 df_mix(df_dvec3 x, df_dvec3 y, df_dvec3 a) {
  df_dvec3 d = df_sub(y, x);
  df_dvec3 p = df_mul(a, d);
  df_dvec3 r = df_add(x, p);
  return r;
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
// (width 3: the width-1 df_select applied to each component)
df_dvec3 df_select(bvec3 c, df_dvec3 a, df_dvec3 b) {
  df_double r0 = df_select(c.x, df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  df_double r1 = df_select(c.y, df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  df_double r2 = df_select(c.z, df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
}

// df_faceforward: dot(nref, i) < 0 ? n : -n. The selection is exact; the sign of the dot
// product carries df_dot's error (wrong only where |dot| is below that bound).
// Algorithm: df_dot, then selection
// Source: GLSL 4.60 (2019) section 8.5 (faceforward); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: exact
// Flops: 181 (W = 4)
df_dvec3 df_faceforward(df_dvec3 n, df_dvec3 i, df_dvec3 nref) {
  df_double d = df_dot(nref, i);
  bvec3 facing = bvec3(d.hi < 0.0);
  df_dvec3 m = df_neg(n);
  df_dvec3 r = df_select(facing, n, m);
  return r;
}

// df_refract: k = 1 - eta^2 (1 - dot(n, i)^2); k < 0 gives 0, else eta i - (eta d + sqrt(k)) n.
// First order, with the rules' bounds composed; sqrt(k) amplifies k's absolute error when k is
// near 0 (grazing incidence), so the bound holds for k not close to 0.
// Algorithm: df_dot, DWTimesDW1, AccurateDWPlusDW, SQRTDWtoDW (LLMPR Algorithm 8)
// Source: GLSL 4.60 (2019) section 8.5 (refract); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 60u^2 * (abs(eta i_j) + (abs(eta d) + sqrt(k)) abs(n_j)) (absolute per component, first order, k not near 0)
// Flops: 481 (W = 4)
df_dvec3 df_refract(df_dvec3 i, df_dvec3 n, df_double eta) {
  df_double d = df_dot(n, i);
  df_double one = df_double(1.0, 0.0);
  df_double dd = df_mul(d, d);
  df_double c = df_sub(one, dd);
  df_double e2 = df_mul(eta, eta);
  df_double ec = df_mul(e2, c);
  df_double k = df_sub(one, ec);
  bool total = k.hi < 0.0;
  df_double s = df_sqrt(k);
  df_double ed = df_mul(eta, d);
  df_double f = df_add(ed, s);
  df_dvec3 a = df_mul(df_dvec3(vec3(eta.hi), vec3(eta.lo)), i);
  df_dvec3 b = df_mul(df_dvec3(vec3(f.hi), vec3(f.lo)), n);
  df_dvec3 t = df_sub(a, b);
  df_dvec3 r = df_select(bvec3(total), df_dvec3(vec3(0.0), vec3(0.0)), t);
  return r;
}

// df_mix_bool: a ? y : x per component (mix with a boolean selector).
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBDType)
// Bound: exact
// Flops: 0
// (width 3: the width-1 df_mix_bool applied to each component)
df_dvec3 df_mix_bool(df_dvec3 x, df_dvec3 y, bvec3 a) {
  df_double r0 = df_mix_bool(df_double(x.hi.x, x.lo.x), df_double(y.hi.x, y.lo.x), a.x);
  df_double r1 = df_mix_bool(df_double(x.hi.y, x.lo.y), df_double(y.hi.y, y.lo.y), a.y);
  df_double r2 = df_mix_bool(df_double(x.hi.z, x.lo.z), df_double(y.hi.z, y.lo.z), a.z);
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
}

// df_less_than: lessThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
bool df_less_than(df_double a, df_double b) {
  return df_lt(a, b);
}

// df_less_than: lessThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 3: the width-1 df_less_than applied to each component)
bvec3 df_less_than(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_less_than(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_less_than(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_less_than(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_le: a <= b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_le(df_double a, df_double b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo <= b.lo))));
}

// df_less_than_equal: lessThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
bool df_less_than_equal(df_double a, df_double b) {
  return df_le(a, b);
}

// df_less_than_equal: lessThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 3: the width-1 df_less_than_equal applied to each component)
bvec3 df_less_than_equal(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_less_than_equal(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_less_than_equal(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_less_than_equal(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_gt(df_double a, df_double b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo > b.lo))));
}

// df_greater_than: greaterThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
bool df_greater_than(df_double a, df_double b) {
  return df_gt(a, b);
}

// df_greater_than: greaterThan(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 3: the width-1 df_greater_than applied to each component)
bvec3 df_greater_than(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_greater_than(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_greater_than(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_greater_than(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_ge: a >= b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_ge(df_double a, df_double b) {
  return any(bvec2(a.hi > b.hi, all(bvec2(a.hi == b.hi, a.lo >= b.lo))));
}

// df_greater_than_equal: greaterThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
bool df_greater_than_equal(df_double a, df_double b) {
  return df_ge(a, b);
}

// df_greater_than_equal: greaterThanEqual(a, b) per component.
// Algorithm: lexicographic comparison of (hi, lo) per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons per component)
// (width 3: the width-1 df_greater_than_equal applied to each component)
bvec3 df_greater_than_equal(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_greater_than_equal(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_greater_than_equal(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_greater_than_equal(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_equal_components: equal(a, b) per component (word-wise).
// Algorithm: word-wise equality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
bool df_equal_components(df_double a, df_double b) {
  return all(bvec2(a.hi == b.hi, a.lo == b.lo));
}

// df_equal_components: equal(a, b) per component (word-wise).
// Algorithm: word-wise equality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
// (width 3: the width-1 df_equal_components applied to each component)
bvec3 df_equal_components(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_equal_components(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_equal_components(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_equal_components(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_not_equal_components: notEqual(a, b) per component (word-wise).
// Algorithm: word-wise inequality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
bool df_not_equal_components(df_double a, df_double b) {
  return any(bvec2(a.hi != b.hi, a.lo != b.lo));
}

// df_not_equal_components: notEqual(a, b) per component (word-wise).
// Algorithm: word-wise inequality per component
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 comparisons per component)
// (width 3: the width-1 df_not_equal_components applied to each component)
bvec3 df_not_equal_components(df_dvec3 a, df_dvec3 b) {
  bool r0 = df_not_equal_components(df_double(a.hi.x, a.lo.x), df_double(b.hi.x, b.lo.x));
  bool r1 = df_not_equal_components(df_double(a.hi.y, a.lo.y), df_double(b.hi.y, b.lo.y));
  bool r2 = df_not_equal_components(df_double(a.hi.z, a.lo.z), df_double(b.hi.z, b.lo.z));
  return bvec3(r0, r1, r2);
}

// df_abs: |a|. Both words are multiplied by sign(hi) (exactly -1, 0 or +1).
// Algorithm: sign of hi applied to both words
// Source: JMP 2017, Definition 1.4 (sign of a double-word number is the sign of hi)
// Bound: exact
// Flops: 3
df_dvec3 df_abs(df_dvec3 a) {
  vec3 s = ((sign(a.hi)) - df_guard[int(df_guard[1])]);
  vec3 h = ((abs(a.hi)) - df_guard[int(df_guard[1])]);
  vec3 l = ((a.lo * s) - df_guard[int(df_guard[1])]);
  return df_dvec3(h, l);
}

// df_floor: largest integer <= x. hi not an integer: floor(hi); else hi + floor(lo), joined by
// Fast2Sum (|floor(lo)| <= |hi| since |lo| <= ulp(hi)/2 and |hi| >= 1).
// Special values: +-0 and +-Inf are integers whose lo is 0 (or, for an input Inf, NaN): they
// are returned as (hi, 0), as native floor does; the Fast2Sum would give +0 for -0 and
// Inf - Inf = NaN in lo. NaN fails f == hi and gives (NaN, 0).
// Algorithm: floor of hi, or Fast2Sum(hi, floor(lo)) when hi is a nonzero finite integer
// Source: JMP 2017, Definition 1.4; Dekker 1971, Theorem 4.3 (Fast2Sum); IEEE 754-2008 section 5.9
// Bound: exact
// Flops: 6 (plus 2 comparisons)
// (width 3: the width-1 df_floor applied to each component)
df_dvec3 df_floor(df_dvec3 a) {
  df_double r0 = df_floor(df_double(a.hi.x, a.lo.x));
  df_double r1 = df_floor(df_double(a.hi.y, a.lo.y));
  df_double r2 = df_floor(df_double(a.hi.z, a.lo.z));
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
}

// df_sign: -1, 0 or +1, the sign of hi.
// Algorithm: sign of hi
// Source: JMP 2017, Definition 1.4 (the sign of a double-word number is the sign of hi)
// Bound: exact
// Flops: 1
df_dvec3 df_sign(df_dvec3 a) {
  vec3 s = ((sign(a.hi)) - df_guard[int(df_guard[1])]);
  return df_dvec3(s, vec3(0.0));
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
  vec3 f = ((a.hi + a.lo) - df_guard[int(df_guard[1])]);
  df_dvec3 r = df_finish(df_dvec3(f, vec3(0.0)), a.hi);
  return r.hi;
}

// df_scale_pow2: a * s for a power of two s: both words scaled, exact while no word over- or
// underflows.
// Algorithm: scaling of hi and lo by a power of two
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 2 (per component)
df_double df_scale_pow2(df_double a, float s) {
  float h = (a.hi * s);
  float l = (a.lo * s);
  return df_double(h, l);
}

// df_length: sqrt(dot(a, a)), W = 2..4, on a scaled by df_norm_scale and scaled back, so any
// vector whose length is within float range gets it (the squares alone would overflow above
// |a| ~ 1.8e19 and underflow below ~1e-19). No cancellation in dot(a, a), so its error is
// relative: (7 + 3d)u^2 with d = ceil(log2 W); sqrt halves that and adds 25/8 u^2:
// 8.125u^2 for W = 2, 9.625u^2 for W = 3, 4 (first order). A length beyond float range is
// (+Inf, 0) (df_finish); one below it tapers into float's subnormals as the scaled-back words
// round.
// Algorithm: df_norm_scale, df_dot(a, a), SQRTDWtoDW (LLMPR Algorithm 8), scaled back, df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 9.625u^2
// Flops: 225 (W = 4; 119 for W = 2, 172 for W = 3)
// Range: every vector (scaled); exact scaling, so the bound holds for lengths in [2^-100, FLT_MAX].
df_double df_length(df_dvec3 a) {
  vec2 k = (df_norm_scale(a.hi));
  df_dvec3 b = df_scale_pow2(a, k.x);
  df_double d = df_dot(b, b);
  df_double n = df_sqrt(d);
  df_double z = df_scale_pow2(n, k.y);
  df_double r = df_finish(z, z.hi);
  return r;
}

// df_distance: length(a - b). The difference of exact inputs is one AccurateDWPlusDW per
// component (3u^2 relative), which adds 3u^2 to df_length's relative bound.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6), then df_length
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 12.625u^2
// Flops: 248 (W = 4)
df_double df_distance(df_dvec3 a, df_dvec3 b) {
  df_dvec3 d = df_sub(a, b);
  df_double r = df_length(d);
  return r;
}

// df_inversesqrt: 1 / sqrt(a): SQRTDWtoDW, then DWDivDW2 of 1 by the root.
// Algorithm: SQRTDWtoDW (LLMPR Algorithm 8), then DWDivDW2 (JMP Algorithm 17)
// Source: Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1
// Bound: 18.125u^2
// Flops: 70
df_double df_inversesqrt(df_double a) {
  df_double s = df_sqrt(a);
  df_double r = df_div(df_double(float(1.0), float(0.0)), s);
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
float df_to_float(df_double a) {
  float f = ((a.hi + a.lo) - df_guard[int(df_guard[1])]);
  df_double r = df_finish(df_double(f, float(0.0)), a.hi);
  return r.hi;
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
df_dvec3 df_mul_f2(df_dvec3 a, vec3 b) {
  df_dvec3 c = df_two_prod(a.hi, b);
  vec3 cl2 = (a.lo * b);
  vec3 cl3 = (c.lo + cl2);
  df_dvec3 z = df_fast_two_sum(c.hi, cl3);
  df_dvec3 r = df_finish(z, c.hi);
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
  float h = (a.hi * p);
  float l = (a.lo * p);
  df_double r = df_finish(df_double(h, l), h);
  return r;
}

df_dvec3 df_splat_dvec3(df_double s) {
  return df_dvec3(vec3(s.hi), vec3(s.lo));
}

df_double scale;
df_dvec3 light;
in vec3 normal_in;
out vec4 color;


void main()
{
  scale = df_double(scale_hi, scale_lo);
  light = df_dvec3(light_hi, light_lo);
  df_double ip;
  df_dvec3 n = df_normalize(df_mul_f2(df_splat_dvec3(scale), normal_in));
  df_double d = df_max(df_dot(n, df_normalize(light)), df_double(0.0 + df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]));
  df_double t = df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_smoothstep(df_double(0.0 + df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]), df_double(1.0 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]), df_fract(df_mul_pow2(d, 4.0))), df_mod(d, df_double(0.25 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]))), df_step(df_double(0.5 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]), d)), df_modf(df_mul_pow2(d, 8.0), ip)), df_trunc(d)), df_round(d)), df_round_even(d)), df_ceil(d)), df_min(d, scale)), df_fma(d, d, scale)), df_sqrt(d)), df_mix_bool(d, scale, df_lt(d, scale)));
  df_dvec3 r = df_add(df_add(df_add(df_add(df_add(df_reflect(df_neg(light), n), df_mul(df_cross(n, light), df_splat_dvec3(df_clamp(d, df_double(0.0 + df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]), df_double(1.0 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]))))), df_mix(n, light, df_splat_dvec3(t))), df_faceforward(n, light, n)), df_refract(n, df_normalize(light), df_double(0.75 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]))), df_mix_bool(n, light, bvec3(true, false, true)));
  bool c = any(df_less_than(n, r)) || all(df_less_than_equal(n, r)) || any(df_greater_than(n, r)) || any(df_greater_than_equal(n, r)) || all(df_equal_components(n, r)) || any(df_not_equal_components(n, r));
  color = vec4(df_to_float(df_add(df_add(df_abs(r), df_floor(r)), df_sign(r))), df_to_float(df_add(df_add(df_add(df_length(r), df_distance(n, light)), df_inversesqrt(df_add_f(d, 1.0))), ip))) + (c ? 1.0 : 0.0);
}
