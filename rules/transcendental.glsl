// rules/transcendental.glsl -- exp, exp2, log, log2, pow, sin, cos, tan, asin, acos, atan (one and
// two arguments), sinh, cosh, tanh on float-float values. GLSL's fp64 has none of them; doublet
// accepts them on double and dvecN as an extension (docs/transcendentals.md).
//
// Sources:
//   [CW]    W. J. Cody, W. Waite, Software Manual for the Elementary Functions, Prentice-Hall,
//           1980: additive argument reduction x - k*C with C split into words whose products
//           with k are exact (ln 2 for exp, pi/2 for sin/cos).
//   [Muller] J.-M. Muller, Elementary Functions: Algorithms and Implementation, 3rd ed.,
//           Birkhauser, 2016, chapters 11 (range reduction) and 5 (polynomial evaluation);
//           log(m) = 2 atanh((m-1)/(m+1)), atan(x) = 2 atan(x / (1 + sqrt(1 + x^2))).
//   [JMP]   M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017: the error bounds of the
//           double-word steps (df_add 3u^2, df_mul 7u^2, df_div 15u^2, df_add_f 2u^2).
//   [QD]    Y. Hida, X. S. Li, D. H. Bailey, "Algorithms for quad-double precision floating
//           point arithmetic", ARITH-15, 2001: the double-double elementary functions
//           (Taylor series after reduction, exp via 2^k * (1 + expm1(r))).
//   [C99]   ISO/IEC 9899:1999, Annex F.9: special values (exp(-Inf) = 0, log(0) = -Inf, ...).
//   [YLHLQL] Y. Yang et al., "On the robustness of double-word addition algorithms",
//           arXiv:2404.05948, 2024: SloppyDWPlusDW keeps 3u^2 unless the high words cancel in
//           the Sterbenz sense (b/2 <= -a <= 2b).
// Horner steps: every float-float step q = m + c of the kernels below (c the coefficient, m the
// product of the previous step by r or w) has |m| <= 0.09 |c| (expm1: |r|/(k+1) <= 0.36/4; the
// others: w times a coefficient ratio, <= 0.031), so the high words never cancel and the sloppy
// addition df_add_fast (11 flops, [JMP] Algorithm 5) keeps the 3u^2 of AccurateDWPlusDW (21)
// [YLHLQL]. The products m are finite and bounded, so they skip df_mul's special-value fix-up
// (df_mul_fast: the same DWTimesDW1, same pairs). docs/transcendentals.md has the bits before and after.
// Notation: u = 2^-24. Bounds are first-order sums of the step bounds of [JMP] through each
// algorithm (an estimate, not a machine-checked proof); docs/transcendentals.md gives the bits
// measured against MPFR on lavapipe and Mesa GLES. Constants are float words computed with
// 300-bit arithmetic (mpmath): c = hi + lo to 2^-49 relative or better.

// df_expm1_kernel: exp(r) - 1 for |r| <= 0.36 (the range left by the ln 2 reduction).
// Taylor series sum_{k>=1} r^k / k! to k = 14 (truncation < 2^-56 relative); the terms k >= 10
// (below 2^-35 of the result) are summed in float, the rest by a float-float Horner scheme.
// Algorithm: Taylor polynomial of expm1, float tail and DWTimesDW1/SloppyDWPlusDW Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001 (double-double exp); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 370
// @widths 1
$DF df_expm1_kernel($DF r) {
  $PRECISE $F t = $SAFE((((1.14707456e-11 * r.hi + 1.60590438e-10) * r.hi + 2.0876757e-09) * r.hi + 2.50521084e-08) * r.hi + 2.75573192e-07);
  $DF q10 = $DF(t, $F(0.0));
  $DF m9 = df_mul_fast(q10, r);
  $DF q9 = df_add_fast(m9, $DF($F(2.75573188e-06), $F(3.79357122e-14)));
  $DF m8 = df_mul_fast(q9, r);
  $DF q8 = df_add_fast(m8, $DF($F(2.48015876e-05), $F(-3.40699609e-13)));
  $DF m7 = df_mul_fast(q8, r);
  $DF q7 = df_add_fast(m7, $DF($F(0.000198412701), $F(-2.72559687e-12)));
  $DF m6 = df_mul_fast(q7, r);
  $DF q6 = df_add_fast(m6, $DF($F(0.00138888892), $F(-3.36310944e-11)));
  $DF m5 = df_mul_fast(q6, r);
  $DF q5 = df_add_fast(m5, $DF($F(0.00833333377), $F(-4.34617203e-10)));
  $DF m4 = df_mul_fast(q5, r);
  $DF q4 = df_add_fast(m4, $DF($F(0.0416666679), $F(-1.24176347e-09)));
  $DF m3 = df_mul_fast(q4, r);
  $DF q3 = df_add_fast(m3, $DF($F(0.166666672), $F(-4.96705388e-09)));
  $DF m2 = df_mul_fast(q3, r);
  $DF q2 = df_add_f(m2, $F(0.5));
  $DF m1 = df_mul_fast(q2, r);
  $DF q1 = df_add_f(m1, $F(1.0));
  $DF e = df_mul(q1, r);
  return e;
}

