#version 300 es
precision highp float;
precision highp int;

// doublet float-float runtime: 23 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct df_dvec2 { vec2 hi; vec2 lo; };
struct df_dvec3 { vec3 hi; vec3 lo; };
uniform highp float df_guard;  // never set: GL zero-fills it at link

// df_neg: -a, exact. Under the Uniform guard a zero result is +0 (x + 0 turns -0 into +0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_dvec3 df_neg(df_dvec3 a) {
  vec3 h = ((-a.hi) + df_guard);
  vec3 l = ((-a.lo) + df_guard);
  return df_dvec3(h, l);
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_dvec3 df_two_sum(vec3 a, vec3 b) {
  vec3 s = ((a + b) + df_guard);
  vec3 bb = ((s - a) + df_guard);
  vec3 ab = ((s - bb) + df_guard);
  vec3 da = ((a - ab) + df_guard);
  vec3 db = ((b - bb) + df_guard);
  vec3 e = ((da + db) + df_guard);
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
  vec3 s = ((a + b) + df_guard);
  vec3 z = ((s - a) + df_guard);
  vec3 e = ((b - z) + df_guard);
  return df_dvec3(s, e);
}

// df_add: a + b.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 20
// Steps: (sh,sl) = TwoSum(ah,bh); (th,tl) = TwoSum(al,bl); c = RN(sl+th);
//        (vh,vl) = Fast2Sum(sh,c); w = RN(tl+vl); (zh,zl) = Fast2Sum(vh,w).
// The bound holds for all signs (the "sloppy" 11-flop variant is unbounded under cancellation).
df_dvec3 df_add(df_dvec3 a, df_dvec3 b) {
  df_dvec3 s = df_two_sum(a.hi, b.hi);
  df_dvec3 t = df_two_sum(a.lo, b.lo);
  vec3 c = ((s.lo + t.hi) + df_guard);
  df_dvec3 v = df_fast_two_sum(s.hi, c);
  vec3 w = ((t.lo + v.lo) + df_guard);
  df_dvec3 z = df_fast_two_sum(v.hi, w);
  return z;
}

// df_sub: a - b = a + (-b); negation is exact, so the df_add bound applies unchanged.
// Algorithm: AccurateDWPlusDW on (a, -b) (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 22
df_dvec3 df_sub(df_dvec3 a, df_dvec3 b) {
  df_dvec3 nb = df_neg(b);
  df_dvec3 z = df_add(a, nb);
  return z;
}

