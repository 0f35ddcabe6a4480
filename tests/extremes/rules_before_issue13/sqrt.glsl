// rules/sqrt.glsl -- float-float square root.
//
// Sources:
//   [LLMPR] V. Lefevre, N. Louvet, J.-M. Muller, J. Picot, L. Rideau, "Accurate calculation of
//           Euclidean norms using double-word arithmetic", ACM TOMS 49(1), article 1, 2023,
//           Algorithm 8 (SQRTDWtoDW) and its error bound 25/8 u^2.
//   [Dekker] T. J. Dekker, Numerische Mathematik 18, 1971 (mul12, used for the exact square).
//   [Karp-Markstein] A. H. Karp, P. Markstein, "High-precision division and square root",
//           ACM TOMS 23(4), 1997 (the same one-Newton-step idea).
// Notation: u = 2^-24.

// df_sqrt: sqrt(a) for a >= 0; sqrt(+-0) = +-0, sqrt(+Inf) = +Inf, sqrt(a < 0) and sqrt(NaN) = NaN
// (IEEE 754-2008 section 5.4.1; GLSL leaves a < 0 undefined, the drivers give NaN).
// Algorithm: SQRTDWtoDW (LLMPR Algorithm 8), FMA step replaced by an exact Dekker square, then df_finish
// Source: Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023, Algorithm 8 and its theorem
// Bound: 25/8 u^2
// Flops: 31
// Steps (LLMPR Algorithm 8, our no-FMA form):
//   sh   = RN(sqrt(ah))
//   (p,e)= TwoProd(sh, sh)           p + e == sh^2 exactly
//   r0   = RN(ah - p)                exact: ah/2 <= p <= 2ah (Sterbenz)
//   rho1 = RN(r0 - e)                == RN(ah - sh^2), the value fma(-sh, sh, ah) returns
//   rho2 = RN(al + rho1)
//   sl   = RN(rho2 / (2 sh))
//   (zh,zl) = Fast2Sum(sh, sl)
// sh is guarded too: Mesa rewrites sqrt(x)*sqrt(x) to |x|, which would zero the residual.
// So every value equals the FMA version's and the 25/8 u^2 bound carries over, given a
// correctly rounded float sqrt and division (x86 llvmpipe). With a k-ulp sqrt (GLSL permits a
// few ulp) the step is still a Newton correction: about (25/8 + k + k^2/2) u^2 (estimate,
// not proved). Special values end in df_finish(z, sh): a = +-0 gives sl = 0/0 = NaN and so
// (sh, 0) = (+-0, 0); Inf, NaN and negative a give (sqrt(ah), 0) = (Inf or NaN, 0).
// Range: every finite a >= 0; within an ulp of FLT_MAX sh*sh overflows and the result is sh alone.
// @widths 1 2 3 4
$DF df_sqrt($DF a) {
  $PRECISE $F sh = $G(sqrt(a.hi));
  $DF sq = df_two_prod(sh, sh);
  $PRECISE $F r0 = $SAFE(a.hi - sq.hi);
  $PRECISE $F rho1 = $SAFE(r0 - sq.lo);
  $PRECISE $F rho2 = $SAFE(a.lo + rho1);
  $PRECISE $F sh2 = $SAFE(sh * 2.0);
  $PRECISE $F sl = $SAFE(rho2 / sh2);
  $DF z = df_fast_two_sum(sh, sl);
  $DF r = df_finish(z, sh);
  return r;
}

// df_inversesqrt: 1 / sqrt(a): SQRTDWtoDW, then DWDivDW2 of 1 by the root.
// Algorithm: SQRTDWtoDW (LLMPR Algorithm 8), then DWDivDW2 (JMP Algorithm 17)
// Source: Lefevre, Louvet, Muller, Picot, Rideau, ACM TOMS 49(1), 2023; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 7.1
// Bound: 18.125u^2
// Flops: 70
// @widths 1 2 3 4
// @uses df_sqrt:W df_div:W
$DF df_inversesqrt($DF a) {
  $DF s = df_sqrt(a);
  $DF r = df_div($DF($F(1.0), $F(0.0)), s);
  return r;
}