// df_exp: e^x. k = round(x / ln 2); r = x - k ln 2 with ln 2 = L1 + L2 + L3 (L1 has 16 bits, so
// k L1 is exact for |k| <= 256; k L2 is an exact TwoProd), |r| <= 0.35; e^x = 2^k (1 + expm1(r)).
// Special values (C99 F.9.3.1): exp(+Inf) = +Inf, exp(-Inf) = +0, exp(NaN) = NaN; x > 89 gives
// +Inf, x < -104 gives +0. Results below 2^-102 (x < -70.7) lose bits as lo becomes subnormal
// (df_ldexp), and vertex/fragment stages may flush them. floor(v + 0.5) is safe here (unlike in
// df_trig_reduce): |v| < 151, so v + 0.5 is exact and any reassociation gives the same k.
// Algorithm: Cody-Waite reduction by ln 2 (three words), df_expm1_kernel, df_ldexp
// Source: Cody, Waite, Software Manual for the Elementary Functions, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 10u^2
// Flops: 460
// Range: normal results for -70.7 <= x <= 88.72; float-float overflows above ln(FLT_MAX).
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_expm1_kernel:1 df_ldexp:1 df_add_f:1 df_sub:1 df_two_prod:1 df_select:1
$DF df_exp($DF a) {
  $PRECISE $F na = $SAFE(-a.hi);
  bool zero = na > 104.0;
  bool over = !(a.hi <= 89.0);
  bool regular = !any(bvec2(zero, over));
  $PRECISE $F big = $SAFE(a.hi * 1.0e38);
  $PRECISE $F eh = $SAFE($SEL(zero, 0.0, big));
  $DF x = df_select(regular, a, $DF($F(0.0), $F(0.0)));
  $PRECISE $F k = $G(floor(x.hi * 1.44269504 + 0.5));
  $PRECISE $F nk1 = $G(k * -0.693145752);
  $DF r1 = df_add_f(x, nk1);
  $DF k2 = df_two_prod(k, 1.42860677e-06);
  $DF r2 = df_sub(r1, k2);
  $PRECISE $F nk3 = $SAFE(k * -5.49792315e-14);
  $DF r = df_add_f(r2, nk3);
  $DF e = df_expm1_kernel(r);
  $DF p = df_add_f(e, $F(1.0));
  int ki = int(k);
  $DF s = df_ldexp(p, ki);
  $DF y = df_select(regular, s, $DF(eh, $F(0.0)));
  return y;
}

// df_exp2: 2^x = 2^k * e^(f ln 2) with k = round(x), f = x - k exact (|f| <= 1/2), the product
// f ln 2 (ln 2 as a float-float) in DWTimesDW1. Special values as df_exp; x > 129 gives +Inf,
// x < -150 gives +0.
// Algorithm: split into integer and fraction, DWTimesDW1 by ln 2, df_expm1_kernel, df_ldexp
// Source: Cody, Waite, 1980; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 431
// Range: normal results for -102 <= x <= 127.99.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_expm1_kernel:1 df_ldexp:1 df_add_f:1 df_mul:1 df_select:1
$DF df_exp2($DF a) {
  $PRECISE $F na = $SAFE(-a.hi);
  bool zero = na > 150.0;
  bool over = !(a.hi <= 129.0);
  bool regular = !any(bvec2(zero, over));
  $PRECISE $F big = $SAFE(a.hi * 1.0e38);
  $PRECISE $F eh = $SAFE($SEL(zero, 0.0, big));
  $DF x = df_select(regular, a, $DF($F(0.0), $F(0.0)));
  $PRECISE $F k = $G(floor(x.hi + 0.5));
  $PRECISE $F nk = $SAFE(-k);
  $DF f = df_add_f(x, nk);
  $DF r = df_mul(f, $DF($F(0.693147182), $F(-1.90465421e-09)));
  $DF e = df_expm1_kernel(r);
  $DF p = df_add_f(e, $F(1.0));
  int ki = int(k);
  $DF s = df_ldexp(p, ki);
  $DF y = df_select(regular, s, $DF(eh, $F(0.0)));
  return y;
}

