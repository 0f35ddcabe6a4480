#version 320 es
precision highp float;
precision highp int;

uniform vec3 eye_hi;
uniform vec3 eye_lo;
uniform float scale_hi;
uniform float scale_lo;
uniform mat4 viewProj;

// doublet float-float runtime: 11 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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

// df_from_float: the exact double-word (f, 0).
// Algorithm: hi = f, lo = 0
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0
df_dvec3 df_from_float(vec3 f) {
  return df_dvec3(f, vec3(0.0));
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

// df_from_float: the exact double-word (f, 0).
// Algorithm: hi = f, lo = 0
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0
df_double df_from_float(float f) {
  return df_double(f, float(0.0));
}

in vec3 position_hi;
in vec3 position_lo;
df_dvec3 position;
df_dvec3 eye;
df_double scale;
out float distanceToEye;


void main()
{
  position = df_dvec3(position_hi, position_lo);
  eye = df_dvec3(eye_hi - df_guard[int(df_guard[1])], eye_lo - df_guard[int(df_guard[1])]);
  scale = df_double(scale_hi - df_guard[int(df_guard[1])], scale_lo - df_guard[int(df_guard[1])]);
  vec3 rel = df_to_float(df_sub(position, eye));
  df_dvec3 offset = df_from_float(df_to_float(df_sub(position, eye)));
  df_double d = df_from_float(length(df_to_float(offset)) * df_to_float(scale));
  distanceToEye = df_to_float(d);
  gl_Position = viewProj * vec4(rel, 1.0);
}
