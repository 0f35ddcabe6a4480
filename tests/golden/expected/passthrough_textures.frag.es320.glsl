#version 320 es
precision highp float;
precision highp int;

uniform float scale_hi;
uniform float scale_lo;

// doublet float-float runtime: 3 functions from rules/*.glsl, guard: precise
struct df_double { float hi; float lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

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

uniform sampler2D tex;
df_double scale;
in vec4 uv;
layout(location = 0) out vec4 o;


void main()
{
  scale = df_double(scale_hi - df_guard[int(df_guard[1])], scale_lo - df_guard[int(df_guard[1])]);
  vec4 a = textureProjGradOffset(tex, uv.xyz, uv.xy, uv.zw, ivec2(1, -1));
  vec4 b = textureProjLodOffset(tex, uv.xyz, 0.0, ivec2(0, 1));
  o = (a + b) * df_to_float(df_mul_pow2(scale, 2.0));
}
