#version 320 es
precision highp float;
precision highp int;

uniform vec3 lat_lon_height_hi;
uniform vec3 lat_lon_height_lo;
uniform vec3 eye_ecef_hi;
uniform vec3 eye_ecef_lo;
uniform float mean_anomaly_hi;
uniform float mean_anomaly_lo;
uniform float eccentricity_hi;
uniform float eccentricity_lo;
uniform mat4 view_projection;

// doublet float-float runtime: 63 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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

// df_trig_reduce: r = x - k pi/2 with |r| <= pi/4 (plus a few ulp) and q = k mod 4, pi/2 =
// P1 + P2 + P3 + P4 (four float words, 97 bits). k = k1 + k2 is the integer nearest x 2/pi,
// from the float-float product x 2/pi (k1 = its rounded hi, k2 the rest; two float integers,
// since k needs up to 40 bits). The products are subtracted largest first, each an exact TwoProd:
// x - k P1 is exact (it keeps the bits of x.lo), then k1 P2 brings it down to |r| + |k| 2^-48,
// so the later sums round relative to about |r|; the smallest terms (k2 P3, k P4) are float.
// The quadrant is computed in float: k - 4 floor(k/4) is exact for every float integer.
// k1 and k2 are roundEven, not floor(v + 0.5): without `precise` Mesa reassociates a second
// "+ 0.5" into the first (t.hi - k1 + 0.5 becomes (t.hi + 0.5) - k1, and t.hi + 0.5 rounds to
// t.hi above 2^23), k came out one short and the kernels ran outside |r| <= pi/4 (31 bits).
// Algorithm: Cody-Waite reduction by pi/2 with a four-word constant, exact TwoProd products, two-word k
// Source: Cody, Waite, 1980; Muller, Elementary Functions, 3rd ed., 2016, section 11.2
// Bound: 6u^2 * abs(r) + abs(x) * 2^-96 (absolute)
// Flops: 267
// Range: |x| < 2^40 with either guard. Callers return NaN beyond 2^40.
df_double df_trig_reduce(df_double a, out int q) {
  df_double t = df_mul(a, df_double(float(0.636619747), float(2.5682553e-08)));
  precise float k1 = (roundEven(t.hi));
  precise float f = (t.hi - k1);
  precise float k2 = (roundEven(f + t.lo));
  precise float n1 = (-k1);
  precise float n2 = (-k2);
  df_double p11 = df_two_prod(n1, 1.57079637);
  df_double r1 = df_add(a, p11);
  df_double p21 = df_two_prod(n2, 1.57079637);
  df_double r2 = df_add(r1, p21);
  df_double p12 = df_two_prod(n1, -4.37113883e-08);
  df_double r3 = df_add(r2, p12);
  df_double p22 = df_two_prod(n2, -4.37113883e-08);
  df_double r4 = df_add(r3, p22);
  df_double p13 = df_two_prod(n1, -1.71512451e-15);
  df_double r5 = df_add(r4, p13);
  precise float p23 = (n2 * -1.71512451e-15);
  precise float p14 = (n1 * 1.0562999e-23);
  precise float p24 = (n2 * 1.0562999e-23);
  precise float small = (p23 + p14 + p24);
  df_double r = df_add_f(r5, small);
  precise float m1 = (k1 - 4.0 * floor(k1 * 0.25));
  precise float m2 = (k2 - 4.0 * floor(k2 * 0.25));
  int qs = (int(m1) + int(m2)) & 3;
  q = qs;
  return r;
}