// df_log_kernel: log(m) for 0.70 <= m <= 1.42 as 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172:
// 2 s sum_{n>=0} s^(2n) / (2n + 1) to n = 10 (truncation < 2^-55); the terms n >= 5 (below 2^-29
// of the result) in float. m - 1 is exact (Sterbenz), so log(m) keeps its relative accuracy as
// m -> 1.
// Algorithm: atanh series of (m - 1)/(m + 1), DWDivDW2 and float-float Horner steps
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 28u^2
// Flops: 314
// @widths 1
$DF df_log_kernel($DF m) {
  $DF f = df_add_f(m, $F(-1.0));
  $DF d = df_add_f(m, $F(1.0));
  $DF s = df_div(f, d);
  $DF w = df_mul(s, s);
  $PRECISE $F t = $SAFE(((((0.095238097 * w.hi + 0.105263159) * w.hi + 0.117647059) * w.hi + 0.13333334) * w.hi + 0.15384616) * w.hi + 0.181818187);
  $DF q5 = $DF(t, $F(0.0));
  $DF m4 = df_mul_fast(q5, w);
  $DF q4 = df_add_fast(m4, $DF($F(0.222222224), $F(-1.65568459e-09)));
  $DF m3 = df_mul_fast(q4, w);
  $DF q3 = df_add_fast(m3, $DF($F(0.285714298), $F(-1.2772424e-08)));
  $DF m2 = df_mul_fast(q3, w);
  $DF q2 = df_add_fast(m2, $DF($F(0.400000006), $F(-5.96046457e-09)));
  $DF m1 = df_mul_fast(q2, w);
  $DF q1 = df_add_fast(m1, $DF($F(0.666666687), $F(-1.98682155e-08)));
  $DF m0 = df_mul_fast(q1, w);
  $DF q0 = df_add_f(m0, $F(2.0));
  $DF l = df_mul(q0, s);
  return l;
}

// df_log_reduce: x = m * 2^e with m in [sqrt(1/2), sqrt(2)) (df_frexp, then m doubled and e
// decremented when m < sqrt(1/2); both exact). For finite x > 0 only.
// Algorithm: df_frexp, exact doubling
// Source: IEEE 754-2008 section 5.3.3 (logB); Muller, Elementary Functions, 3rd ed., 2016, chapter 11
// Bound: exact
// Flops: 11
// @widths 1
// @min-es 300
// @uses df_frexp:1 df_select:1
$DF df_log_reduce($DF a, out int e) {
  int e0;
  $DF m0 = df_frexp(a, e0);
  bool low = m0.hi < 0.707106781;
  $PRECISE $F h = $SAFE(m0.hi * 2.0);
  $PRECISE $F l = $SAFE(m0.lo * 2.0);
  int em = e0 - 1;
  e = low ? em : e0;
  $DF d = $DF(h, l);
  $DF m = df_select(low, d, m0);
  return m;
}

// df_log: natural logarithm: log(x) = e ln 2 + log(m), x = m 2^e (df_log_reduce). |log(m)| <=
// 0.35 <= |e ln 2| / 2 when e != 0, so the sum does not cancel. Special values (C99 F.9.3.7):
// log(+-0) = -Inf, log(x < 0) = NaN, log(+Inf) = +Inf, log(NaN) = NaN.
// Algorithm: df_log_reduce, df_log_kernel, DWTimesFP1 of ln 2 (float-float) by e, AccurateDWPlusDW
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 28u^2
// Flops: 380
// Range: every finite x > 0 (subnormal hi included: df_frexp scales it).
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_log_reduce:1 df_log_kernel:1 df_mul_f:1 df_add:1 df_select:1
$DF df_log($DF a) {
  bool regular = all(bvec2(a.hi > 0.0, a.hi <= 3.40282347e38));
  $PRECISE $F pole = $SAFE(-1.0 / abs(a.hi));
  $PRECISE $F root = $SAFE(sqrt(a.hi));
  $PRECISE $F beyond = $SAFE($SEL(a.hi > 0.0, a.hi, root));
  $PRECISE $F special = $SAFE($SEL(a.hi == 0.0, pole, beyond));
  $DF x = df_select(regular, a, $DF($F(1.0), $F(0.0)));
  int e;
  $DF m = df_log_reduce(x, e);
  $DF l = df_log_kernel(m);
  $PRECISE $F fe = $SAFE(float(e));
  $DF el = df_mul_f($DF($F(0.693147182), $F(-1.90465421e-09)), fe);
  $DF r = df_add(el, l);
  $DF y = df_select(regular, r, $DF(special, $F(0.0)));
  return y;
}

// df_log2: log2(x) = e + log(m) log2(e) (log2(e) as a float-float); special values as df_log.
// Algorithm: df_log_reduce, df_log_kernel, DWTimesDW1 by log2(e), DWPlusFP of the exponent
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 37u^2
// Flops: 369
// Range: every finite x > 0.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_log_reduce:1 df_log_kernel:1 df_mul:1 df_add_f:1 df_select:1
$DF df_log2($DF a) {
  bool regular = all(bvec2(a.hi > 0.0, a.hi <= 3.40282347e38));
  $PRECISE $F pole = $SAFE(-1.0 / abs(a.hi));
  $PRECISE $F root = $SAFE(sqrt(a.hi));
  $PRECISE $F beyond = $SAFE($SEL(a.hi > 0.0, a.hi, root));
  $PRECISE $F special = $SAFE($SEL(a.hi == 0.0, pole, beyond));
  $DF x = df_select(regular, a, $DF($F(1.0), $F(0.0)));
  int e;
  $DF m = df_log_reduce(x, e);
  $DF l = df_log_kernel(m);
  $DF l2 = df_mul(l, $DF($F(1.44269502), $F(1.92596303e-08)));
  $PRECISE $F fe = $SAFE(float(e));
  $DF r = df_add_f(l2, fe);
  $DF y = df_select(regular, r, $DF(special, $F(0.0)));
  return y;
}

