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
// doublet float-float runtime: 32 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard;  // never set: GL zero-fills it at link

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
  float ka = (mix(mix(1.0, 8192.0, big_b), 1.220703125e-4, big_a));
  float kb = (mix(mix(1.0, 1.220703125e-4, big_b), 8192.0, big_a));
  float as = (a * ka);
  float bs = (b * kb);
  df_double sa = df_split(as);
  df_double sb = df_split(bs);
  float hh = (sa.hi * sb.hi);
  float hl = (sa.hi * sb.lo);
  float lh = (sa.lo * sb.hi);
  float ll = (sa.lo * sb.lo);
  float t1 = (hh - p);
  float t2 = (t1 + hl);
  float t3 = (t2 + lh);
  float e = (t3 + ll);
  return df_double(p, e);
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
  float s = ((a + b) - df_guard);
  float bb = ((s - a) - df_guard);
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
  float s = ((a + b) - df_guard);
  float z = ((s - a) - df_guard);
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
  vec2 s = ((a + b) - df_guard);
  vec2 bb = ((s - a) - df_guard);
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
  vec2 s = ((a + b) - df_guard);
  vec2 z = ((s - a) - df_guard);
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
  if (df_gt(y, df_double(0.5, 0.0)))
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
