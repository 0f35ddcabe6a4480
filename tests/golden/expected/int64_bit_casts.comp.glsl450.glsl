#version 450 core
#extension GL_ARB_gpu_shader_int64 : enable
precision highp float;
precision highp int;
layout(local_size_x = 16, local_size_y = 1, local_size_z = 1) in;

struct df_dvec4 {
  vec4 hi;
  vec4 lo;
};
// doublet float-float runtime: 17 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };

// df_abs: |a|. Both words are multiplied by sign(hi) (exactly -1, 0 or +1).
// Algorithm: sign of hi applied to both words
// Source: JMP 2017, Definition 1.4 (sign of a double-word number is the sign of hi)
// Bound: exact
// Flops: 3
df_double df_abs(df_double a) {
  precise float s = (sign(a.hi));
  precise float h = (abs(a.hi));
  precise float l = (a.lo * s);
  return df_double(h, l);
}

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
  precise float az = (abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  precise float h = (mix(f, z.hi, regular));
  precise float l = (mix(0.0, z.lo, regular));
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
  precise float s1 = (intBitsToFloat(b.x));
  precise float s2 = (intBitsToFloat(b.y));
  precise float s3 = (intBitsToFloat(b.z));
  precise float h1 = (a.hi * s1);
  precise float h2 = (h1 * s2);
  precise float h = (h2 * s3);
  precise float l1 = (a.lo * s1);
  precise float l2 = (l1 * s2);
  precise float l = (l2 * s3);
  df_double z = df_double(h, l);
  df_double r = df_finish(z, h);
  return r;
}

// df_unpack_double2x32: the IEEE binary64 bits (low word, high word) of the double nearest to a
// (ties to even). With x = abs(a) * 2^-k in [1, 2): M = round(x * 2^52) = hi * 2^52 + roundEven(lo *
// 2^52) exactly (hi * 2^52 is an integer), assembled in two 32-bit words with carry.
// Algorithm: exponent of hi, exact scaling, integer assembly of the rounded significand
// Source: IEEE 754-2008 section 3.4; JMP 2017, Definition 1.4 (abs(lo) <= ulp(hi)/2)
// Bound: 0.5 ulp of binary64 (correctly rounded; exact when the value has at most 53 bits)
// Flops: 8
uvec2 df_unpack_double2x32(df_double a) {
  uint sign_bit = floatBitsToUint(a.hi) & 2147483648u;
  bool zero = a.hi == 0.0;
  bool nan = isnan(a.hi);
  bool special = any(bvec3(zero, nan, isinf(a.hi)));
  uint inf_bits = sign_bit | 2146435072u;
  uint edge_high = zero ? sign_bit : (nan ? 2146959360u : inf_bits);
  df_double m = df_abs(a);
  int bits = floatBitsToInt(m.hi);
  int e = ((bits >> 23) & 255) - 127;
  bool below = all(bvec2((bits & 8388607) == 0, m.lo < 0.0));
  int k = below ? e - 1 : e;
  int nk = 0 - k;
  df_double x = df_ldexp(m, nk);
  precise float hs = (x.hi * 8388608.0);
  precise float ls = (x.lo * 4503599627370496.0);
  precise float lr = (roundEven(ls));
  uint big = uint(hs);
  uint high = big >> 3u;
  uint low = big << 29u;
  int li = int(lr);
  uint add = uint(li >= 0 ? li : 0 - li);
  uint sum = low + add;
  uint difference = low - add;
  uint carry = sum < low ? 1u : 0u;
  uint borrow = low < add ? 1u : 0u;
  uint low_word = li >= 0 ? sum : difference;
  uint high_sig = li >= 0 ? high + carry : high - borrow;
  bool overflow = high_sig >= 2097152u;
  uint significand = overflow ? 1048576u : high_sig;
  int biased = (overflow ? k + 1 : k) + 1023;
  uint high_word = sign_bit | (uint(biased) << 20u) | (significand & 1048575u);
  uint lw = special ? 0u : low_word;
  uint hw = special ? edge_high : high_word;
  return uvec2(lw, hw);
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
  precise float h = (mix(b.hi, a.hi, c));
  precise float l = (mix(b.lo, a.lo, c));
  return df_double(h, l);
}