// df_pow: x^y = e^(y log x). The absolute error of y log(x) becomes a relative error of the
// result, so the bound grows with |y log x| (= |log(result)|): 40u^2 + 31u^2 |y log x|; >= 44 bits
// needs |y log x| <= 1/2 or so (docs/transcendentals.md has the measured bits per decade).
// Special values (C99 F.9.4.4 where GLSL leaves them undefined): pow(x, +-0) = 1, pow(1, y) = 1,
// pow(+0, y > 0) = +0, pow(+0, y < 0) = +Inf, pow(x < 0, y) = NaN (also for integer y).
// Algorithm: df_log, DWTimesDW1, df_exp
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.4.4
// Bound: 40u^2 + 31u^2 * abs(y * log(x)) (relative)
// Flops: 869
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_log:1 df_mul:1 df_exp:1 df_select:1
$DF df_pow($DF x, $DF y) {
  bool one = any(bvec2(y.hi == 0.0, all(bvec2(x.hi == 1.0, x.lo == 0.0))));
  $DF l = df_log(x);
  $DF z = df_mul(y, l);
  $DF r = df_exp(z);
  $DF p = df_select(one, $DF($F(1.0), $F(0.0)), r);
  return p;
}

// df_trig_reduce: r = x - k pi/2 with |r| <= pi/4 (plus a few ulp) and q = k mod 4, pi/2 =
// P1 + P2 + P3 + P4 (four float words, 97 bits). k = k1 + k2 is the integer nearest x 2/pi,
// from the float-float product x 2/pi (k1 = its rounded hi, k2 the rest; two float integers,
// since k needs up to 40 bits). The products are subtracted largest first, each an exact TwoProd:
// x - k P1 is exact (it keeps the bits of x.lo), then k1 P2 brings it down to |r| + |k| 2^-48,
// so the later sums round relative to about |r|; the smallest terms (k2 P3, k P4) are float.
// The quadrant is computed in float: k - 4 floor(k/4) is exact for every float integer.
// k1 and k2 are roundEven, not floor(v + 0.5): without `precise` Mesa reassociates a second
// "+ 0.5" into the first (t.hi - k1 + 0.5 becomes (t.hi + 0.5) - k1, and t.hi + 0.5 rounds to
// t.hi above 2^23), k came out one short and the kernels ran outside |r| <= pi/4 (31 bits).
// Algorithm: Cody-Waite reduction by pi/2 with a four-word constant, exact TwoProd products, two-word k
// Source: Cody, Waite, 1980; Muller, Elementary Functions, 3rd ed., 2016, section 11.2
// Bound: 6u^2 * abs(r) + abs(x) * 2^-96 (absolute)
// Flops: 267
// Range: |x| < 2^40 with either guard. Callers return NaN beyond 2^40.
// @widths 1
// @min-es 300
$DF df_trig_reduce($DF a, out int q) {
  $DF t = df_mul(a, $DF($F(0.636619747), $F(2.5682553e-08)));
  $PRECISE $F k1 = $G(roundEven(t.hi));
  $PRECISE $F f = $G(t.hi - k1);
  $PRECISE $F k2 = $G(roundEven(f + t.lo));
  $PRECISE $F n1 = $SAFE(-k1);
  $PRECISE $F n2 = $SAFE(-k2);
  $DF p11 = df_two_prod(n1, 1.57079637);
  $DF r1 = df_add(a, p11);
  $DF p21 = df_two_prod(n2, 1.57079637);
  $DF r2 = df_add(r1, p21);
  $DF p12 = df_two_prod(n1, -4.37113883e-08);
  $DF r3 = df_add(r2, p12);
  $DF p22 = df_two_prod(n2, -4.37113883e-08);
  $DF r4 = df_add(r3, p22);
  $DF p13 = df_two_prod(n1, -1.71512451e-15);
  $DF r5 = df_add(r4, p13);
  $PRECISE $F p23 = $SAFE(n2 * -1.71512451e-15);
  $PRECISE $F p14 = $SAFE(n1 * 1.0562999e-23);
  $PRECISE $F p24 = $SAFE(n2 * 1.0562999e-23);
  $PRECISE $F small = $SAFE(p23 + p14 + p24);
  $DF r = df_add_f(r5, small);
  $PRECISE $F m1 = $G(k1 - 4.0 * floor(k1 * 0.25));
  $PRECISE $F m2 = $G(k2 - 4.0 * floor(k2 * 0.25));
  int qs = (int(m1) + int(m2)) & 3;
  q = qs;
  return r;
}

