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

// df_length: sqrt(dot(a, a)), W = 2..4. No cancellation in dot(a, a), so its error is
// relative: (7 + 3d)u^2 with d = ceil(log2 W); sqrt halves that and adds 25/8 u^2:
// 8.125u^2 for W = 2, 9.625u^2 for W = 3, 4 (first order).
// Algorithm: df_dot(a, a) then SQRTDWtoDW (LLMPR Algorithm 8)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 9.625u^2
// Flops: 210 (W = 4; 110 for W = 2, 160 for W = 3)
// Range: |a|^2 must not overflow float (|a| < 1.8e19); no prescaling is done.
// @widths 2 3 4
// @uses df_sqrt:1
df_double df_length($DF a) {
  df_double d = df_dot(a, a);
  df_double z = df_sqrt(d);
  return z;
}

// df_distance: length(a - b). The difference of exact inputs is one AccurateDWPlusDW per
// component (3u^2 relative), which adds 3u^2 to df_length's relative bound.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6), then df_length
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 12.625u^2
// Flops: 233 (W = 4)
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

// df_normalize: a / length(a) per component (width 1: sign(a), exact).
// Algorithm: df_length, then DWDivDW2 (JMP Algorithm 17) per component
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1; Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023
// Bound: 24.625u^2
// Flops: 366 (W = 4)
// Range: |a|^2 must not overflow float, as for df_length.
// @widths 2 3 4
// @uses df_length:W df_div:W
$DF df_normalize($DF a) {
  df_double n = df_length(a);
  $DF r = df_div(a, $DF($F(n.hi), $F(n.lo)));
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
  if (d.hi < 0.0) {
    return n;
  }
  $DF m = df_neg(n);
  return m;
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
  if (k.hi < 0.0) {
    return $DF($F(0.0), $F(0.0));
  }
  df_double s = df_sqrt(k);
  df_double ed = df_mul(eta, d);
  df_double f = df_add(ed, s);
  $DF a = df_mul($DF($F(eta.hi), $F(eta.lo)), i);
  $DF b = df_mul($DF($F(f.hi), $F(f.lo)), n);
  $DF r = df_sub(a, b);
  return r;
}