// df_pack_double2x32: the double whose IEEE binary64 bits are (v.x = low word, v.y = high word),
// as float-float. Significand 1.m (52 bits) = t (21 bits) + mid (24 bits) + low (8 bits), each an
// exact float; TwoSum joins the first two exactly, DWPlusFP adds the last (the only rounding:
// 53 bits to a double-word), then df_ldexp scales by the exponent (exact unless the value is
// outside float range, which gives Inf or 0). Zero and subnormal doubles give +-0.
// Algorithm: TwoSum, DWPlusFP (JMP Algorithm 4), exponent scaling
// Source: IEEE 754-2008 section 3.4; Knuth TAOCP vol. 2, 1998, 4.2.2 Theorem B; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 28
df_double df_pack_double2x32(uvec2 v) {
  uint exponent = (v.y >> 20u) & 2047u;
  uint top = (v.y & 1048575u) | 1048576u;
  uint mid = v.x >> 8u;
  uint low = v.x & 255u;
  uint sign_bit = v.y & 2147483648u;
  bool zero = exponent == 0u;
  bool special = exponent == 2047u;
  bool nan = any(bvec2((v.y & 1048575u) != 0u, v.x != 0u));
  uint edge_bits = zero ? sign_bit : (nan ? 2143289344u : (sign_bit | 2139095040u));
  precise float eh = (uintBitsToFloat(edge_bits));
  precise float t = (float(top));
  precise float tn = (t * 9.5367431640625e-07);
  precise float m = (float(mid));
  precise float mn = (m * 5.684341886080802e-14);
  precise float l = (float(low));
  precise float ln = (l * 2.220446049250313e-16);
  df_double s = df_two_sum(tn, mn);
  df_double r = df_add_f(s, ln);
  int scale = int(exponent) - 1023;
  df_double x = df_ldexp(r, scale);
  df_double n = df_neg(x);
  df_double y = df_select(sign_bit != 0u, n, x);
  df_double edge = df_double(eh, 0.0);
  df_double z = df_select(any(bvec2(zero, special)), edge, y);
  return z;
}

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_dvec2 df_neg(df_dvec2 a) {
  precise vec2 h = (-a.hi);
  precise vec2 l = (-a.lo);
  return df_dvec2(h, l);
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

uint64_t df_doubleBitsToUint64_1(df_double v) {
  return uint64_t(uint64_t(packUint2x32(df_unpack_double2x32(df_double(v.hi, v.lo)))));
}

df_double df_uint64BitsToDouble_1(uint64_t v) {
  df_double r0 = df_pack_double2x32(unpackUint2x32(uint64_t(v)));
  return r0;
}

i64vec2 df_doubleBitsToInt64_2(df_dvec2 v) {
  return i64vec2(int64_t(packUint2x32(df_unpack_double2x32(df_double(v.hi.x, v.lo.x)))), int64_t(packUint2x32(df_unpack_double2x32(df_double(v.hi.y, v.lo.y)))));
}

df_dvec2 df_int64BitsToDouble_2(i64vec2 v) {
  df_double r0 = df_pack_double2x32(unpackUint2x32(uint64_t(v.x)));
  df_double r1 = df_pack_double2x32(unpackUint2x32(uint64_t(v.y)));
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

df_double df_from_int64(int64_t i) {
  float hi = float(i);
  uint b = floatBitsToUint(hi);
  int e = int((b >> 23) & 0xFFu) - 150;
  int64_t m = int64_t((b & 0x7FFFFFu) | 0x800000u);
  int64_t back = e >= 0 ? m << e : m >> min(-e, 63);
  if ((b >> 31) != 0u) back = -back;
  return df_double(hi, float(int64_t(i - back)));
}

df_dvec4 df_make_dvec4_1_1_2(df_double a0, df_double a1, df_dvec2 a2) {
  return df_dvec4(vec4(a0.hi, a1.hi, a2.hi.x, a2.hi.y), vec4(a0.lo, a1.lo, a2.lo.x, a2.lo.y));
}

layout(std430, binding = 0) buffer Data {
  df_dvec2 x[];
};
layout(std430, binding = 1) buffer Bits {
  df_dvec4 b[];
};


void main()
{
  uint i = gl_GlobalInvocationID.x;
  df_double nudged = df_uint64BitsToDouble_1(df_doubleBitsToUint64_1(df_double(x[i].hi.x, x[i].lo.x)) ^ 1ul);
  i64vec2 patterns = df_doubleBitsToInt64_2(x[i]);
  df_dvec2 again = df_int64BitsToDouble_2(patterns);
  b[i] = df_make_dvec4_1_1_2(nudged, df_from_int64(patterns.y & 1048575l), df_sub(again, x[i]));
}
