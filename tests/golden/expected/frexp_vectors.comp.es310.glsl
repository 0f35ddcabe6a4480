#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

// doublet float-float runtime: 18 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
struct df_dvec4 { vec4 hi; vec4 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_exp2i: the bit patterns of three floats whose product is 2^e, -300 <= e <= 300 (each factor
// is 2^k with |k| <= 100, a normal float; intBitsToFloat needs ES 3.00). 300 is beyond every
// float-float result: 2^-149 * 2^300 overflows and 2^128 * 2^-300 underflows to 0, so clamping
// e there changes nothing.
// Algorithm: IEEE 754 binary32 exponent field
// Source: IEEE 754-2008 section 3.4 (binary interchange format encodings)
// Bound: exact
// Flops: 0 (integer operations)
ivec3 df_exp2i(int e) {
  int c = clamp(e, -300, 300);
  int e1 = c / 3;
  int e2 = (c - e1) / 2;
  int e3 = c - e1 - e2;
  int b1 = (e1 + 127) << 23;
  int b2 = (e2 + 127) << 23;
  int b3 = (e3 + 127) << 23;
  return ivec3(b1, b2, b3);
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

// df_ldexp: x * 2^e, both words scaled by powers of two in three exact steps, then df_finish:
// a result beyond float range is (+-Inf, 0) (lo alone would overflow to an infinity of the
// other sign, and Inf + -Inf is NaN), one below it (+-0, 0) with x's sign.
// Algorithm: scaling of hi and lo by 2^e in three exact steps, then df_finish
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 7 (plus 2 comparisons)
// Range: exact while the result is a normal float-float; into float's subnormal range each word
// is rounded (at most twice), within one subnormal ulp (2^-149) absolute.
df_double df_ldexp(df_double a, int e) {
  ivec3 b = df_exp2i(e);
  float s1 = ((intBitsToFloat(b.x)) - df_guard[int(df_guard[1])]);
  float s2 = ((intBitsToFloat(b.y)) - df_guard[int(df_guard[1])]);
  float s3 = ((intBitsToFloat(b.z)) - df_guard[int(df_guard[1])]);
  float h1 = ((a.hi * s1) - df_guard[int(df_guard[1])]);
  float h2 = ((h1 * s2) - df_guard[int(df_guard[1])]);
  float h = ((h2 * s3) - df_guard[int(df_guard[1])]);
  float l1 = ((a.lo * s1) - df_guard[int(df_guard[1])]);
  float l2 = ((l1 * s2) - df_guard[int(df_guard[1])]);
  float l = ((l2 * s3) - df_guard[int(df_guard[1])]);
  df_double z = df_double(h, l);
  df_double r = df_finish(z, h);
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
df_double df_select(bool c, df_double a, df_double b) {
  float h = (mix(b.hi, a.hi, c));
  float l = (mix(b.lo, a.lo, c));
  return df_double(h, l);
}

// df_frexp: x = m * 2^e with 0.5 <= |m| < 1. The exponent is hi's; when hi = +-2^k and lo has
// the opposite sign, |x| < 2^k, so e is one less. A subnormal hi is first scaled by 2^64 (exact)
// to read its exponent. +-0 gives (+-0, e = 0); +-Inf and NaN give m = x and e = 1025, the
// values native fp64 gives on Mesa (GLSL leaves them undefined).
// Algorithm: exponent field of hi (of hi * 2^64 when subnormal), corrected by the sign of lo, then df_ldexp
// Source: IEEE 754-2008 section 5.3.3 (logB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 9 (plus 4 comparisons)
df_double df_frexp(df_double a, out int e) {
  float ah = (abs(a.hi));
  bool regular = all(bvec2(ah > 0.0, ah <= 3.40282347e38));
  bool subnormal = ah < 1.17549435e-38;
  float scale = (mix(1.0, 1.8446744073709552e19, subnormal));
  float h = (a.hi * scale);
  int bits = floatBitsToInt(h);
  int k = ((bits >> 23) & 255) - (subnormal ? 190 : 126);
  int mantissa = bits & 8388607;
  bool opposite = any(bvec2(all(bvec2(a.hi > 0.0, a.lo < 0.0)), all(bvec2(a.hi < 0.0, a.lo > 0.0))));
  bool below = all(bvec2(mantissa == 0, opposite));
  int exponent = below ? k - 1 : k;
  int special = ah == 0.0 ? 0 : 1025;
  e = regular ? exponent : special;
  int undo = regular ? 0 - exponent : 0;
  df_double m = df_ldexp(a, undo);
  float sh = (a.hi);
  df_double x = df_double(sh, 0.0);
  df_double r = df_select(regular, m, x);
  return r;
}

// df_frexp: x = m * 2^e with 0.5 <= |m| < 1. The exponent is hi's; when hi = +-2^k and lo has
// the opposite sign, |x| < 2^k, so e is one less. A subnormal hi is first scaled by 2^64 (exact)
// to read its exponent. +-0 gives (+-0, e = 0); +-Inf and NaN give m = x and e = 1025, the
// values native fp64 gives on Mesa (GLSL leaves them undefined).
// Algorithm: exponent field of hi (of hi * 2^64 when subnormal), corrected by the sign of lo, then df_ldexp
// Source: IEEE 754-2008 section 5.3.3 (logB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 9 (plus 4 comparisons)
// (width 4: the width-1 df_frexp applied to each component)
df_dvec4 df_frexp(df_dvec4 a, out ivec4 e) {
  int e_0;
  int e_1;
  int e_2;
  int e_3;
  df_double r0 = df_frexp(df_double(a.hi.x, a.lo.x), e_0);
  df_double r1 = df_frexp(df_double(a.hi.y, a.lo.y), e_1);
  df_double r2 = df_frexp(df_double(a.hi.z, a.lo.z), e_2);
  df_double r3 = df_frexp(df_double(a.hi.w, a.lo.w), e_3);
  e = ivec4(e_0, e_1, e_2, e_3);
  return df_dvec4(vec4(r0.hi, r1.hi, r2.hi, r3.hi), vec4(r0.lo, r1.lo, r2.lo, r3.lo));
}

// df_frexp: x = m * 2^e with 0.5 <= |m| < 1. The exponent is hi's; when hi = +-2^k and lo has
// the opposite sign, |x| < 2^k, so e is one less. A subnormal hi is first scaled by 2^64 (exact)
// to read its exponent. +-0 gives (+-0, e = 0); +-Inf and NaN give m = x and e = 1025, the
// values native fp64 gives on Mesa (GLSL leaves them undefined).
// Algorithm: exponent field of hi (of hi * 2^64 when subnormal), corrected by the sign of lo, then df_ldexp
// Source: IEEE 754-2008 section 5.3.3 (logB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 9 (plus 4 comparisons)
// (width 3: the width-1 df_frexp applied to each component)
df_dvec3 df_frexp(df_dvec3 a, out ivec3 e) {
  int e_0;
  int e_1;
  int e_2;
  df_double r0 = df_frexp(df_double(a.hi.x, a.lo.x), e_0);
  df_double r1 = df_frexp(df_double(a.hi.y, a.lo.y), e_1);
  df_double r2 = df_frexp(df_double(a.hi.z, a.lo.z), e_2);
  e = ivec3(e_0, e_1, e_2);
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
}

// df_frexp: x = m * 2^e with 0.5 <= |m| < 1. The exponent is hi's; when hi = +-2^k and lo has
// the opposite sign, |x| < 2^k, so e is one less. A subnormal hi is first scaled by 2^64 (exact)
// to read its exponent. +-0 gives (+-0, e = 0); +-Inf and NaN give m = x and e = 1025, the
// values native fp64 gives on Mesa (GLSL leaves them undefined).
// Algorithm: exponent field of hi (of hi * 2^64 when subnormal), corrected by the sign of lo, then df_ldexp
// Source: IEEE 754-2008 section 5.3.3 (logB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 9 (plus 4 comparisons)
// (width 2: the width-1 df_frexp applied to each component)
df_dvec2 df_frexp(df_dvec2 a, out ivec2 e) {
  int e_0;
  int e_1;
  df_double r0 = df_frexp(df_double(a.hi.x, a.lo.x), e_0);
  df_double r1 = df_frexp(df_double(a.hi.y, a.lo.y), e_1);
  e = ivec2(e_0, e_1);
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec4 df_two_sum(vec4 a, vec4 b) {
  vec4 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec4 bb = ((s - a) - df_guard[int(df_guard[1])]);
  vec4 ab = (s - bb);
  vec4 da = (a - ab);
  vec4 db = (b - bb);
  vec4 e = (da + db);
  return df_dvec4(s, e);
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
df_dvec4 df_from_int(ivec4 i) {
  ivec4 q = i / 65536;
  ivec4 r = i - q * 65536;
  vec4 qf = ((vec4(q) * 65536.0) - df_guard[int(df_guard[1])]);
  vec4 rf = ((vec4(r)) - df_guard[int(df_guard[1])]);
  df_dvec4 z = df_two_sum(qf, rf);
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

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec4 df_fast_two_sum(vec4 a, vec4 b) {
  vec4 s = ((a + b) - df_guard[int(df_guard[1])]);
  vec4 z = ((s - a) - df_guard[int(df_guard[1])]);
  vec4 e = (b - z);
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
  vec4 c = (s.lo + t.hi);
  df_dvec4 v = df_fast_two_sum(s.hi, c);
  vec4 w = (t.lo + v.lo);
  df_dvec4 z = df_fast_two_sum(v.hi, w);
  df_dvec4 r = df_finish(z, s.hi);
  return r;
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

// df_mul_pow2: a * p where every component of p is a power of two (+-2^k), exact: scaling by a
// power of two only changes exponents, so hi*p and lo*p are exact and (hi*p, lo*p) is still a
// double-word number. Replaces df_mul (29 flops) and df_div by a power of two.
// Algorithm: exact scaling of both words by a power of two, then df_finish
// Source: HFPA (2018), section 2.2 (multiplication by a power of the radix is exact); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// Range: exact while lo*p stays normal (|lo*p| >= 2^-126) and hi*p does not overflow; an
// overflowing, zero or NaN hi*p gives (hi*p, 0) as df_mul does (df_finish).
df_dvec2 df_mul_pow2(df_dvec2 a, vec2 p) {
  vec2 h = (a.hi * p);
  vec2 l = (a.lo * p);
  df_dvec2 r = df_finish(df_dvec2(h, l), h);
  return r;
}

df_dvec2 df_splat_dvec2(df_double s) {
  return df_dvec2(vec2(s.hi), vec2(s.lo));
}

df_dvec4 df_make_dvec4_3_1(df_dvec3 a0, df_double a1) {
  return df_dvec4(vec4(a0.hi.x, a0.hi.y, a0.hi.z, a1.hi), vec4(a0.lo.x, a0.lo.y, a0.lo.z, a1.lo));
}

layout(std430, binding = 0) buffer Data {
  df_dvec4 x[];
};
layout(std430, binding = 1) buffer Mantissas {
  df_dvec4 m[];
};
layout(std430, binding = 2) buffer Exponents {
  df_dvec4 e[];
};


void main()
{
  ivec4 e4;
  ivec3 e3;
  ivec2 e2;
  uint i = gl_GlobalInvocationID.x;
  m[i] = df_frexp(x[i], e4);
  df_dvec3 m3 = df_frexp(df_dvec3(x[i].hi.zyx, x[i].lo.zyx), e3);
  df_dvec2 m2 = df_frexp(df_mul_pow2(df_dvec2(x[i].hi.xy, x[i].lo.xy), vec2(1024.0)), e2);
  e[i] = df_from_int(e4 + ivec4(e3, e2.x) * 4096 + ivec4(e2.y) * 16777216);
  m[i] = df_add(m[i], df_make_dvec4_3_1(m3, df_add(df_double(m2.hi.x, m2.lo.x), df_double(m2.hi.y, m2.lo.y))));
}