// df_sin_kernel: sin(r) for |r| <= pi/4, w = r^2: r (1 + w P(w)), the Taylor series to r^17
// (truncation < 2^-54); terms from r^11 on (below 2^-28 of the result) in float.
// Algorithm: Taylor polynomial of sin in w = r^2, float tail, float-float Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 12u^2
// Flops: 220
// @widths 1
$DF df_sin_kernel($DF r, $DF w) {
  $PRECISE $F t = $SAFE(((2.81145725e-15 * w.hi - 7.64716373e-13) * w.hi + 1.60590438e-10) * w.hi - 2.50521084e-08);
  $DF q5 = $DF(t, $F(0.0));
  $DF m4 = df_mul_fast(q5, w);
  $DF q4 = df_add_fast(m4, $DF($F(2.75573188e-06), $F(3.79357122e-14)));
  $DF m3 = df_mul_fast(q4, w);
  $DF q3 = df_add_fast(m3, $DF($F(-0.000198412701), $F(2.72559687e-12)));
  $DF m2 = df_mul_fast(q3, w);
  $DF q2 = df_add_fast(m2, $DF($F(0.00833333377), $F(-4.34617203e-10)));
  $DF m1 = df_mul_fast(q2, w);
  $DF q1 = df_add_fast(m1, $DF($F(-0.166666672), $F(4.96705388e-09)));
  $DF m0 = df_mul_fast(q1, w);
  $DF q0 = df_add_f(m0, $F(1.0));
  $DF s = df_mul(q0, r);
  return s;
}

// df_cos_kernel: cos(r) for |r| <= pi/4 from w = r^2: 1 + w P(w), the Taylor series to r^18
// (truncation < 2^-58); terms from r^12 on (below 2^-33) in float. cos(r) >= 0.70: the last
// additions do not cancel.
// Algorithm: Taylor polynomial of cos in w = r^2, float tail, float-float Horner steps
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 8u^2
// Flops: 218
// @widths 1
$DF df_cos_kernel($DF w) {
  $PRECISE $F t = $SAFE(((-1.5619207e-16 * w.hi + 4.77947733e-14) * w.hi - 1.14707456e-11) * w.hi + 2.0876757e-09);
  $DF q6 = $DF(t, $F(0.0));
  $DF m5 = df_mul_fast(q6, w);
  $DF q5 = df_add_fast(m5, $DF($F(-2.755732e-07), $F(7.57511221e-15)));
  $DF m4 = df_mul_fast(q5, w);
  $DF q4 = df_add_fast(m4, $DF($F(2.48015876e-05), $F(-3.40699609e-13)));
  $DF m3 = df_mul_fast(q4, w);
  $DF q3 = df_add_fast(m3, $DF($F(-0.00138888892), $F(3.36310944e-11)));
  $DF m2 = df_mul_fast(q3, w);
  $DF q2 = df_add_fast(m2, $DF($F(0.0416666679), $F(-1.24176347e-09)));
  $DF m1 = df_mul_fast(q2, w);
  $DF q1 = df_add_f(m1, $F(-0.5));
  $DF m0 = df_mul_fast(q1, w);
  $DF c = df_add_f(m0, $F(1.0));
  return c;
}

// df_sin_quadrant: sin(x + q pi/2) from the reduced r (quadrant q in 0..3): sin r, cos r,
// -sin r, -cos r.
// Algorithm: quadrant selection of df_sin_kernel / df_cos_kernel
// Source: Cody, Waite, 1980; Muller, Elementary Functions, 3rd ed., 2016, section 11.1
// Bound: 18u^2
// Flops: 251 (on the path taken)
// @widths 1
// @min-es 300
// @uses df_mul:1 df_sin_kernel:1 df_cos_kernel:1 df_neg:1
$DF df_sin_quadrant($DF r, int q) {
  $DF w = df_mul(r, r);
  $DF v;
  if ((q & 1) == 0) {
    v = df_sin_kernel(r, w);
  } else {
    v = df_cos_kernel(w);
  }
  $DF n = df_neg(v);
  $DF s = df_select((q & 2) != 0, n, v);
  return s;
}

// df_sin: sin(x), |x| < 2^40 (beyond: NaN, as for +-Inf and NaN). sin(+-0) = +-0. Near a zero
// x ~ k pi the error is absolute (|k| 2^-96 from the 97-bit pi/2), so the relative bits drop
// only when x is within 2^-48 |x| of k pi.
// Algorithm: df_trig_reduce (Cody-Waite, four-word pi/2), df_sin_quadrant
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 20u^2 (relative) plus abs(x) * 2^-96 absolute
// Flops: 522 (on the path taken)
// Range: |x| < 2^40.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_trig_reduce:1 df_sin_quadrant:1
$DF df_sin($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  bool finite = ax < 1.09951163e12;
  $PRECISE $F nan = $G((a.hi - a.hi) / (a.hi - a.hi));
  $DF x = df_select(finite, a, $DF($F(0.0), $F(0.0)));
  int q;
  $DF r = df_trig_reduce(x, q);
  $DF s = df_sin_quadrant(r, q);
  $DF z = df_select(ax == 0.0, a, s);
  $DF y = df_select(finite, z, $DF(nan, $F(0.0)));
  return y;
}