// df_split: a == hi + lo exactly, hi and lo each fit in 12 significant bits, so any product
// of two halves is exact in float. Returned as df_dvec3(hi, lo) (not a normalized double-word).
// Algorithm: Veltkamp splitting, C = 2^12 + 1 = 4097 (s = ceil(24/2) = 12)
// Source: Dekker 1971, section 5 (attributed to Veltkamp); HFPA (2018) Algorithm 4.9
// Bound: exact
// Flops: 4
// Steps: g = RN(C*a); d = RN(a-g); hi = RN(g+d); lo = RN(a-hi).
// Range: C*a overflows when |a| > FLT_MAX/4097 (about 8.3e34); the result is then NaN.
df_dvec3 df_split(vec3 a) {
  vec3 g = ((a * 4097.0) + df_guard);
  vec3 d = ((a - g) + df_guard);
  vec3 hi = ((g + d) + df_guard);
  vec3 lo = ((a - hi) + df_guard);
  return df_dvec3(hi, lo);
}

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 17
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: needs |a|, |b| <= 8.3e34 (split) and |a*b| <= FLT_MAX; e underflows below ~2^-102.
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (NUMERICS.md).
df_dvec3 df_two_prod(vec3 a, vec3 b) {
  vec3 p = ((a * b) + df_guard);
  df_dvec3 sa = df_split(a);
  df_dvec3 sb = df_split(b);
  vec3 hh = ((sa.hi * sb.hi) + df_guard);
  vec3 hl = ((sa.hi * sb.lo) + df_guard);
  vec3 lh = ((sa.lo * sb.hi) + df_guard);
  vec3 ll = ((sa.lo * sb.lo) + df_guard);
  vec3 t1 = ((hh - p) + df_guard);
  vec3 t2 = ((t1 + hl) + df_guard);
  vec3 t3 = ((t2 + lh) + df_guard);
  vec3 e = ((t3 + ll) + df_guard);
  return df_dvec3(p, e);
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split, C = 4097)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 24
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: |ah|, |bh| <= 8.3e34 (the split multiplies by 4097); beyond that the result is NaN.
df_dvec3 df_mul(df_dvec3 a, df_dvec3 b) {
  df_dvec3 c = df_two_prod(a.hi, b.hi);
  vec3 tl = ((a.hi * b.lo) + df_guard);
  vec3 th = ((a.lo * b.hi) + df_guard);
  vec3 cl2 = ((th + tl) + df_guard);
  vec3 cl3 = ((c.lo + cl2) + df_guard);
  df_dvec3 z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_lt: a < b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_lt(df_double a, df_double b) {
  return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}

// df_gt: a > b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_gt(df_double a, df_double b) {
  return a.hi > b.hi || (a.hi == b.hi && a.lo > b.lo);
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_double df_two_sum(float a, float b) {
  float s = ((a + b) + df_guard);
  float bb = ((s - a) + df_guard);
  float ab = ((s - bb) + df_guard);
  float da = ((a - ab) + df_guard);
  float db = ((b - bb) + df_guard);
  float e = ((da + db) + df_guard);
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
  float s = ((a + b) + df_guard);
  float z = ((s - a) + df_guard);
  float e = ((b - z) + df_guard);
  return df_double(s, e);
}

// df_add: a + b.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 20
// Steps: (sh,sl) = TwoSum(ah,bh); (th,tl) = TwoSum(al,bl); c = RN(sl+th);
//        (vh,vl) = Fast2Sum(sh,c); w = RN(tl+vl); (zh,zl) = Fast2Sum(vh,w).
// The bound holds for all signs (the "sloppy" 11-flop variant is unbounded under cancellation).
df_double df_add(df_double a, df_double b) {
  df_double s = df_two_sum(a.hi, b.hi);
  df_double t = df_two_sum(a.lo, b.lo);
  float c = ((s.lo + t.hi) + df_guard);
  df_double v = df_fast_two_sum(s.hi, c);
  float w = ((t.lo + v.lo) + df_guard);
  df_double z = df_fast_two_sum(v.hi, w);
  return z;
}

// df_split: a == hi + lo exactly, hi and lo each fit in 12 significant bits, so any product
// of two halves is exact in float. Returned as df_double(hi, lo) (not a normalized double-word).
// Algorithm: Veltkamp splitting, C = 2^12 + 1 = 4097 (s = ceil(24/2) = 12)
// Source: Dekker 1971, section 5 (attributed to Veltkamp); HFPA (2018) Algorithm 4.9
// Bound: exact
// Flops: 4
// Steps: g = RN(C*a); d = RN(a-g); hi = RN(g+d); lo = RN(a-hi).
// Range: C*a overflows when |a| > FLT_MAX/4097 (about 8.3e34); the result is then NaN.
df_double df_split(float a) {
  float g = ((a * 4097.0) + df_guard);
  float d = ((a - g) + df_guard);
  float hi = ((g + d) + df_guard);
  float lo = ((a - hi) + df_guard);
  return df_double(hi, lo);
}

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 17
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: needs |a|, |b| <= 8.3e34 (split) and |a*b| <= FLT_MAX; e underflows below ~2^-102.
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (NUMERICS.md).
df_double df_two_prod(float a, float b) {
  float p = ((a * b) + df_guard);
  df_double sa = df_split(a);
  df_double sb = df_split(b);
  float hh = ((sa.hi * sb.hi) + df_guard);
  float hl = ((sa.hi * sb.lo) + df_guard);
  float lh = ((sa.lo * sb.hi) + df_guard);
  float ll = ((sa.lo * sb.lo) + df_guard);
  float t1 = ((hh - p) + df_guard);
  float t2 = ((t1 + hl) + df_guard);
  float t3 = ((t2 + lh) + df_guard);
  float e = ((t3 + ll) + df_guard);
  return df_double(p, e);
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split, C = 4097)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 24
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: |ah|, |bh| <= 8.3e34 (the split multiplies by 4097); beyond that the result is NaN.
df_double df_mul(df_double a, df_double b) {
  df_double c = df_two_prod(a.hi, b.hi);
  float tl = ((a.hi * b.lo) + df_guard);
  float th = ((a.lo * b.hi) + df_guard);
  float cl2 = ((th + tl) + df_guard);
  float cl3 = ((c.lo + cl2) + df_guard);
  df_double z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_split: a == hi + lo exactly, hi and lo each fit in 12 significant bits, so any product
// of two halves is exact in float. Returned as df_dvec2(hi, lo) (not a normalized double-word).
// Algorithm: Veltkamp splitting, C = 2^12 + 1 = 4097 (s = ceil(24/2) = 12)
// Source: Dekker 1971, section 5 (attributed to Veltkamp); HFPA (2018) Algorithm 4.9
// Bound: exact
// Flops: 4
// Steps: g = RN(C*a); d = RN(a-g); hi = RN(g+d); lo = RN(a-hi).
// Range: C*a overflows when |a| > FLT_MAX/4097 (about 8.3e34); the result is then NaN.
df_dvec2 df_split(vec2 a) {
  vec2 g = ((a * 4097.0) + df_guard);
  vec2 d = ((a - g) + df_guard);
  vec2 hi = ((g + d) + df_guard);
  vec2 lo = ((a - hi) + df_guard);
  return df_dvec2(hi, lo);
}

// df_two_prod: p + e == a * b exactly, with p = RN(a * b).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on Veltkamp halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 17
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl)
//        (every product of halves and every partial sum is exact).
// Range: needs |a|, |b| <= 8.3e34 (split) and |a*b| <= FLT_MAX; e underflows below ~2^-102.
// fma(a, b, -p) would be 2 flops but Mesa/llvmpipe does not fuse it (NUMERICS.md).
df_dvec2 df_two_prod(vec2 a, vec2 b) {
  vec2 p = ((a * b) + df_guard);
  df_dvec2 sa = df_split(a);
  df_dvec2 sb = df_split(b);
  vec2 hh = ((sa.hi * sb.hi) + df_guard);
  vec2 hl = ((sa.hi * sb.lo) + df_guard);
  vec2 lh = ((sa.lo * sb.hi) + df_guard);
  vec2 ll = ((sa.lo * sb.lo) + df_guard);
  vec2 t1 = ((hh - p) + df_guard);
  vec2 t2 = ((t1 + hl) + df_guard);
  vec2 t3 = ((t2 + lh) + df_guard);
  vec2 e = ((t3 + ll) + df_guard);
  return df_dvec2(p, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_dvec2 df_fast_two_sum(vec2 a, vec2 b) {
  vec2 s = ((a + b) + df_guard);
  vec2 z = ((s - a) + df_guard);
  vec2 e = ((b - z) + df_guard);
  return df_dvec2(s, e);
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split, C = 4097)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 24
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: |ah|, |bh| <= 8.3e34 (the split multiplies by 4097); beyond that the result is NaN.
df_dvec2 df_mul(df_dvec2 a, df_dvec2 b) {
  df_dvec2 c = df_two_prod(a.hi, b.hi);
  vec2 tl = ((a.hi * b.lo) + df_guard);
  vec2 th = ((a.lo * b.hi) + df_guard);
  vec2 cl2 = ((th + tl) + df_guard);
  vec2 cl3 = ((c.lo + cl2) + df_guard);
  df_dvec2 z = df_fast_two_sum(c.hi, cl3);
  return z;
}

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Algorithm: RN(hi + lo)
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo))
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 1
float df_to_float(df_double a) {
  float f = ((a.hi + a.lo) + df_guard);
  return f;
}

// df_equal: a == b for the whole value (all components), like GLSL == on dvecN.
// Algorithm: word-wise equality (GLSL vector == is already whole-vector)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness)
// Bound: exact
// Flops: 0 (2 vector comparisons)
bool df_equal(df_double a, df_double b) {
  return a.hi == b.hi && a.lo == b.lo;
}

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Algorithm: RN(hi + lo)
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo))
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 1
vec3 df_to_float(df_dvec3 a) {
  vec3 f = ((a.hi + a.lo) + df_guard);
  return f;
}

