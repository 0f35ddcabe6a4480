// rules/geometric.glsl -- dot product and length of float-float vectors.
// Built from df_mul (DWTimesDW1, 7u^2; 5u^2 per MR 2022), df_add (AccurateDWPlusDW,
// 3u^2 + 13u^3) and df_sqrt (SQRTDWtoDW, 25/8 u^2). The component products are computed
// with one vector df_mul, then summed pairwise.
//
// Error analysis (u = 2^-24, first order, no overflow/underflow): each product p_i has
// |p_i - a_i b_i| <= 7u^2 |a_i b_i|; each addition adds at most 3u^2 times its result, and the
// results at one level of the pairwise tree sum to at most S = sum |a_i b_i|. With depth
// d = ceil(log2 W): |dot - a.b| <= (7 + 3d) u^2 S + O(u^3). That is a relative bound only
// when there is no cancellation (S = |a.b|), as for length: dot(a, a) has relative error
// (7 + 3d)u^2 and sqrt halves it and adds 25/8 u^2.
//
// Sources:
//   [JMP]   M. Joldes, J.-M. Muller, V. Popescu, "Tight and rigorous error bounds for basic
//           building blocks of double-word arithmetic", ACM TOMS 44(2), 2017 (Algorithms 6, 10).
//   [MR]    J.-M. Muller, L. Rideau, ACM TOMS 48(1), 2022 (DWTimesDW1 is within 5u^2).
//   [LLMPR] V. Lefevre, N. Louvet, J.-M. Muller, J. Picot, L. Rideau, "Accurate calculation of
//           Euclidean norms using double-word arithmetic", ACM TOMS 49(1), 2023.
//   [Higham] N. J. Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., SIAM,
//           2002, section 4.2 (pairwise summation error).

// df_dot: width 1 is the product a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Muller, Rideau, ACM TOMS 48(1), 2022
// Bound: 7u^2
// Flops: 29
// @widths 1
df_double df_dot($DF a, $DF b) {
  $DF z = df_mul(a, b);
  return z;
}

// df_dot: a.x*b.x + a.y*b.y.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 10u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 79
// @widths 2
// @uses df_add:1
df_double df_dot($DF a, $DF b) {
  $DF m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_add(x, y);
  return z;
}

// df_dot: (a.x*b.x + a.y*b.y) + a.z*b.z.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then 2 AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 13u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 129
// @widths 3
// @uses df_add:1
df_double df_dot($DF a, $DF b) {
  $DF m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_double(m.hi.z, m.lo.z);
  df_double xy = df_add(x, y);
  df_double r = df_add(xy, z);
  return r;
}

// df_dot: (a.x*b.x + a.y*b.y) + (a.z*b.z + a.w*b.w), pairwise.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then 3 AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 13u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 179
// @widths 4
// @uses df_add:1
df_double df_dot($DF a, $DF b) {
  $DF m = df_mul(a, b);
  df_double x = df_double(m.hi.x, m.lo.x);
  df_double y = df_double(m.hi.y, m.lo.y);
  df_double z = df_double(m.hi.z, m.lo.z);
  df_double w = df_double(m.hi.w, m.lo.w);
  df_double xy = df_add(x, y);
  df_double zw = df_add(z, w);
  df_double r = df_add(xy, zw);
  return r;
}

// df_length: width 1 is |a|.
// Algorithm: df_abs (sign of hi applied to both words)
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// @widths 1
df_double df_length($DF a) {
  $DF z = df_abs(a);
  return z;
}

