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
// Flops: 24
// @widths 1
df_double df_dot($DF a, $DF b) {
  $DF z = df_mul(a, b);
  return z;
}

// df_dot: a.x*b.x + a.y*b.y.
// Algorithm: vector DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017; Higham 2002, section 4.2
// Bound: 10u^2 * S, S = sum of abs(a_i*b_i) (absolute error; relative when no cancellation)
// Flops: 68
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
// Flops: 112
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
// Flops: 156
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
// Flops: 183 (W = 4; 95 for W = 2, 139 for W = 3)
// Range: |a|^2 must not overflow float (|a| < 1.8e19); no prescaling is done.
// @widths 2 3 4
// @uses df_sqrt:1
df_double df_length($DF a) {
  df_double d = df_dot(a, a);
  df_double z = df_sqrt(d);
  return z;
}