// df_cos: cos(x) = sin(x + pi/2): the quadrant of df_sin plus one. |x| < 2^40 (beyond: NaN).
// Algorithm: df_trig_reduce (Cody-Waite, four-word pi/2), df_sin_quadrant at quadrant q + 1
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: 20u^2 (relative) plus abs(x) * 2^-96 absolute
// Flops: 522 (on the path taken)
// Range: |x| < 2^40.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_trig_reduce:1 df_sin_quadrant:1
$DF df_cos($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  bool finite = ax < 1.09951163e12;
  $PRECISE $F nan = $G((a.hi - a.hi) / (a.hi - a.hi));
  $DF x = df_select(finite, a, $DF($F(0.0), $F(0.0)));
  int q;
  $DF r = df_trig_reduce(x, q);
  int q1 = (q + 1) & 3;
  $DF c = df_sin_quadrant(r, q1);
  $DF y = df_select(finite, c, $DF(nan, $F(0.0)));
  return y;
}

// df_tan: sin(r) / cos(r) in quadrants 0 and 2, -cos(r) / sin(r) in 1 and 3. tan(+-0) = +-0.
// Algorithm: df_trig_reduce, df_sin_kernel and df_cos_kernel, DWDivDW2
// Source: Cody, Waite, 1980; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 40u^2 (relative) plus abs(x) * 2^-96 absolute times (1 + tan(x)^2)
// Flops: 818
// Range: |x| < 2^40.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_trig_reduce:1 df_mul:1 df_sin_kernel:1 df_cos_kernel:1 df_div:1 df_neg:1
$DF df_tan($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  bool finite = ax < 1.09951163e12;
  $PRECISE $F nan = $G((a.hi - a.hi) / (a.hi - a.hi));
  $DF x = df_select(finite, a, $DF($F(0.0), $F(0.0)));
  int q;
  $DF r = df_trig_reduce(x, q);
  $DF w = df_mul(r, r);
  $DF s = df_sin_kernel(r, w);
  $DF c = df_cos_kernel(w);
  bool even = (q & 1) == 0;
  $DF num = df_select(even, s, c);
  $DF den = df_select(even, c, s);
  $DF t = df_div(num, den);
  $DF u = df_neg(t);
  $DF v = df_select(even, t, u);
  $DF z = df_select(ax == 0.0, a, v);
  $DF y = df_select(finite, z, $DF(nan, $F(0.0)));
  return y;
}

// df_atan_halve: t / (1 + sqrt(1 + t^2)) = tan(atan(t) / 2) for t >= 0.
// Algorithm: DWTimesDW1, DWPlusFP, SQRTDWtoDW, DWPlusFP, DWDivDW2
// Source: Muller, Elementary Functions, 3rd ed., 2016 (half-angle reduction); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 22u^2
// Flops: 121
// @widths 1
$DF df_atan_halve($DF t) {
  $DF t2 = df_mul(t, t);
  $DF o = df_add_f(t2, $F(1.0));
  $DF s = df_sqrt(o);
  $DF d = df_add_f(s, $F(1.0));
  $DF h = df_div(t, d);
  return h;
}

// df_atan_kernel: atan(t) for 0 <= t <= 1: two half-angle steps bring t below tan(pi/16) =
// 0.199, then the Taylor series h (1 - h^2/3 + h^4/5 ...) to h^21 (truncation < 2^-51); terms
// from h^11 on (below 2^-26 of the result) in float; the result is 4 atan(h) (exact scaling).
// Algorithm: two df_atan_halve steps, Taylor polynomial of atan, float-float Horner steps
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 55u^2
// Flops: 497
// @widths 1
$DF df_atan_kernel($DF t) {
  $DF h1 = df_atan_halve(t);
  $DF h = df_atan_halve(h1);
  $DF w = df_mul(h, h);
  $PRECISE $F t5 = $SAFE(((((0.0476190485 * w.hi - 0.0526315793) * w.hi + 0.0588235296) * w.hi - 0.0666666701) * w.hi + 0.0769230798) * w.hi - 0.0909090936);
  $DF q5 = $DF(t5, $F(0.0));
  $DF m4 = df_mul_fast(q5, w);
  $DF q4 = df_add_fast(m4, $DF($F(0.111111112), $F(-8.27842295e-10)));
  $DF m3 = df_mul_fast(q4, w);
  $DF q3 = df_add_fast(m3, $DF($F(-0.142857149), $F(6.386212e-09)));
  $DF m2 = df_mul_fast(q3, w);
  $DF q2 = df_add_fast(m2, $DF($F(0.200000003), $F(-2.98023228e-09)));
  $DF m1 = df_mul_fast(q2, w);
  $DF q1 = df_add_fast(m1, $DF($F(-0.333333343), $F(9.93410776e-09)));
  $DF m0 = df_mul_fast(q1, w);
  $DF q0 = df_add_f(m0, $F(1.0));
  $DF p = df_mul(q0, h);
  $PRECISE $F rh = $SAFE(p.hi * 4.0);
  $PRECISE $F rl = $SAFE(p.lo * 4.0);
  return $DF(rh, rl);
}

