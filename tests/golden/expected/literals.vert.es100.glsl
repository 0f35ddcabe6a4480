#version 100
precision highp float;
precision highp int;

// doublet float-float runtime: 20 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard;  // never set: GL zero-fills it at link

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
  float th = ((a.hi / b.hi) - df_guard);
  df_double r = df_mul_f(b, th);
  float pih = (a.hi - r.hi);
  float dl = (a.lo - r.lo);
  float d = (pih + dl);
  float tl = (d / b.hi);
  df_double z = df_fast_two_sum(th, tl);
  df_double q = df_finish(z, th);
  return q;
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec3 df_two_sum(vec3 a, vec3 b) {
  vec3 s = ((a + b) - df_guard);
  vec3 bb = ((s - a) - df_guard);
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
  vec3 s = ((a + b) - df_guard);
  vec3 z = ((s - a) - df_guard);
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

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
vec2 df_to_float(df_dvec2 a) {
  vec2 f = ((a.hi + a.lo) - df_guard);
  df_dvec2 r = df_finish(df_dvec2(f, vec2(0.0)), a.hi);
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
  vec3 f = ((a.hi + a.lo) - df_guard);
  df_dvec3 r = df_finish(df_dvec3(f, vec3(0.0)), a.hi);
  return r.hi;
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_double df_two_sum(float a, float b) {
  float s = ((a + b) - df_guard);
  float bb = ((s - a) - df_guard);
  float ab = (s - bb);
  float da = (a - ab);
  float db = (b - bb);
  float e = (da + db);
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
  float v = (a.lo + s.lo);
  df_double z = df_fast_two_sum(s.hi, v);
  df_double r = df_finish(z, s.hi);
  return r;
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
// (width 3: the width-1 df_two_prod applied to each component)
df_dvec3 df_two_prod(vec3 a, vec3 b) {
  df_double r0 = df_two_prod(a.x, b.x);
  df_double r1 = df_two_prod(a.y, b.y);
  df_double r2 = df_two_prod(a.z, b.z);
  return df_dvec3(vec3(r0.hi, r1.hi, r2.hi), vec3(r0.lo, r1.lo, r2.lo));
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
  float p = ((a.hi * a.hi) - df_guard);
  df_double s = df_split(a.hi);
  float hh = (s.hi * s.hi);
  float hl = (s.hi * s.lo);
  float hl2 = (hl + hl);
  float ll = (s.lo * s.lo);
  float t1 = (hh - p);
  float t2 = (t1 + hl2);
  float e = (t2 + ll);
  float c = (a.hi * a.lo);
  float c2 = (c + c);
  float cl3 = (e + c2);
  df_double z = df_fast_two_sum(p, cl3);
  df_double r = df_finish(z, p);
  return r;
}

df_dvec3 df_splat_dvec3(df_double s) {
  return df_dvec3(vec3(s.hi), vec3(s.lo));
}

attribute vec3 offset;
varying vec4 v_info;
const df_double EARTH_RADIUS = df_double(6378137.0, 0.0);
const df_double GM = df_double(3.9860045e+14, -4348608.0);
df_double tenth;


void main()
{
  tenth = df_double(0.1 - df_guard, -1.4901161e-09 - df_guard);
  df_double r = df_two_sum(6378137.0, offset.x);
  df_double g = df_div(df_double(3.9860045e+14 - df_guard, -4348608.0 - df_guard), df_sqr(r));
  df_dvec3 p = df_add(df_mul_f2(df_splat_dvec3(tenth), offset), df_dvec3(vec3(0.33333334, -2.5, 1.0e-20) - df_guard, vec3(-9.934108e-09 - df_guard, 0.0 + df_guard, 3.1734477e-28 - df_guard)));
  v_info = vec4(df_to_float(g), df_to_float(df_add_f(r, -6378137.0)), df_to_float(df_dvec2(p.hi.xy, p.lo.xy)));
  gl_Position = vec4(df_to_float(p), 1.0);
}
