#version 300 es
precision highp float;
precision highp int;

uniform mat4 u_model_hi;
uniform mat4 u_model_lo;
uniform mat4 u_view_hi;
uniform mat4 u_view_lo;
uniform mat3x4 u_normal_hi;
uniform mat3x4 u_normal_lo;

struct df_dvec3 {
  vec3 hi;
  vec3 lo;
};
struct df_dmat3x4 {
  mat3x4 hi;
  mat3x4 lo;
};
struct df_dmat4 {
  mat4 hi;
  mat4 lo;
};
// doublet float-float runtime: 17 functions from rules/*.glsl, guard: none (unprotected), error-free transformations: integer (df64-int)
struct df_double { float hi; float lo; };
struct df_dvec4 { vec4 hi; vec4 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_int_unit: the biased exponent u of x's unit in the last place, x = m * 2^(u - 150) with m the
// integer significand (u = 1 for 0 and subnormals). Callers subtract units; only scaling needs the bias.
// Algorithm: binary32 exponent field, at least 1
// Source: IEEE 754-2008 binary32 encoding; HFPA (2018) section 2.1
// Bound: exact
// Flops: 0 (integer: 1 shift, 1 and, 1 max)
int df_int_unit(float x) {
  int field = int((floatBitsToUint(x) >> 23u) & 255u);
  int u = max(field, 1);
  return u;
}

// df_int_magnitude: the 24-bit integer significand m of |x| (hidden bit restored when x is normal).
// Algorithm: binary32 significand field plus the hidden bit (min(field, 1) << 23)
// Source: IEEE 754-2008 binary32 encoding; HFPA (2018) section 2.1
// Bound: exact
// Flops: 0 (integer: 1 shift, 2 ands, 1 min, 1 shift, 1 or; the field shared with df_int_unit)
uint df_int_magnitude(float x) {
  uint bits = floatBitsToUint(x);
  uint field = (bits >> 23u) & 255u;
  uint m = (bits & 8388607u) | (min(field, 1u) << 23u);
  return m;
}

// df_int_scale: n * 2^k, exact whenever the result is a float (one rounding below 2^-126 otherwise).
// Algorithm: conversion of n (at most 24 significant bits, so exact), then two multiplications by
// powers of two built from their bit patterns, k split in halves (k >> 1 and the rest) so neither
// factor leaves the normal range and the first product cannot underflow or overflow
// Source: HFPA (2018) section 2.2 (multiplication by a power of the radix is exact)
// Bound: exact
// Flops: 3
// Range: -252 <= k <= 253, which the callers guarantee wherever their result is used.
float df_int_scale(int n, int k) {
  int k1 = k >> 1;
  int k2 = k - k1;
  float p1 = (uintBitsToFloat(uint(k1 + 127) << 23u));
  float p2 = (uintBitsToFloat(uint(k2 + 127) << 23u));
  float f = (float(n));
  float f1 = (f * p1);
  float r = (f1 * p2);
  return r;
}

// df_int_prod_error: a*b - p exactly, for p the float product the hardware computed.
// Algorithm: a*b = ma*mb * 2^(Ea+Eb) and p = mp * 2^Ep with k = Ep - Ea - Eb in 0..25; the
// residual in units of 2^(Ea+Eb) is ma*mb - mp<<k, below 2^24 in magnitude, so the low 32 bits
// of the 48-bit product (uint multiplication wraps) give it exactly; p's sign is applied by
// (n ^ s) - s
// Source: Dekker 1971 (the error of RN(a*b) is a float); ESSL 3.00 (2012) 4.1.3 (uint multiplication wraps modulo 2^32)
// Bound: exact
// Flops: 3 (df_int_scale; integer: about 35 operations)
// Steps: p zero, subnormal, Inf or NaN (its field minus 1 is 254 or more as a uint): 0 (a*b
// underflowed, overflowed or was special; the callers' df_finish returns (p, 0) for the last
// three, as in df64). k outside 0..31 (k < 0: the product had fewer than 24 bits, p is exact): 0.
// Range: e below 2^-126 is rounded (df_int_scale), as the float TwoProd's error term underflows;
// where e is used, Ea + Eb >= Ep - 31 >= -180, within df_int_scale's range.
float df_int_prod_error(float a, float b, float p) {
  uint bp = floatBitsToUint(p);
  int fp = int((bp >> 23u) & 255u);
  int ua = df_int_unit(a);
  int ub = df_int_unit(b);
  int k = fp - ua - ub + 150;
  bool none = any(bvec2(uint(fp - 1) >= 254u, uint(k) > 31u));
  uint low = df_int_magnitude(a) * df_int_magnitude(b);
  uint shifted = ((bp & 8388607u) | 8388608u) << min(uint(k), 31u);
  int n = int(low - shifted);
  int sign = floatBitsToInt(p) >> 31;
  int sn = (n ^ sign) - sign;
  float e = (df_int_scale(sn, ua + ub - 300));
  float r = (mix(e, 0.0, none));
  return r;
}

// df_two_prod (df64-int): p + e == a * b exactly, p = RN(a * b); e by integers (no split,
// so no range limit from Veltkamp's constant).
// Algorithm: TwoProd with the error term as the integer residual df_int_prod_error
// Source: Dekker 1971, mul12 (the error is representable); HFPA (2018) section 4.4
// Bound: exact
// Flops: 4
// Range: exact while e >= 2^-126; p Inf/NaN/overflowed gives e = 0 and df_finish returns (p, 0).
df_double df_two_prod(float a, float b) {
  float p = (a * b);
  float e = (df_int_prod_error(a, b, p));
  return df_double(p, e);
}

// df_two_prod (df64-int): p + e == a * b exactly, p = RN(a * b); e by integers (no split,
// so no range limit from Veltkamp's constant).
// Algorithm: TwoProd with the error term as the integer residual df_int_prod_error
// Source: Dekker 1971, mul12 (the error is representable); HFPA (2018) section 4.4
// Bound: exact
// Flops: 4
// Range: exact while e >= 2^-126; p Inf/NaN/overflowed gives e = 0 and df_finish returns (p, 0).
// (width 4: the width-1 df_two_prod applied to each component)
df_dvec4 df_two_prod(vec4 a, vec4 b) {
  df_double r0 = df_two_prod(a.x, b.x);
  df_double r1 = df_two_prod(a.y, b.y);
  df_double r2 = df_two_prod(a.z, b.z);
  df_double r3 = df_two_prod(a.w, b.w);
  return df_dvec4(vec4(r0.hi, r1.hi, r2.hi, r3.hi), vec4(r0.lo, r1.lo, r2.lo, r3.lo));
}

// df_int_signed: the integer significand of x with x's sign, two's complement in a uint.
// Algorithm: df_int_magnitude, negated modulo 2^32 by (m ^ s) - s with s the sign bit spread over
// the word (arithmetic shift), no select
// Source: ESSL 3.00 (2012) sections 4.1.3 (uint arithmetic wraps modulo 2^32) and 5.9 (>> of a
// signed int extends the sign)
// Bound: exact
// Flops: 0 (integer: df_int_magnitude, 1 shift, 1 xor, 1 sub)
uint df_int_signed(float x) {
  uint m = df_int_magnitude(x);
  uint s = uint(floatBitsToInt(x) >> 31);
  uint r = (m ^ s) - s;
  return r;
}

// df_int_sum_error: (a + b) - s exactly, for s the float sum the hardware computed.
// Algorithm: all three are integer multiples of 2^Emin (Emin the smaller exponent of a and b;
// s too unless s has a smaller exponent, and then a + b was exact); the residual in units of
// 2^Emin is ma<<da + mb<<db - ms<<ds, computed modulo 2^32: its true value is below 2^25
// because |(a+b) - s| <= ulp(s)/2 and ds <= 26, so the modular result is exact
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 (the error of RN(a+b) is a float); ESSL 3.00 (2012) 4.1.3
// Bound: exact
// Flops: 3 (integer: about 40 operations)
// Steps: shifts are clamped to 31. When the exponents differ by more than 25 the smaller operand
// is below a quarter ulp of the larger, so s is the larger: s and the larger operand get the same
// clamped shift, cancel exactly, and the residual is the smaller operand with no special case.
// Inf/NaN s, or s whose exponent field is below both operands' units (zero and subnormal s
// included: a sum that small is exact, Hauser 1996): 0. So s is decoded as a normal number (its
// field, the hidden bit always set). Scaling: n * 2^-23 (exact: n is an integer below 2^25), then
// times 2^(Emin - 127), a normal power of two built from Emin's bits: one rounding, where e is
// below 2^-126, as the float TwoSum's; no overflow, since |e| <= 2^103.
float df_int_sum_error(float a, float b, float s) {
  int ua = df_int_unit(a);
  int ub = df_int_unit(b);
  int umin = min(ua, ub);
  uint ta = df_int_signed(a) << min(uint(ua - umin), 31u);
  uint tb = df_int_signed(b) << min(uint(ub - umin), 31u);
  uint bs = floatBitsToUint(s);
  int fs = int((bs >> 23u) & 255u);
  uint sign = uint(floatBitsToInt(s) >> 31);
  uint ms = (bs & 8388607u) | 8388608u;
  uint ts = ((ms ^ sign) - sign) << min(uint(fs - umin), 31u);
  int n = int(ta + tb - ts);
  bool exact = any(bvec2(fs == 255, fs < umin));
  float f = (float(n) * 1.1920928955078125e-7);
  float e = (f * uintBitsToFloat(uint(umin) << 23u));
  float r = (mix(e, 0.0, exact));
  return r;
}

// df_fast_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); no precondition on a, b
// (the integer residual does not need |a| >= |b|).
// Algorithm: Fast2Sum replaced by TwoSum with the integer residual df_int_sum_error
// Source: Dekker 1971, Theorem 4.3 (the error is representable); Knuth, TAOCP vol. 2, 1998, 4.2.2
// Bound: exact
// Flops: 4
df_double df_fast_two_sum(float a, float b) {
  float s = (a + b);
  float e = (df_int_sum_error(a, b, s));
  return df_double(s, e);
}

// df_fast_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); no precondition on a, b
// (the integer residual does not need |a| >= |b|).
// Algorithm: Fast2Sum replaced by TwoSum with the integer residual df_int_sum_error
// Source: Dekker 1971, Theorem 4.3 (the error is representable); Knuth, TAOCP vol. 2, 1998, 4.2.2
// Bound: exact
// Flops: 4
// (width 4: the width-1 df_fast_two_sum applied to each component)
df_dvec4 df_fast_two_sum(vec4 a, vec4 b) {
  df_double r0 = df_fast_two_sum(a.x, b.x);
  df_double r1 = df_fast_two_sum(a.y, b.y);
  df_double r2 = df_fast_two_sum(a.z, b.z);
  df_double r3 = df_fast_two_sum(a.w, b.w);
  return df_dvec4(vec4(r0.hi, r1.hi, r2.hi, r3.hi), vec4(r0.lo, r1.lo, r2.lo, r3.lo));
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
  vec4 tl = (a.hi * b.lo);
  vec4 th = (a.lo * b.hi);
  vec4 cl2 = (th + tl);
  vec4 cl3 = (c.lo + cl2);
  df_dvec4 z = df_fast_two_sum(c.hi, cl3);
  df_dvec4 r = df_finish(z, c.hi);
  return r;
}

// df_two_sum (df64-int): s + e == a + b exactly, s = RN(a + b); e by integers.
// Algorithm: TwoSum with the error term as the integer residual df_int_sum_error
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (the error is representable)
// Bound: exact
// Flops: 4
df_double df_two_sum(float a, float b) {
  float s = (a + b);
  float e = (df_int_sum_error(a, b, s));
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

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
vec4 df_to_float(df_dvec4 a) {
  vec4 f = (a.hi + a.lo);
  df_dvec4 r = df_finish(df_dvec4(f, vec4(0.0)), a.hi);
  return r.hi;
}

// df_mul_dmat4_dvec4: (m * v)[i] = df_dot(row i of m, v) (vector DWTimesDW1 + pairwise
// AccurateDWPlusDW). Bound: 13u^2 * sum_j |m[j][i] v[j]| per component (absolute).
df_dvec4 df_mul_dmat4_dvec4(df_dmat4 m, df_dvec4 v) {
  df_dvec4 p;
  for (int k = 0; k < 4; ++k) {
    int idx = 3 - k;
    df_double d = df_dot(df_dvec4(vec4(m.hi[0][idx], m.hi[1][idx], m.hi[2][idx], m.hi[3][idx]), vec4(m.lo[0][idx], m.lo[1][idx], m.lo[2][idx], m.lo[3][idx])), v);
    p.hi[idx] = d.hi;
    p.lo[idx] = d.lo;
  }
  return p;
}

// df_mul_dvec4_dmat4: (v * m)[j] = df_dot(v, column j of m). Bound: 13u^2 * sum_i |v[i] m[j][i]| per component (absolute).
df_dvec4 df_mul_dvec4_dmat4(df_dvec4 v, df_dmat4 m) {
  df_dvec4 p;
  for (int k = 0; k < 4; ++k) {
    int idx = 3 - k;
    df_double d = df_dot(v, df_dvec4(m.hi[idx], m.lo[idx]));
    p.hi[idx] = d.hi;
    p.lo[idx] = d.lo;
  }
  return p;
}

// df_mul_dmat4_dmat4: column j of a * b is a * (column j of b) (df_mul_dmat4_dvec4). Bound: 13u^2 * sum_k |a[k][i] b[j][k]| per element (absolute).
df_dmat4 df_mul_dmat4_dmat4(df_dmat4 a, df_dmat4 b) {
  df_dmat4 m;
  for (int k = 0; k < 4; ++k) {
    int idx = 3 - k;
    df_dvec4 cj = df_mul_dmat4_dvec4(a, df_dvec4(b.hi[idx], b.lo[idx]));
    m.hi[idx] = cj.hi;
    m.lo[idx] = cj.lo;
  }
  return m;
}

df_dvec4 df_column_dmat4(df_dmat4 m, int j) {
  return df_dvec4(m.hi[j], m.lo[j]);
}

// df_mul_dvec4_dmat3x4: (v * m)[j] = df_dot(v, column j of m). Bound: 13u^2 * sum_i |v[i] m[j][i]| per component (absolute).
df_dvec3 df_mul_dvec4_dmat3x4(df_dvec4 v, df_dmat3x4 m) {
  df_dvec3 p;
  for (int k = 0; k < 3; ++k) {
    int idx = 2 - k;
    df_double d = df_dot(v, df_dvec4(m.hi[idx], m.lo[idx]));
    p.hi[idx] = d.hi;
    p.lo[idx] = d.lo;
  }
  return p;
}

df_dmat4 u_model;
df_dmat4 u_view;
df_dmat3x4 u_normal;
in vec4 a_position_hi;
in vec4 a_position_lo;
df_dvec4 a_position;
flat out vec4 v_model_hi;
flat out vec4 v_model_lo;
df_dvec4 v_model;
flat out vec4 v_row_hi;
flat out vec4 v_row_lo;
df_dvec4 v_row;
flat out vec4 v_view_model_hi;
flat out vec4 v_view_model_lo;
df_dvec4 v_view_model;
flat out vec3 v_normal_hi;
flat out vec3 v_normal_lo;
df_dvec3 v_normal;


void main()
{
  u_model = df_dmat4(u_model_hi - df_guard[int(df_guard[1])], u_model_lo - df_guard[int(df_guard[1])]);
  u_view = df_dmat4(u_view_hi - df_guard[int(df_guard[1])], u_view_lo - df_guard[int(df_guard[1])]);
  u_normal = df_dmat3x4(u_normal_hi - df_guard[int(df_guard[1])], u_normal_lo - df_guard[int(df_guard[1])]);
  a_position = df_dvec4(a_position_hi, a_position_lo);
  v_model = df_mul_dmat4_dvec4(u_model, a_position);
  v_row = df_mul_dvec4_dmat4(a_position, u_model);
  v_view_model = df_column_dmat4(df_mul_dmat4_dmat4(u_view, u_model), 2);
  v_normal = df_mul_dvec4_dmat3x4(a_position, u_normal);
  gl_Position = df_to_float(df_mul_dmat4_dvec4(u_view, v_model));
  v_model_hi = v_model.hi;
  v_model_lo = v_model.lo;
  v_row_hi = v_row.hi;
  v_row_lo = v_row.lo;
  v_view_model_hi = v_view_model.hi;
  v_view_model_lo = v_view_model.lo;
  v_normal_hi = v_normal.hi;
  v_normal_lo = v_normal.lo;
}