df_dvec3 df_splat_dvec3(df_double s) {
  return df_dvec3(vec3(s.hi), vec3(s.lo));
}

df_dvec2 df_splat_dvec2(df_double s) {
  return df_dvec2(vec2(s.hi), vec2(s.lo));
}

struct Frame {
  df_dvec3 origin;
  df_double scale;
};
struct Camera {
  Frame frame;
  df_double weights[3];
};

uniform Camera camera;
in vec3 position_hi;
in vec3 position_lo;
df_dvec3 position;
out vec2 uv_hi;
out vec2 uv_lo;
df_dvec2 uv;
out vec4 tint;

df_dvec3 to_eye(Frame f, df_dvec3 p);
df_double weigh(Camera c);

df_dvec3 to_eye(Frame f, df_dvec3 p)
{
  return df_mul(df_sub(p, f.origin), df_splat_dvec3(f.scale));
}

df_double weigh(Camera c)
{
  df_double sum = df_double(0.0, 0.0);
  for (int i = 0; i < 3; ++i)
  {
    if (df_lt(c.weights[i], df_double(0.0, 0.0)))
    {
      continue;
    }
    if (df_gt(sum, df_double(1.0e+01, 0.0)))
    {
      break;
    }
    sum = df_add(sum, c.weights[i]);
  }
  return sum;
}

void main()
{
  position = df_dvec3(position_hi, position_lo);
  df_double history[2];
  df_dvec3 eye = to_eye(camera.frame, position);
  df_double w = weigh(camera);
  history[0] = w;
  history[1] = df_mul(history[0], df_double(0.5, 0.0));
  uv = df_mul(df_dvec2(eye.hi.xy, eye.lo.xy), df_splat_dvec2(history[1]));
  tint = vec4(df_to_float(w));
  if (df_equal(w, df_double(0.0, 0.0)))
  {
    gl_Position = vec4(0.0);
    {
      uv_hi = uv.hi;
      uv_lo = uv.lo;
      return;
    }
  }
  gl_Position = vec4(df_to_float(eye), 1.0);
  uv_hi = uv.hi;
  uv_lo = uv.lo;
}
