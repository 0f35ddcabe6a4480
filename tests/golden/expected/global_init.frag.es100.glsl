#version 100
precision highp float;
precision highp int;

uniform float farPlane_hi;
uniform float farPlane_lo;

// doublet float-float runtime: 8 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
uniform highp float df_guard;  // never set: GL zero-fills it at link

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
  float h = ((regular ? z.hi : f));
  float l = ((regular ? z.lo : 0.0));
  return df_double(h, l);
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
  float f = ((a.hi + a.lo) - df_guard);
  df_double r = df_finish(df_double(f, float(0.0)), a.hi);
  return r.hi;
}

// df_split: a == hi + lo exactly, hi and lo each fit in 12 significant bits, so any product
// of two halves is exact in float. Returned as df_double(hi, lo) (not a normalized double-word).
// Algorithm: Veltkamp splitting, C = 2^12 + 1 = 4097 (s = ceil(24/2) = 12)
// Source: Dekker 1971, section 5 (attributed to Veltkamp); HFPA (2018) Algorithm 4.9
// Bound: exact
// Flops: 4
// Steps: g = RN(C*a); d = RN(a-g); hi = RN(g+d); lo = RN(a-hi).
// Range: C*a overflows when |a| > FLT_MAX/4097 (about 8.3e34); the result is then NaN.
// df_two_prod scales its operands by powers of two so that it never splits such a value.
df_double df_split(float a) {
  float g = ((a * 4097.0) - df_guard);
  float d = ((a - g) - df_guard);
  float hi = (g + d);
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

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves of power-of-two scaled operands
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10; Boldo, "Pitfalls of a full floating-point proof", IJCAR 2006 (overflow of the split)
// Bound: exact
// Flops: 21 (plus 2 comparisons and 2 selects)
// Steps: p = RN(a*b); as = a*k, bs = b/k with k = 2^-13 when |a| > 1e34, 2^13 when |b| > 1e34,
//        else 1 (exact: as*bs == a*b); (ah,al) = split(as); (bh,bl) = split(bs);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: when a*b is finite and one operand exceeds 1e34 the other is below 3.5e4, so both
// scaled operands stay below FLT_MAX/4097 and nothing underflows; the split never overflows.
// Exact when |a*b| <= FLT_MAX (minus an ulp); e underflows below ~2^-102. When a*b overflows
// (or an operand is Inf or NaN) p is the IEEE result and e is not finite: the callers'
// df_finish then returns (p, 0). The scale factors are selects, not a branch: a branch here
// let lavapipe's vertex stage delete the error terms under the Uniform guard (stages_test).
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (docs/numerics.md).
df_double df_two_prod(float a, float b) {
  float p = ((a * b) - df_guard);
  float aa = (abs(a));
  float ab = (abs(b));
  bool big_a = aa > 1.0e34;
  bool big_b = ab > 1.0e34;
  float ka = ((big_a ? 1.220703125e-4 : (big_b ? 8192.0 : 1.0)));
  float kb = ((big_a ? 8192.0 : (big_b ? 1.220703125e-4 : 1.0)));
  float as = (a * ka);
  float bs = (b * kb);
  df_double sa = df_split(as);
  df_double sb = df_split(bs);
  float e = (df_mul12_error(sa, sb, p));
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
  float s = ((a + b) - df_guard);
  float z = ((s - a) - df_guard);
  float e = (b - z);
  return df_double(s, e);
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

df_double farPlane;
const df_double kScale = df_double(0.5, 0.0);
df_double half_far;
float k;
df_double scaled;
df_double t2;
varying vec2 uv;

df_double twice(df_double x);

df_double twice(df_double x)
{
  return df_mul_pow2(x, 2.0);
}

void main()
{
  farPlane = df_double(farPlane_hi, farPlane_lo);
  half_far = df_double(1.0 - df_guard, 0.0 + df_guard);
  k = 2.0 / log2(df_to_float(farPlane) + 1.0);
  scaled = df_mul_pow2(farPlane, 2.0);
  t2 = twice(scaled);
  gl_FragColor = vec4(k, df_to_float(scaled), df_to_float(df_mul(t2, half_far)), uv.x);
}