// df_norm_scale: (s, 1/s), powers of two that bring the largest component of hi into
// [2^-36, 2^60] (as hypot does): s = 2^-90 when some |hi_i| > 2^60, 2^90 when every |hi_i| < 2^-36,
// else 1. Then the squares of the scaled vector neither overflow (4 * 2^120 < 2^128) nor lose
// their error terms to underflow (the largest square is >= 2^-72, its low words >= ~2^-120),
// and scaling is exact. Values in [2^-36, 2^60] take s = 1: bit for bit the unscaled result.
// +-Inf scales to +-Inf; NaN fails both tests and is not scaled.
// Algorithm: two threshold tests on abs(hi), selection of power-of-two constants
// Source: IEEE 754-2008 section 9.2 (hypot: scaling to avoid spurious overflow and underflow); Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023, section 5 (scaled norms)
// Bound: exact
// Flops: 4 (W = 4: one abs per component; plus 2 vector comparisons and 4 selects)
// @widths 2 3 4
vec2 df_norm_scale($F h) {
  $PRECISE $F ah = $SAFE(abs(h));
  bool big = any(greaterThan(ah, $F(1.152921504606846976e18)));
  bool small = all(lessThan(ah, $F(1.4551915228366851806640625e-11)));
  $PRECISE float down = $SAFE($SEL(big, 8.0779356694631608874161005085933746e-28, 1.0));
  $PRECISE float s = $SAFE($SEL(small, 1.237940039285380274899124224e27, down));
  $PRECISE float up = $SAFE($SEL(big, 1.237940039285380274899124224e27, 1.0));
  $PRECISE float back = $SAFE($SEL(small, 8.0779356694631608874161005085933746e-28, up));
  return vec2(s, back);
}

// df_scale_pow2: a * s for a power of two s: both words scaled, exact while no word over- or
// underflows.
// Algorithm: scaling of hi and lo by a power of two
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 2 (per component)
// @widths 1 2 3 4
$DF df_scale_pow2($DF a, float s) {
  $PRECISE $F h = $SAFE(a.hi * s);
  $PRECISE $F l = $SAFE(a.lo * s);
  return $DF(h, l);
}

// df_length: sqrt(dot(a, a)), W = 2..4, on a scaled by df_norm_scale and scaled back, so any
// vector whose length is within float range gets it (the squares alone would overflow above
// |a| ~ 1.8e19 and underflow below ~1e-19). No cancellation in dot(a, a), so its error is
// relative: (7 + 3d)u^2 with d = ceil(log2 W); sqrt halves that and adds 25/8 u^2:
// 8.125u^2 for W = 2, 9.625u^2 for W = 3, 4 (first order). A length beyond float range is
// (+Inf, 0) (df_finish); one below it tapers into float's subnormals as the scaled-back words
// round.
// Algorithm: df_norm_scale, df_dot(a, a), SQRTDWtoDW (LLMPR Algorithm 8), scaled back, df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 9.625u^2
// Flops: 225 (W = 4; 119 for W = 2, 172 for W = 3)
// Range: every vector (scaled); exact scaling, so the bound holds for lengths in [2^-100, FLT_MAX].
// @widths 2 3 4
// @uses df_norm_scale:W df_scale_pow2:W,1 df_sqrt:1 df_finish:1
df_double df_length($DF a) {
  $PRECISE vec2 k = $SAFE(df_norm_scale(a.hi));
  $DF b = df_scale_pow2(a, k.x);
  df_double d = df_dot(b, b);
  df_double n = df_sqrt(d);
  df_double z = df_scale_pow2(n, k.y);
  df_double r = df_finish(z, z.hi);
  return r;
}

// df_distance: length(a - b). The difference of exact inputs is one AccurateDWPlusDW per
// component (3u^2 relative), which adds 3u^2 to df_length's relative bound.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6), then df_length
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 12.625u^2
// Flops: 248 (W = 4)
// @widths 1 2 3 4
// @uses df_sub:W df_length:W
df_double df_distance($DF a, $DF b) {
  $DF d = df_sub(a, b);
  df_double r = df_length(d);
  return r;
}

// df_cross: a.yzx * b.zxy - a.zxy * b.yzx (two DWTimesDW1 and one AccurateDWPlusDW per component).
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 10u^2 * (abs(a_j b_k) + abs(a_k b_j)) per component (absolute, first order)
// Flops: 81
// @widths 3
df_dvec3 df_cross(df_dvec3 a, df_dvec3 b) {
  df_dvec3 p = df_mul(df_dvec3(a.hi.yzx, a.lo.yzx), df_dvec3(b.hi.zxy, b.lo.zxy));
  df_dvec3 q = df_mul(df_dvec3(a.hi.zxy, a.lo.zxy), df_dvec3(b.hi.yzx, b.lo.yzx));
  df_dvec3 r = df_sub(p, q);
  return r;
}