// df_atan2_unit: atan2(ay, ax) for ay, ax >= 0 (not both zero): atan(ay/ax) when ay <= ax,
// pi/2 - atan(ax/ay) otherwise (no cancellation: the result is >= pi/4 there).
// Algorithm: DWDivDW2 of the smaller by the larger, df_atan_kernel, AccurateDWPlusDW with pi/2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 70u^2
// Flops: 559 (on the path taken)
// @widths 1
// @uses df_lt:1 df_div:1 df_atan_kernel:1 df_sub:1 df_select:1
$DF df_atan2_unit($DF ay, $DF ax) {
  bool steep = df_lt(ax, ay);
  $DF num = df_select(steep, ax, ay);
  $DF den = df_select(steep, ay, ax);
  $DF t = df_div(num, den);
  $DF a = df_atan_kernel(t);
  $DF r = df_sub($DF($F(1.57079637), $F(-4.37113883e-08)), a);
  $DF y = df_select(steep, r, a);
  return y;
}

// df_atan: arctangent, in (-pi/2, pi/2). atan(+-0) = +-0, atan(+-Inf) = +-pi/2, NaN -> NaN.
// Algorithm: df_atan2_unit(abs(x), 1), sign of x
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.1.3
// Bound: 70u^2
// Flops: 565 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @uses df_abs:1 df_atan2_unit:1 df_neg:1 df_select:1
$DF df_atan($DF a) {
  $DF t = df_abs(a);
  $DF r = df_atan2_unit(t, $DF($F(1.0), $F(0.0)));
  $DF n = df_neg(r);
  $DF s = df_select(a.hi < 0.0, n, r);
  $DF y = df_select(a.hi == 0.0, a, s);
  return y;
}

// df_atan2: atan(y, x), the angle of (x, y) in [-pi, pi]: df_atan2_unit on |y|, |x|, then
// pi - a when x < 0 and the sign of y (a zero's sign read as the sign of 1/y). atan(+-0, x >= 0)
// = +-0, atan(+-0, x < 0) = +-pi; atan(+-0, +-0) = y (GLSL leaves it undefined; C gives +-pi for
// x = -0); a NaN gives NaN.
// Algorithm: df_atan2_unit, AccurateDWPlusDW with pi (float-float), sign
// Source: Muller, Elementary Functions, 3rd ed., 2016; C99 Annex F.9.1.4
// Bound: 70u^2
// Flops: 591 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @uses df_abs:1 df_atan2_unit:1 df_sub:1 df_neg:1 df_select:1
$DF df_atan2($DF y, $DF x) {
  bool origin = all(bvec2(x.hi == 0.0, y.hi == 0.0));
  $DF ay = df_abs(y);
  $DF ax = df_abs(x);
  $DF a = df_atan2_unit(ay, ax);
  $DF c = df_sub($DF($F(3.14159274), $F(-8.74227766e-08)), a);
  $DF b = df_select(x.hi < 0.0, c, a);
  $PRECISE $F iy = $SAFE(1.0 / y.hi);
  $PRECISE $F ys = $SAFE($SEL(y.hi == 0.0, iy, y.hi));
  $DF n = df_neg(b);
  $DF s = df_select(ys < 0.0, n, b);
  $DF r = df_select(origin, y, s);
  return r;
}

// df_asin: atan(x, sqrt((1 - x)(1 + x))): 1 - x is exact near |x| = 1, so the cosine keeps its
// relative accuracy there. asin(+-0) = +-0, |x| > 1 gives NaN.
// Algorithm: DWPlusFP, DWTimesDW1, SQRTDWtoDW, df_atan2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 75u^2
// Flops: 674 (on the path taken)
// Range: |x| <= 1.
// @widths 1 2 3 4
// @per-component
// @uses df_neg:1 df_add_f:1 df_mul:1 df_sqrt:1 df_atan2:1 df_select:1
$DF df_asin($DF a) {
  $DF n = df_neg(a);
  $DF om = df_add_f(n, $F(1.0));
  $DF op = df_add_f(a, $F(1.0));
  $DF p = df_mul(om, op);
  $DF c = df_sqrt(p);
  $DF r = df_atan2(a, c);
  $DF y = df_select(a.hi == 0.0, a, r);
  return y;
}

// df_acos: atan(sqrt((1 - x)(1 + x)), x), in [0, pi]. |x| > 1 gives NaN.
// Algorithm: DWPlusFP, DWTimesDW1, SQRTDWtoDW, df_atan2
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 75u^2
// Flops: 674 (on the path taken)
// Range: |x| <= 1.
// @widths 1 2 3 4
// @per-component
// @uses df_neg:1 df_add_f:1 df_mul:1 df_sqrt:1 df_atan2:1
$DF df_acos($DF a) {
  $DF n = df_neg(a);
  $DF om = df_add_f(n, $F(1.0));
  $DF op = df_add_f(a, $F(1.0));
  $DF p = df_mul(om, op);
  $DF c = df_sqrt(p);
  $DF r = df_atan2(c, a);
  return r;
}

