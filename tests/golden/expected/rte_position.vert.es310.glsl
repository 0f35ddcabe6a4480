#version 310 es
precision highp float;
precision highp int;

// doublet float-float runtime: 6 functions from rules/*.glsl, guard: uniform df_guard
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

in vec3 position_hi;
in vec3 position_lo;
df_dvec3 position;
uniform vec3 eye_hi;
uniform vec3 eye_lo;
df_dvec3 eye;
uniform mat4 viewProj;


void main()
{
  position = df_dvec3(position_hi, position_lo);
  eye = df_dvec3(eye_hi, eye_lo);
  gl_Position = viewProj * vec4(df_to_float(df_sub(position, eye)), 1.0);
}