// df_normalize: a / length(a) per component (width 1: sign(a), exact), computed on a scaled by
// df_norm_scale (a / |a| does not change when a is scaled by a power of two), so every vector
// whose components are within float range normalizes, however long or short.
// Algorithm: df_norm_scale, df_dot, SQRTDWtoDW (LLMPR Algorithm 8), then DWDivDW2 (JMP Algorithm 17) per component
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 24.625u^2
// Flops: 378 (W = 4)
// @widths 2 3 4
// @uses df_norm_scale:W df_scale_pow2:W df_dot:W df_sqrt:1 df_div:W
$DF df_normalize($DF a) {
  $PRECISE vec2 k = $SAFE(df_norm_scale(a.hi));
  $DF b = df_scale_pow2(a, k.x);
  df_double d = df_dot(b, b);
  df_double n = df_sqrt(d);
  $DF r = df_div(b, $DF($F(n.hi), $F(n.lo)));
  return r;
}

// df_faceforward: dot(nref, i) < 0 ? n : -n. The selection is exact; the sign of the dot
// product carries df_dot's error (wrong only where |dot| is below that bound).
// Algorithm: df_dot, then selection
// Source: GLSL 4.60 (2019) section 8.5 (faceforward); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: exact
// Flops: 181 (W = 4)
// @widths 1 2 3 4
// @uses df_dot:W df_neg:W
$DF df_faceforward($DF n, $DF i, $DF nref) {
  df_double d = df_dot(nref, i);
  $B facing = $B(d.hi < 0.0);
  $DF m = df_neg(n);
  $DF r = df_select(facing, n, m);
  return r;
}

// df_reflect: i - 2 dot(n, i) n. With S = sum |n_j i_j|: the dot has 13u^2 S, doubling is exact,
// the product adds 7u^2, the subtraction 3u^2 of the result r_i.
// Algorithm: df_dot, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.5 (reflect); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r_i) + 20u^2 * 2S abs(n_i) (absolute per component, first order)
// Flops: 245 (W = 4)
// @widths 1 2 3 4
// @uses df_dot:W df_add:1 df_mul:W df_sub:W
$DF df_reflect($DF i, $DF n) {
  df_double d = df_dot(n, i);
  df_double d2 = df_add(d, d);
  $DF p = df_mul($DF($F(d2.hi), $F(d2.lo)), n);
  $DF r = df_sub(i, p);
  return r;
}

// df_refract: k = 1 - eta^2 (1 - dot(n, i)^2); k < 0 gives 0, else eta i - (eta d + sqrt(k)) n.
// First order, with the rules' bounds composed; sqrt(k) amplifies k's absolute error when k is
// near 0 (grazing incidence), so the bound holds for k not close to 0.
// Algorithm: df_dot, DWTimesDW1, AccurateDWPlusDW, SQRTDWtoDW (LLMPR Algorithm 8)
// Source: GLSL 4.60 (2019) section 8.5 (refract); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 60u^2 * (abs(eta i_j) + (abs(eta d) + sqrt(k)) abs(n_j)) (absolute per component, first order, k not near 0)
// Flops: 481 (W = 4)
// @widths 1 2 3 4
// @uses df_dot:W df_mul:1,W df_sub:1,W df_add:1 df_sqrt:1
$DF df_refract($DF i, $DF n, df_double eta) {
  df_double d = df_dot(n, i);
  df_double one = df_double(1.0, 0.0);
  df_double dd = df_mul(d, d);
  df_double c = df_sub(one, dd);
  df_double e2 = df_mul(eta, eta);
  df_double ec = df_mul(e2, c);
  df_double k = df_sub(one, ec);
  bool total = k.hi < 0.0;
  df_double s = df_sqrt(k);
  df_double ed = df_mul(eta, d);
  df_double f = df_add(ed, s);
  $DF a = df_mul($DF($F(eta.hi), $F(eta.lo)), i);
  $DF b = df_mul($DF($F(f.hi), $F(f.lo)), n);
  $DF t = df_sub(a, b);
  $DF r = df_select($B(total), $DF($F(0.0), $F(0.0)), t);
  return r;
}