// df_expm1: e^x - 1: df_expm1_kernel for |x| < 0.3465 (relative accuracy near 0), else
// df_exp(x) - 1 (e^x - 1 cancels by at most 2.4 there).
// Algorithm: df_expm1_kernel, or df_exp and DWPlusFP
// Source: Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 30u^2
// Flops: 471 (on the path taken)
// @widths 1
// @min-es 300
// @uses df_expm1_kernel:1 df_exp:1 df_add_f:1
$DF df_expm1($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  $DF r;
  if (ax < 0.3465) {
    r = df_expm1_kernel(a);
  } else {
    $DF e = df_exp(a);
    r = df_add_f(e, $F(-1.0));
  }
  return r;
}

// df_sinh: sinh|x| = (E + E / (E + 1)) / 2 with E = expm1(|x|): no cancellation near 0.
// sinh(+-0) = +-0; |x| > 88.72 gives +-Inf (float-float's range ends at FLT_MAX, the true
// overflow is at 89.4); NaN gives NaN.
// Algorithm: df_expm1, DWPlusFP, DWDivDW2, AccurateDWPlusDW, sign
// Source: Muller, Elementary Functions, 3rd ed., 2016 (sinh from expm1); C99 Annex F.9.2.5
// Bound: 50u^2
// Flops: 548 (on the path taken)
// Range: |x| <= 88.72.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_abs:1 df_expm1:1 df_add_f:1 df_div:1 df_add:1 df_neg:1 df_select:1
$DF df_sinh($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  bool over = !(ax <= 88.72);
  $PRECISE $F big = $SAFE(a.hi * 1.0e38);
  $DF x = df_select(over, $DF($F(0.0), $F(0.0)), a);
  $DF t = df_abs(x);
  $DF e = df_expm1(t);
  $DF e1 = df_add_f(e, $F(1.0));
  $DF q = df_div(e, e1);
  $DF s = df_add(e, q);
  $PRECISE $F h = $SAFE(s.hi * 0.5);
  $PRECISE $F l = $SAFE(s.lo * 0.5);
  $PRECISE $F nh = $SAFE(-h);
  $PRECISE $F nl = $SAFE(-l);
  bool negative = a.hi < 0.0;
  $PRECISE $F sh = $SAFE($SEL(negative, nh, h));
  $PRECISE $F sl = $SAFE($SEL(negative, nl, l));
  $DF v = $DF(sh, sl);
  $DF w = df_select(over, $DF(big, $F(0.0)), v);
  $DF y = df_select(ax == 0.0, a, w);
  return y;
}

// df_cosh: (e^|x| + 1/e^|x|) / 2 (no cancellation: both terms positive). |x| > 88.72 gives
// +Inf (true overflow at 89.4); NaN gives NaN.
// Algorithm: df_exp, DWDivDW2, AccurateDWPlusDW
// Source: Muller, Elementary Functions, 3rd ed., 2016; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 20u^2
// Flops: 525
// Range: |x| <= 88.72.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_abs:1 df_exp:1 df_div:1 df_add:1
$DF df_cosh($DF a) {
  $DF t = df_abs(a);
  $DF e = df_exp(t);
  $DF i = df_div($DF($F(1.0), $F(0.0)), e);
  $DF s = df_add(e, i);
  $PRECISE $F h = $SAFE(s.hi * 0.5);
  $PRECISE $F l = $SAFE(s.lo * 0.5);
  return $DF(h, l);
}

// df_tanh: tanh|x| = E / (E + 2) with E = expm1(2|x|): no cancellation near 0; |x| > 22 gives
// +-1 (1 - tanh < 2^-62). tanh(+-0) = +-0; NaN gives NaN.
// Algorithm: df_expm1, DWPlusFP, DWDivDW2, sign
// Source: Muller, Elementary Functions, 3rd ed., 2016 (tanh from expm1); C99 Annex F.9.2.6
// Bound: 50u^2
// Flops: 528 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_expm1:1 df_add_f:1 df_div:1 df_select:1
$DF df_tanh($DF a) {
  $PRECISE $F ax = $SAFE(abs(a.hi));
  $PRECISE $F one = $SAFE($SEL(a.hi < 0.0, -1.0, 1.0));
  bool saturated = ax > 22.0;
  $DF x = df_select(saturated, $DF($F(0.0), $F(0.0)), a);
  $PRECISE $F xh = $SAFE(abs(x.hi));
  $PRECISE $F th = $SAFE(xh * 2.0);
  $PRECISE $F tl = $SAFE(x.lo * one * 2.0);
  $DF e = df_expm1($DF(th, tl));
  $DF d = df_add_f(e, $F(2.0));
  $DF q = df_div(e, d);
  $PRECISE $F h = $SAFE(q.hi * one);
  $PRECISE $F l = $SAFE(q.lo * one);
  $DF v = $DF(h, l);
  $DF w = df_select(saturated, $DF(one, $F(0.0)), v);
  $DF y = df_select(ax == 0.0, a, w);
  return y;
}
