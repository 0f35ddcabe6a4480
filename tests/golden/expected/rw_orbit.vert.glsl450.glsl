#version 450 core
precision highp float;
precision highp int;

uniform float time_seconds_hi;
uniform float time_seconds_lo;
uniform vec3 camera_position_hi;
uniform vec3 camera_position_lo;
uniform mat4 view_projection;

// doublet float-float runtime: 35 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
struct Orbit {
  df_double semi_major_axis;
  df_double eccentricity;
  df_double mean_motion;
  df_double epoch;
};

uniform Orbit orbit;

uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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
  precise float f = (floor(a.hi));
  precise float af = (abs(f));
  bool integer = all(bvec3(f == a.hi, af > 0.0, af <= 3.40282347e38));
  precise float g = (floor(a.lo));
  df_double r = df_fast_two_sum(a.hi, g);
  precise float h = (mix(f, r.hi, integer));
  precise float l = (mix(0.0, r.lo, integer));
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
  precise float sh = (sqrt(a.hi));
  df_double sq = df_two_prod(sh, sh);
  precise float r0 = (a.hi - sq.hi);
  precise float rho1 = (r0 - sq.lo);
  precise float rho2 = (a.lo + rho1);
  precise float sh2 = (sh * 2.0);
  precise float sl = (rho2 / sh2);
  df_double z = df_fast_two_sum(sh, sl);
  df_double r = df_finish(z, sh);
  return r;
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
  precise vec3 ah = (abs(h));
  bool big = any(greaterThan(ah, vec3(1.152921504606846976e18)));
  bool small = all(lessThan(ah, vec3(1.4551915228366851806640625e-11)));
  precise float down = (mix(1.0, 8.0779356694631608874161005085933746e-28, big));
  precise float s = (mix(down, 1.237940039285380274899124224e27, small));
  precise float up = (mix(1.0, 1.237940039285380274899124224e27, big));
  precise float back = (mix(up, 8.0779356694631608874161005085933746e-28, small));
  return vec2(s, back);
}

// df_scale_pow2: a * s for a power of two s: both words scaled, exact while no word over- or
// underflows.
// Algorithm: scaling of hi and lo by a power of two
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 2 (per component)
df_dvec3 df_scale_pow2(df_dvec3 a, float s) {
  precise vec3 h = (a.hi * s);
  precise vec3 l = (a.lo * s);
  return df_dvec3(h, l);
}

// df_scale_pow2: a * s for a power of two s: both words scaled, exact while no word over- or
// underflows.
// Algorithm: scaling of hi and lo by a power of two
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 2 (per component)
df_double df_scale_pow2(df_double a, float s) {
  precise float h = (a.hi * s);
  precise float l = (a.lo * s);
  return df_double(h, l);
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
  precise vec2 k = (df_norm_scale(a.hi));
  df_dvec3 b = df_scale_pow2(a, k.x);
  df_double d = df_dot(b, b);
  df_double n = df_sqrt(d);
  df_double z = df_scale_pow2(n, k.y);
  df_double r = df_finish(z, z.hi);
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
  precise float cl2 = (a.lo * b);
  precise float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
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

df_dvec3 df_make_dvec3_1_1_1(df_double a0, df_double a1, df_double a2) {
  return df_dvec3(vec3(a0.hi, a1.hi, a2.hi), vec3(a0.lo, a1.lo, a2.lo));
}

df_double time_seconds;
df_dvec3 camera_position;
in float phase_offset;
out float brightness;
const df_double kTwoPi = df_double(6.2831855, -1.7484555e-07);
const int kIterations = 6;
df_double elapsed;

void solve_kepler(df_double mean_anomaly, df_double e, inout df_double eccentric_anomaly);

void solve_kepler(df_double mean_anomaly, df_double e, inout df_double eccentric_anomaly)
{
  for (int k = 0; k < 6; ++k)
  {
    df_double f = df_sub(df_sub(eccentric_anomaly, df_mul_f2(e, sin(df_to_float(eccentric_anomaly)))), mean_anomaly);
    eccentric_anomaly = df_sub(eccentric_anomaly, df_div(f, df_add_f(df_neg(df_mul_f2(e, cos(df_to_float(eccentric_anomaly)))), 1.0)));
  }
}

void main()
{
  time_seconds = df_double(time_seconds_hi - df_guard[int(df_guard[1])], time_seconds_lo - df_guard[int(df_guard[1])]);
  camera_position = df_dvec3(camera_position_hi - df_guard[int(df_guard[1])], camera_position_lo - df_guard[int(df_guard[1])]);
  elapsed = df_sub(time_seconds, df_double(orbit.epoch.hi - df_guard[int(df_guard[1])], orbit.epoch.lo - df_guard[int(df_guard[1])]));
  df_double m = df_mod(df_add_f(df_mul(df_double(orbit.mean_motion.hi - df_guard[int(df_guard[1])], orbit.mean_motion.lo - df_guard[int(df_guard[1])]), elapsed), phase_offset), df_double(6.2831855, -1.7484555e-07));
  df_double ea = m;
  solve_kepler(m, df_double(orbit.eccentricity.hi - df_guard[int(df_guard[1])], orbit.eccentricity.lo - df_guard[int(df_guard[1])]), ea);
  df_double a = df_double(orbit.semi_major_axis.hi - df_guard[int(df_guard[1])], orbit.semi_major_axis.lo - df_guard[int(df_guard[1])]);
  df_dvec3 position = df_make_dvec3_1_1_1(df_mul(a, df_add_f(df_neg(df_double(orbit.eccentricity.hi - df_guard[int(df_guard[1])], orbit.eccentricity.lo - df_guard[int(df_guard[1])])), cos(df_to_float(ea)))), df_mul_f2(df_mul(a, df_sqrt(df_add_f(df_neg(df_sqr(df_double(orbit.eccentricity.hi - df_guard[int(df_guard[1])], orbit.eccentricity.lo - df_guard[int(df_guard[1])]))), 1.0))), sin(df_to_float(ea))), df_double(0.0, 0.0));
  df_dvec3 relative = df_sub(position, camera_position);
  brightness = 1.0 / (1.0 + df_to_float(df_length(relative)) * 1.0e-06);
  gl_Position = view_projection * vec4(df_to_float(relative), 1.0);
}