// df_mul_fast: a * b. Without FMA no product cheaper than DWTimesDW1 has a proved bound (its
// one Fast2Sum is what keeps the result a double-word number for comparisons and
// conversions), so the arithmetic is df_mul's; what df64-fast drops is df_mul's special-value
// fix-up (df_finish): an overflowing product or an Inf/NaN operand gives NaN instead of the
// IEEE result.
// Algorithm: DWTimesDW1 (JMP Algorithm 10; Dekker's mul2) with Dekker's TwoProd, no special-value fix-up
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2); Dekker 1971 (mul2)
// Bound: 7u^2
// Flops: 28 (with df_two_prod's 21 of ES 1.00; 18 with its split by bits, rules/core.glsl)
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
df_double df_mul_fast(df_double a, df_double b) {
  df_double c = df_two_prod(a.hi, b.hi);
  precise float tl = (a.hi * b.lo);
  precise float th = (a.lo * b.hi);
  precise float cl2 = (th + tl);
  precise float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_add_fast: a + b without the second TwoSum of the low words.
// Algorithm: SloppyDWPlusDW (JMP Algorithm 5; Dekker's add2)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Section 3; Yang et al., arXiv:2404.05948, 2024
// Bound: 3u^2 when a and b have the same sign; unbounded relative error for opposite signs (cancellation of the high words)
// Flops: 11
// Steps: (sh,sl) = TwoSum(ah,bh); v = RN(al+bl); w = RN(sl+v); (zh,zl) = Fast2Sum(sh,w).
// Under cancellation (ah ~ -bh) the rounding of al+bl is no longer small next to the result:
// the error stays below about u^2 (|a| + |b|) in absolute terms, which can be all of a
// small result. Use df64 where differences of nearly equal values matter.
df_double df_add_fast(df_double a, df_double b) {
  df_double s = df_two_sum(a.hi, b.hi);
  precise float v = (a.lo + b.lo);
  precise float w = (s.lo + v);
  df_double z = df_fast_two_sum(s.hi, w);
  return z;
}

// df_sin_kernel: sin(r) for |r| <= pi/4, w = r^2: r (1 + w P(w)), the Taylor series to r^17
// (truncation < 2^-54); terms from r^11 on (below 2^-28 of the result) in float.
// Algorithm: Taylor polynomial of sin in w = r^2, float tail, float-float Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 220
df_double df_sin_kernel(df_double r, df_double w) {
  precise float t = (((2.81145725e-15 * w.hi - 7.64716373e-13) * w.hi + 1.60590438e-10) * w.hi - 2.50521084e-08);
  df_double q5 = df_double(t, float(0.0));
  df_double m4 = df_mul_fast(q5, w);
  df_double q4 = df_add_fast(m4, df_double(float(2.75573188e-06), float(3.79357122e-14)));
  df_double m3 = df_mul_fast(q4, w);
  df_double q3 = df_add_fast(m3, df_double(float(-0.000198412701), float(2.72559687e-12)));
  df_double m2 = df_mul_fast(q3, w);
  df_double q2 = df_add_fast(m2, df_double(float(0.00833333377), float(-4.34617203e-10)));
  df_double m1 = df_mul_fast(q2, w);
  df_double q1 = df_add_fast(m1, df_double(float(-0.166666672), float(4.96705388e-09)));
  df_double m0 = df_mul_fast(q1, w);
  df_double q0 = df_add_f(m0, float(1.0));
  df_double s = df_mul(q0, r);
  return s;
}

// df_cos_kernel: cos(r) for |r| <= pi/4 from w = r^2: 1 + w P(w), the Taylor series to r^18
// (truncation < 2^-58); terms from r^12 on (below 2^-33) in float. cos(r) >= 0.70: the last
// additions do not cancel.
// Algorithm: Taylor polynomial of cos in w = r^2, float tail, float-float Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 8u^2
// Flops: 218
df_double df_cos_kernel(df_double w) {
  precise float t = (((-1.5619207e-16 * w.hi + 4.77947733e-14) * w.hi - 1.14707456e-11) * w.hi + 2.0876757e-09);
  df_double q6 = df_double(t, float(0.0));
  df_double m5 = df_mul_fast(q6, w);
  df_double q5 = df_add_fast(m5, df_double(float(-2.755732e-07), float(7.57511221e-15)));
  df_double m4 = df_mul_fast(q5, w);
  df_double q4 = df_add_fast(m4, df_double(float(2.48015876e-05), float(-3.40699609e-13)));
  df_double m3 = df_mul_fast(q4, w);
  df_double q3 = df_add_fast(m3, df_double(float(-0.00138888892), float(3.36310944e-11)));
  df_double m2 = df_mul_fast(q3, w);
  df_double q2 = df_add_fast(m2, df_double(float(0.0416666679), float(-1.24176347e-09)));
  df_double m1 = df_mul_fast(q2, w);
  df_double q1 = df_add_f(m1, float(-0.5));
  df_double m0 = df_mul_fast(q1, w);
  df_double c = df_add_f(m0, float(1.0));
  return c;
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

// df_sin_quadrant: sin(x + q pi/2) from the reduced r (quadrant q in 0..3): sin r, cos r,
// -sin r, -cos r.
// Algorithm: quadrant selection of df_sin_kernel / df_cos_kernel
// Source: Cody, Waite, 1980; Muller, Elementary Functions, 3rd ed., 2016, section 11.1
// Bound: 18u^2
// Flops: 251 (on the path taken)
df_double df_sin_quadrant(df_double r, int q) {
  df_double w = df_mul(r, r);
  df_double v;
  if ((q & 1) == 0) {
    v = df_sin_kernel(r, w);
  } else {
    v = df_cos_kernel(w);
  }
  df_double n = df_neg(v);
  df_double s = df_select((q & 2) != 0, n, v);
  return s;
}

// df_sin: sin(x), |x| < 2^40 (beyond: NaN, as for +-Inf and NaN). sin(+-0) = +-0. Near a zero
// x ~ k pi the error is absolute (|k| 2^-96 from the 97-bit pi/2), so the relative bits drop
// only when x is within 2^-48 |x| of k pi.
// Algorithm: df_trig_reduce (Cody-Waite, four-word pi/2), df_sin_quadrant
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 20u^2 (relative) plus abs(x) * 2^-96 absolute
// Flops: 522 (on the path taken)
// Range: |x| < 2^40.
df_double df_sin(df_double a) {
  precise float ax = (abs(a.hi));
  bool finite = ax < 1.09951163e12;
  precise float nan = ((a.hi - a.hi) / (a.hi - a.hi));
  df_double x = df_select(finite, a, df_double(float(0.0), float(0.0)));
  int q;
  df_double r = df_trig_reduce(x, q);
  df_double s = df_sin_quadrant(r, q);
  df_double z = df_select(ax == 0.0, a, s);
  df_double y = df_select(finite, z, df_double(nan, float(0.0)));
  return y;
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

// df_cos: cos(x) = sin(x + pi/2): the quadrant of df_sin plus one. |x| < 2^40 (beyond: NaN).
// Algorithm: df_trig_reduce (Cody-Waite, four-word pi/2), df_sin_quadrant at quadrant q + 1
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 20u^2 (relative) plus abs(x) * 2^-96 absolute
// Flops: 522 (on the path taken)
// Range: |x| < 2^40.
df_double df_cos(df_double a) {
  precise float ax = (abs(a.hi));
  bool finite = ax < 1.09951163e12;
  precise float nan = ((a.hi - a.hi) / (a.hi - a.hi));
  df_double x = df_select(finite, a, df_double(float(0.0), float(0.0)));
  int q;
  df_double r = df_trig_reduce(x, q);
  int q1 = (q + 1) & 3;
  df_double c = df_sin_quadrant(r, q1);
  df_double y = df_select(finite, c, df_double(nan, float(0.0)));
  return y;
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

// df_lt: a < b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_lt(df_double a, df_double b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo < b.lo))));
}

// df_atan_halve: t / (1 + sqrt(1 + t^2)) = tan(atan(t) / 2) for t >= 0.
// Algorithm: DWTimesDW1, DWPlusFP, SQRTDWtoDW, DWPlusFP, DWDivDW2
// Source: Muller, Elementary Functions, 3rd ed., 2016 (half-angle reduction); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 22u^2
// Flops: 121
df_double df_atan_halve(df_double t) {
  df_double t2 = df_mul(t, t);
  df_double o = df_add_f(t2, float(1.0));
  df_double s = df_sqrt(o);
  df_double d = df_add_f(s, float(1.0));
  df_double h = df_div(t, d);
  return h;
}

// df_atan_kernel: atan(t) for 0 <= t <= 1: two half-angle steps bring t below tan(pi/16) =
// 0.199, then the Taylor series h (1 - h^2/3 + h^4/5 ...) to h^21 (truncation < 2^-51); terms
// from h^11 on (below 2^-26 of the result) in float; the result is 4 atan(h) (exact scaling).
// Algorithm: two df_atan_halve steps, Taylor polynomial of atan, float-float Horner steps
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 55u^2
// Flops: 497
df_double df_atan_kernel(df_double t) {
  df_double h1 = df_atan_halve(t);
  df_double h = df_atan_halve(h1);
  df_double w = df_mul(h, h);
  precise float t5 = (((((0.0476190485 * w.hi - 0.0526315793) * w.hi + 0.0588235296) * w.hi - 0.0666666701) * w.hi + 0.0769230798) * w.hi - 0.0909090936);
  df_double q5 = df_double(t5, float(0.0));
  df_double m4 = df_mul_fast(q5, w);
  df_double q4 = df_add_fast(m4, df_double(float(0.111111112), float(-8.27842295e-10)));
  df_double m3 = df_mul_fast(q4, w);
  df_double q3 = df_add_fast(m3, df_double(float(-0.142857149), float(6.386212e-09)));
  df_double m2 = df_mul_fast(q3, w);
  df_double q2 = df_add_fast(m2, df_double(float(0.200000003), float(-2.98023228e-09)));
  df_double m1 = df_mul_fast(q2, w);
  df_double q1 = df_add_fast(m1, df_double(float(-0.333333343), float(9.93410776e-09)));
  df_double m0 = df_mul_fast(q1, w);
  df_double q0 = df_add_f(m0, float(1.0));
  df_double p = df_mul(q0, h);
  precise float rh = (p.hi * 4.0);
  precise float rl = (p.lo * 4.0);
  return df_double(rh, rl);
}

// df_atan2_unit: atan2(ay, ax) for ay, ax >= 0 (not both zero): atan(ay/ax) when ay <= ax,
// pi/2 - atan(ax/ay) otherwise (no cancellation: the result is >= pi/4 there).
// Algorithm: DWDivDW2 of the smaller by the larger, df_atan_kernel, AccurateDWPlusDW with pi/2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 70u^2
// Flops: 559 (on the path taken)
df_double df_atan2_unit(df_double ay, df_double ax) {
  bool steep = df_lt(ax, ay);
  df_double num = df_select(steep, ax, ay);
  df_double den = df_select(steep, ay, ax);
  df_double t = df_div(num, den);
  df_double a = df_atan_kernel(t);
  df_double r = df_sub(df_double(float(1.57079637), float(-4.37113883e-08)), a);
  df_double y = df_select(steep, r, a);
  return y;
}

// df_atan2: atan(y, x), the angle of (x, y) in [-pi, pi]: df_atan2_unit on |y|, |x|, then
// pi - a when x < 0 and the sign of y (a zero's sign read as the sign of 1/y). atan(+-0, x >= 0)
// = +-0, atan(+-0, x < 0) = +-pi; atan(+-0, +-0) = y (GLSL leaves it undefined; C gives +-pi for
// x = -0); a NaN gives NaN.
// Algorithm: df_atan2_unit, AccurateDWPlusDW with pi (float-float), sign
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.1.4
// Bound: 70u^2
// Flops: 591 (on the path taken)
df_double df_atan2(df_double y, df_double x) {
  bool origin = all(bvec2(x.hi == 0.0, y.hi == 0.0));
  df_double ay = df_abs(y);
  df_double ax = df_abs(x);
  df_double a = df_atan2_unit(ay, ax);
  df_double c = df_sub(df_double(float(3.14159274), float(-8.74227766e-08)), a);
  df_double b = df_select(x.hi < 0.0, c, a);
  precise float iy = (1.0 / y.hi);
  precise float ys = (mix(y.hi, iy, y.hi == 0.0));
  df_double n = df_neg(b);
  df_double s = df_select(ys < 0.0, n, b);
  df_double r = df_select(origin, y, s);
  return r;
}

// df_expm1_kernel: exp(r) - 1 for |r| <= 0.36 (the range left by the ln 2 reduction).
// Taylor series sum_{k>=1} r^k / k! to k = 14 (truncation < 2^-56 relative); the terms k >= 10
// (below 2^-35 of the result) are summed in float, the rest by a float-float Horner scheme.
// Algorithm: Taylor polynomial of expm1, float tail and DWTimesDW1/SloppyDWPlusDW Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001 (double-double exp); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 370
df_double df_expm1_kernel(df_double r) {
  precise float t = ((((1.14707456e-11 * r.hi + 1.60590438e-10) * r.hi + 2.0876757e-09) * r.hi + 2.50521084e-08) * r.hi + 2.75573192e-07);
  df_double q10 = df_double(t, float(0.0));
  df_double m9 = df_mul_fast(q10, r);
  df_double q9 = df_add_fast(m9, df_double(float(2.75573188e-06), float(3.79357122e-14)));
  df_double m8 = df_mul_fast(q9, r);
  df_double q8 = df_add_fast(m8, df_double(float(2.48015876e-05), float(-3.40699609e-13)));
  df_double m7 = df_mul_fast(q8, r);
  df_double q7 = df_add_fast(m7, df_double(float(0.000198412701), float(-2.72559687e-12)));
  df_double m6 = df_mul_fast(q7, r);
  df_double q6 = df_add_fast(m6, df_double(float(0.00138888892), float(-3.36310944e-11)));
  df_double m5 = df_mul_fast(q6, r);
  df_double q5 = df_add_fast(m5, df_double(float(0.00833333377), float(-4.34617203e-10)));
  df_double m4 = df_mul_fast(q5, r);
  df_double q4 = df_add_fast(m4, df_double(float(0.0416666679), float(-1.24176347e-09)));
  df_double m3 = df_mul_fast(q4, r);
  df_double q3 = df_add_fast(m3, df_double(float(0.166666672), float(-4.96705388e-09)));
  df_double m2 = df_mul_fast(q3, r);
  df_double q2 = df_add_f(m2, float(0.5));
  df_double m1 = df_mul_fast(q2, r);
  df_double q1 = df_add_f(m1, float(1.0));
  df_double e = df_mul(q1, r);
  return e;
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

// df_exp: e^x. k = round(x / ln 2); r = x - k ln 2 with ln 2 = L1 + L2 + L3 (L1 has 16 bits, so
// k L1 is exact for |k| <= 256; k L2 is an exact TwoProd), |r| <= 0.35; e^x = 2^k (1 + expm1(r)).
// Special values (C99 F.9.3.1): exp(+Inf) = +Inf, exp(-Inf) = +0, exp(NaN) = NaN; x > 89 gives
// +Inf, x < -104 gives +0. Results below 2^-102 (x < -70.7) lose bits as lo becomes subnormal
// (df_ldexp), and vertex/fragment stages may flush them. floor(v + 0.5) is safe here (unlike in
// df_trig_reduce): |v| < 151, so v + 0.5 is exact and any reassociation gives the same k.
// Algorithm: Cody-Waite reduction by ln 2 (three words), df_expm1_kernel, df_ldexp
// Source: Cody, Waite, Software Manual for the Elementary Functions, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 10u^2
// Flops: 460
// Range: normal results for -70.7 <= x <= 88.72; float-float overflows above ln(FLT_MAX).
df_double df_exp(df_double a) {
  precise float na = (-a.hi);
  bool zero = na > 104.0;
  bool over = !(a.hi <= 89.0);
  bool regular = !any(bvec2(zero, over));
  precise float big = (a.hi * 1.0e38);
  precise float eh = (mix(big, 0.0, zero));
  df_double x = df_select(regular, a, df_double(float(0.0), float(0.0)));
  precise float k = (floor(x.hi * 1.44269504 + 0.5));
  precise float nk1 = (k * -0.693145752);
  df_double r1 = df_add_f(x, nk1);
  df_double k2 = df_two_prod(k, 1.42860677e-06);
  df_double r2 = df_sub(r1, k2);
  precise float nk3 = (k * -5.49792315e-14);
  df_double r = df_add_f(r2, nk3);
  df_double e = df_expm1_kernel(r);
  df_double p = df_add_f(e, float(1.0));
  int ki = int(k);
  df_double s = df_ldexp(p, ki);
  df_double y = df_select(regular, s, df_double(eh, float(0.0)));
  return y;
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
  precise float ah = (abs(a.hi));
  bool regular = all(bvec2(ah > 0.0, ah <= 3.40282347e38));
  bool subnormal = ah < 1.17549435e-38;
  precise float scale = (mix(1.0, 1.8446744073709552e19, subnormal));
  precise float h = (a.hi * scale);
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
  precise float sh = (a.hi);
  df_double x = df_double(sh, 0.0);
  df_double r = df_select(regular, m, x);
  return r;
}

// df_log_reduce: x = m * 2^e with m in [sqrt(1/2), sqrt(2)) (df_frexp, then m doubled and e
// decremented when m < sqrt(1/2); both exact). For finite x > 0 only.
// Algorithm: df_frexp, exact doubling
// Source: IEEE 754-2008 section 5.3.3 (logB); Muller, Elementary Functions, 3rd ed., 2016, chapter 11
// Bound: exact
// Flops: 11
df_double df_log_reduce(df_double a, out int e) {
  int e0;
  df_double m0 = df_frexp(a, e0);
  bool low = m0.hi < 0.707106781;
  precise float h = (m0.hi * 2.0);
  precise float l = (m0.lo * 2.0);
  int em = e0 - 1;
  e = low ? em : e0;
  df_double d = df_double(h, l);
  df_double m = df_select(low, d, m0);
  return m;
}

// df_log_kernel: log(m) for 0.70 <= m <= 1.42 as 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172:
// 2 s sum_{n>=0} s^(2n) / (2n + 1) to n = 10 (truncation < 2^-55); the terms n >= 5 (below 2^-29
// of the result) in float. m - 1 is exact (Sterbenz), so log(m) keeps its relative accuracy as
// m -> 1.
// Algorithm: atanh series of (m - 1)/(m + 1), DWDivDW2 and float-float Horner steps
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 28u^2
// Flops: 314
df_double df_log_kernel(df_double m) {
  df_double f = df_add_f(m, float(-1.0));
  df_double d = df_add_f(m, float(1.0));
  df_double s = df_div(f, d);
  df_double w = df_mul(s, s);
  precise float t = (((((0.095238097 * w.hi + 0.105263159) * w.hi + 0.117647059) * w.hi + 0.13333334) * w.hi + 0.15384616) * w.hi + 0.181818187);
  df_double q5 = df_double(t, float(0.0));
  df_double m4 = df_mul_fast(q5, w);
  df_double q4 = df_add_fast(m4, df_double(float(0.222222224), float(-1.65568459e-09)));
  df_double m3 = df_mul_fast(q4, w);
  df_double q3 = df_add_fast(m3, df_double(float(0.285714298), float(-1.2772424e-08)));
  df_double m2 = df_mul_fast(q3, w);
  df_double q2 = df_add_fast(m2, df_double(float(0.400000006), float(-5.96046457e-09)));
  df_double m1 = df_mul_fast(q2, w);
  df_double q1 = df_add_fast(m1, df_double(float(0.666666687), float(-1.98682155e-08)));
  df_double m0 = df_mul_fast(q1, w);
  df_double q0 = df_add_f(m0, float(2.0));
  df_double l = df_mul(q0, s);
  return l;
}

// df_log: natural logarithm: log(x) = e ln 2 + log(m), x = m 2^e (df_log_reduce). |log(m)| <=
// 0.35 <= |e ln 2| / 2 when e != 0, so the sum does not cancel. Special values (C99 F.9.3.7):
// log(+-0) = -Inf, log(x < 0) = NaN, log(+Inf) = +Inf, log(NaN) = NaN.
// Algorithm: df_log_reduce, df_log_kernel, DWTimesFP1 of ln 2 (float-float) by e, AccurateDWPlusDW
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 28u^2
// Flops: 380
// Range: every finite x > 0 (subnormal hi included: df_frexp scales it).
df_double df_log(df_double a) {
  bool regular = all(bvec2(a.hi > 0.0, a.hi <= 3.40282347e38));
  precise float pole = (-1.0 / abs(a.hi));
  precise float root = (sqrt(a.hi));
  precise float beyond = (mix(root, a.hi, a.hi > 0.0));
  precise float special = (mix(beyond, pole, a.hi == 0.0));
  df_double x = df_select(regular, a, df_double(float(1.0), float(0.0)));
  int e;
  df_double m = df_log_reduce(x, e);
  df_double l = df_log_kernel(m);
  precise float fe = (float(e));
  df_double el = df_mul_f(df_double(float(0.693147182), float(-1.90465421e-09)), fe);
  df_double r = df_add(el, l);
  df_double y = df_select(regular, r, df_double(special, float(0.0)));
  return y;
}

// df_exp2: 2^x = 2^k * e^(f ln 2) with k = round(x), f = x - k exact (|f| <= 1/2), the product
// f ln 2 (ln 2 as a float-float) in DWTimesDW1. Special values as df_exp; x > 129 gives +Inf,
// x < -150 gives +0.
// Algorithm: split into integer and fraction, DWTimesDW1 by ln 2, df_expm1_kernel, df_ldexp
// Source: Cody, Waite, 1980; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 431
// Range: normal results for -102 <= x <= 127.99.
df_double df_exp2(df_double a) {
  precise float na = (-a.hi);
  bool zero = na > 150.0;
  bool over = !(a.hi <= 129.0);
  bool regular = !any(bvec2(zero, over));
  precise float big = (a.hi * 1.0e38);
  precise float eh = (mix(big, 0.0, zero));
  df_double x = df_select(regular, a, df_double(float(0.0), float(0.0)));
  precise float k = (floor(x.hi + 0.5));
  precise float nk = (-k);
  df_double f = df_add_f(x, nk);
  df_double r = df_mul(f, df_double(float(0.693147182), float(-1.90465421e-09)));
  df_double e = df_expm1_kernel(r);
  df_double p = df_add_f(e, float(1.0));
  int ki = int(k);
  df_double s = df_ldexp(p, ki);
  df_double y = df_select(regular, s, df_double(eh, float(0.0)));
  return y;
}

// df_log2: log2(x) = e + log(m) log2(e) (log2(e) as a float-float); special values as df_log.
// Algorithm: df_log_reduce, df_log_kernel, DWTimesDW1 by log2(e), DWPlusFP of the exponent
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 37u^2
// Flops: 369
// Range: every finite x > 0.
df_double df_log2(df_double a) {
  bool regular = all(bvec2(a.hi > 0.0, a.hi <= 3.40282347e38));
  precise float pole = (-1.0 / abs(a.hi));
  precise float root = (sqrt(a.hi));
  precise float beyond = (mix(root, a.hi, a.hi > 0.0));
  precise float special = (mix(beyond, pole, a.hi == 0.0));
  df_double x = df_select(regular, a, df_double(float(1.0), float(0.0)));
  int e;
  df_double m = df_log_reduce(x, e);
  df_double l = df_log_kernel(m);
  df_double l2 = df_mul(l, df_double(float(1.44269502), float(1.92596303e-08)));
  precise float fe = (float(e));
  df_double r = df_add_f(l2, fe);
  df_double y = df_select(regular, r, df_double(special, float(0.0)));
  return y;
}

// df_pow: x^y = e^(y log x). The absolute error of y log(x) becomes a relative error of the
// result, so the bound grows with |y log x| (= |log(result)|): 40u^2 + 31u^2 |y log x|; >= 44 bits
// needs |y log x| <= 1/2 or so (docs/transcendentals.md has the measured bits per decade).
// Special values (C99 F.9.4.4 where GLSL leaves them undefined): pow(x, +-0) = 1, pow(1, y) = 1,
// pow(+0, y > 0) = +0, pow(+0, y < 0) = +Inf, pow(x < 0, y) = NaN (also for integer y).
// Algorithm: df_log, DWTimesDW1, df_exp
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.4.4
// Bound: 40u^2 + 31u^2 * abs(y * log(x)) (relative)
// Flops: 869
df_double df_pow(df_double x, df_double y) {
  bool one = any(bvec2(y.hi == 0.0, all(bvec2(x.hi == 1.0, x.lo == 0.0))));
  df_double l = df_log(x);
  df_double z = df_mul(y, l);
  df_double r = df_exp(z);
  df_double p = df_select(one, df_double(float(1.0), float(0.0)), r);
  return p;
}

// df_tan: sin(r) / cos(r) in quadrants 0 and 2, -cos(r) / sin(r) in 1 and 3. tan(+-0) = +-0.
// Algorithm: df_trig_reduce, df_sin_kernel and df_cos_kernel, DWDivDW2
// Source: Cody, Waite, 1980; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 40u^2 (relative) plus abs(x) * 2^-96 absolute times (1 + tan(x)^2)
// Flops: 818
// Range: |x| < 2^40.
df_double df_tan(df_double a) {
  precise float ax = (abs(a.hi));
  bool finite = ax < 1.09951163e12;
  precise float nan = ((a.hi - a.hi) / (a.hi - a.hi));
  df_double x = df_select(finite, a, df_double(float(0.0), float(0.0)));
  int q;
  df_double r = df_trig_reduce(x, q);
  df_double w = df_mul(r, r);
  df_double s = df_sin_kernel(r, w);
  df_double c = df_cos_kernel(w);
  bool even = (q & 1) == 0;
  df_double num = df_select(even, s, c);
  df_double den = df_select(even, c, s);
  df_double t = df_div(num, den);
  df_double u = df_neg(t);
  df_double v = df_select(even, t, u);
  df_double z = df_select(ax == 0.0, a, v);
  df_double y = df_select(finite, z, df_double(nan, float(0.0)));
  return y;
}

// df_asin: atan(x, sqrt((1 - x)(1 + x))): 1 - x is exact near |x| = 1, so the cosine keeps its
// relative accuracy there. asin(+-0) = +-0, |x| > 1 gives NaN.
// Algorithm: DWPlusFP, DWTimesDW1, SQRTDWtoDW, df_atan2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 75u^2
// Flops: 674 (on the path taken)
// Range: |x| <= 1.
df_double df_asin(df_double a) {
  df_double n = df_neg(a);
  df_double om = df_add_f(n, float(1.0));
  df_double op = df_add_f(a, float(1.0));
  df_double p = df_mul(om, op);
  df_double c = df_sqrt(p);
  df_double r = df_atan2(a, c);
  df_double y = df_select(a.hi == 0.0, a, r);
  return y;
}

// df_acos: atan(sqrt((1 - x)(1 + x)), x), in [0, pi]. |x| > 1 gives NaN.
// Algorithm: DWPlusFP, DWTimesDW1, SQRTDWtoDW, df_atan2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 75u^2
// Flops: 674 (on the path taken)
// Range: |x| <= 1.
df_double df_acos(df_double a) {
  df_double n = df_neg(a);
  df_double om = df_add_f(n, float(1.0));
  df_double op = df_add_f(a, float(1.0));
  df_double p = df_mul(om, op);
  df_double c = df_sqrt(p);
  df_double r = df_atan2(c, a);
  return r;
}

// df_atan: arctangent, in (-pi/2, pi/2). atan(+-0) = +-0, atan(+-Inf) = +-pi/2, NaN -> NaN.
// Algorithm: df_atan2_unit(abs(x), 1), sign of x
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.1.3
// Bound: 70u^2
// Flops: 565 (on the path taken)
df_double df_atan(df_double a) {
  df_double t = df_abs(a);
  df_double r = df_atan2_unit(t, df_double(float(1.0), float(0.0)));
  df_double n = df_neg(r);
  df_double s = df_select(a.hi < 0.0, n, r);
  df_double y = df_select(a.hi == 0.0, a, s);
  return y;
}

// df_expm1: e^x - 1: df_expm1_kernel for |x| < 0.3465 (relative accuracy near 0), else
// df_exp(x) - 1 (e^x - 1 cancels by at most 2.4 there).
// Algorithm: df_expm1_kernel, or df_exp and DWPlusFP
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 30u^2
// Flops: 471 (on the path taken)
df_double df_expm1(df_double a) {
  precise float ax = (abs(a.hi));
  df_double r;
  if (ax < 0.3465) {
    r = df_expm1_kernel(a);
  } else {
    df_double e = df_exp(a);
    r = df_add_f(e, float(-1.0));
  }
  return r;
}

// df_sinh: sinh|x| = (E + E / (E + 1)) / 2 with E = expm1(|x|): no cancellation near 0.
// sinh(+-0) = +-0; |x| > 88.72 gives +-Inf (float-float's range ends at FLT_MAX, the true
// overflow is at 89.4); NaN gives NaN.
// Algorithm: df_expm1, DWPlusFP, DWDivDW2, AccurateDWPlusDW, sign
// Source: Muller, Elementary Functions, 3rd ed., 2016 (sinh from expm1); C99 Annex F.9.2.5
// Bound: 50u^2
// Flops: 548 (on the path taken)
// Range: |x| <= 88.72.
df_double df_sinh(df_double a) {
  precise float ax = (abs(a.hi));
  bool over = !(ax <= 88.72);
  precise float big = (a.hi * 1.0e38);
  df_double x = df_select(over, df_double(float(0.0), float(0.0)), a);
  df_double t = df_abs(x);
  df_double e = df_expm1(t);
  df_double e1 = df_add_f(e, float(1.0));
  df_double q = df_div(e, e1);
  df_double s = df_add(e, q);
  precise float h = (s.hi * 0.5);
  precise float l = (s.lo * 0.5);
  precise float nh = (-h);
  precise float nl = (-l);
  bool negative = a.hi < 0.0;
  precise float sh = (mix(h, nh, negative));
  precise float sl = (mix(l, nl, negative));
  df_double v = df_double(sh, sl);
  df_double w = df_select(over, df_double(big, float(0.0)), v);
  df_double y = df_select(ax == 0.0, a, w);
  return y;
}

// df_cosh: (e^|x| + 1/e^|x|) / 2 (no cancellation: both terms positive). |x| > 88.72 gives
// +Inf (true overflow at 89.4); NaN gives NaN.
// Algorithm: df_exp, DWDivDW2, AccurateDWPlusDW
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 20u^2
// Flops: 525
// Range: |x| <= 88.72.
df_double df_cosh(df_double a) {
  df_double t = df_abs(a);
  df_double e = df_exp(t);
  df_double i = df_div(df_double(float(1.0), float(0.0)), e);
  df_double s = df_add(e, i);
  precise float h = (s.hi * 0.5);
  precise float l = (s.lo * 0.5);
  return df_double(h, l);
}

// df_tanh: tanh|x| = E / (E + 2) with E = expm1(2|x|): no cancellation near 0; |x| > 22 gives
// +-1 (1 - tanh < 2^-62). tanh(+-0) = +-0; NaN gives NaN.
// Algorithm: df_expm1, DWPlusFP, DWDivDW2, sign
// Source: Muller, Elementary Functions, 3rd ed., 2016 (tanh from expm1); C99 Annex F.9.2.6
// Bound: 50u^2
// Flops: 528 (on the path taken)
df_double df_tanh(df_double a) {
  precise float ax = (abs(a.hi));
  precise float one = (mix(1.0, -1.0, a.hi < 0.0));
  bool saturated = ax > 22.0;
  df_double x = df_select(saturated, df_double(float(0.0), float(0.0)), a);
  precise float xh = (abs(x.hi));
  precise float th = (xh * 2.0);
  precise float tl = (x.lo * one * 2.0);
  df_double e = df_expm1(df_double(th, tl));
  df_double d = df_add_f(e, float(2.0));
  df_double q = df_div(e, d);
  precise float h = (q.hi * one);
  precise float l = (q.lo * one);
  df_double v = df_double(h, l);
  df_double w = df_select(saturated, df_double(one, float(0.0)), v);
  df_double y = df_select(ax == 0.0, a, w);
  return y;
}

// df_exp: e^x. k = round(x / ln 2); r = x - k ln 2 with ln 2 = L1 + L2 + L3 (L1 has 16 bits, so
// k L1 is exact for |k| <= 256; k L2 is an exact TwoProd), |r| <= 0.35; e^x = 2^k (1 + expm1(r)).
// Special values (C99 F.9.3.1): exp(+Inf) = +Inf, exp(-Inf) = +0, exp(NaN) = NaN; x > 89 gives
// +Inf, x < -104 gives +0. Results below 2^-102 (x < -70.7) lose bits as lo becomes subnormal
// (df_ldexp), and vertex/fragment stages may flush them. floor(v + 0.5) is safe here (unlike in
// df_trig_reduce): |v| < 151, so v + 0.5 is exact and any reassociation gives the same k.
// Algorithm: Cody-Waite reduction by ln 2 (three words), df_expm1_kernel, df_ldexp
// Source: Cody, Waite, Software Manual for the Elementary Functions, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 10u^2
// Flops: 460
// Range: normal results for -70.7 <= x <= 88.72; float-float overflows above ln(FLT_MAX).
// (width 2: the width-1 df_exp applied to each component)
df_dvec2 df_exp(df_dvec2 a) {
  df_double r0 = df_exp(df_double(a.hi.x, a.lo.x));
  df_double r1 = df_exp(df_double(a.hi.y, a.lo.y));
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
}

// df_sin: sin(x), |x| < 2^40 (beyond: NaN, as for +-Inf and NaN). sin(+-0) = +-0. Near a zero
// x ~ k pi the error is absolute (|k| 2^-96 from the 97-bit pi/2), so the relative bits drop
// only when x is within 2^-48 |x| of k pi.
// Algorithm: df_trig_reduce (Cody-Waite, four-word pi/2), df_sin_quadrant
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 20u^2 (relative) plus abs(x) * 2^-96 absolute
// Flops: 522 (on the path taken)
// Range: |x| < 2^40.
// (width 2: the width-1 df_sin applied to each component)
df_dvec2 df_sin(df_dvec2 a) {
  df_double r0 = df_sin(df_double(a.hi.x, a.lo.x));
  df_double r1 = df_sin(df_double(a.hi.y, a.lo.y));
  return df_dvec2(vec2(r0.hi, r1.hi), vec2(r0.lo, r1.lo));
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

df_dvec3 df_make_dvec3_1_1_1(df_double a0, df_double a1, df_double a2) {
  return df_dvec3(vec3(a0.hi, a1.hi, a2.hi), vec3(a0.lo, a1.lo, a2.lo));
}

df_dvec2 df_make_dvec2_1_1(df_double a0, df_double a1) {
  return df_dvec2(vec2(a0.hi, a1.hi), vec2(a0.lo, a1.lo));
}

df_dvec3 lat_lon_height;
df_dvec3 eye_ecef;
df_double mean_anomaly;
df_double eccentricity;
out float shade;

df_dvec3 ecef(df_dvec3 llh);
df_double kepler(df_double m, df_double e);

df_dvec3 ecef(df_dvec3 llh)
{
  df_double s = df_sin(df_double(llh.hi.x, llh.lo.x));
  df_double n = df_div(df_double(6378137.0, 0.0), df_sqrt(df_add_f(df_neg(df_mul(df_mul(df_double(0.00669438, -2.0380875e-10), s), s)), 1.0)));
  df_double r = df_mul(df_add(n, df_double(llh.hi.z, llh.lo.z)), df_cos(df_double(llh.hi.x, llh.lo.x)));
  return df_make_dvec3_1_1_1(df_mul(r, df_cos(df_double(llh.hi.y, llh.lo.y))), df_mul(r, df_sin(df_double(llh.hi.y, llh.lo.y))), df_mul(df_add(df_mul(n, df_double(0.9933056, -3.5214816e-09)), df_double(llh.hi.z, llh.lo.z)), s));
}

df_double kepler(df_double m, df_double e)
{
  df_double E = m;
  for (int i = 0; i < 4; ++i)
  {
    E = df_sub(E, df_div(df_sub(df_sub(E, df_mul(e, df_sin(E))), m), df_add_f(df_neg(df_mul(e, df_cos(E))), 1.0)));
  }
  return E;
}

void main()
{
  lat_lon_height = df_dvec3(lat_lon_height_hi - df_guard[int(df_guard[1])], lat_lon_height_lo - df_guard[int(df_guard[1])]);
  eye_ecef = df_dvec3(eye_ecef_hi - df_guard[int(df_guard[1])], eye_ecef_lo - df_guard[int(df_guard[1])]);
  mean_anomaly = df_double(mean_anomaly_hi - df_guard[int(df_guard[1])], mean_anomaly_lo - df_guard[int(df_guard[1])]);
  eccentricity = df_double(eccentricity_hi - df_guard[int(df_guard[1])], eccentricity_lo - df_guard[int(df_guard[1])]);
  df_dvec3 p = df_sub(ecef(lat_lon_height), eye_ecef);
  df_double E = kepler(mean_anomaly, eccentricity);
  df_double nu = df_mul_pow2(df_atan2(df_mul(df_sqrt(df_add_f(eccentricity, 1.0)), df_sin(df_mul_pow2(E, 0.5))), df_mul(df_sqrt(df_add_f(df_neg(eccentricity), 1.0)), df_cos(df_mul_pow2(E, 0.5)))), 2.0);
  df_dvec2 v = df_make_dvec2_1_1(nu, E);
  df_double t = df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_add(df_exp(df_neg(df_double(v.hi.x, v.lo.x))), df_log(df_add_f(df_abs(df_double(v.hi.y, v.lo.y)), 1.0))), df_exp2(df_double(v.hi.x, v.lo.x))), df_log2(df_add_f(df_double(v.hi.y, v.lo.y), 2.0))), df_pow(df_abs(df_double(v.hi.x, v.lo.x)), df_double(0.75, 0.0))), df_tan(df_double(v.hi.x, v.lo.x))), df_asin(df_mul(df_double(v.hi.y, v.lo.y), df_double(0.1, -1.4901161e-09)))), df_acos(df_mul(df_double(v.hi.x, v.lo.x), df_double(0.1, -1.4901161e-09)))), df_atan(df_double(v.hi.y, v.lo.y))), df_sinh(df_double(v.hi.x, v.lo.x))), df_cosh(df_double(v.hi.y, v.lo.y))), df_tanh(df_double(v.hi.x, v.lo.x)));
  df_dvec2 w = df_add(df_exp(v), df_sin(v));
  shade = df_to_float(df_add(df_add(t, df_double(w.hi.x, w.lo.x)), df_double(w.hi.y, w.lo.y)));
  gl_Position = view_projection * vec4(df_to_float(p), 1.0);
}
