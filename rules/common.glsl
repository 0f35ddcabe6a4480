// rules/common.glsl -- sign, rounding, selection, interpolation and classification built-ins
// on float-float values (GLSL 4.60 section 8.3 on doubles).
//
// Sources:
//   [JMP]   M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017, Definition 1.4: in a
//           double-word number |lo| <= ulp(hi)/2 and the sign of the value is the sign of hi.
//           So when hi is not an integer no integer lies between hi and hi + lo, and
//           floor(hi + lo) = floor(hi); when hi is an integer, floor(hi + lo) = hi + floor(lo).
//   [Knuth] D. E. Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (TwoSum).
//   [Dekker] T. J. Dekker, Numerische Mathematik 18, 1971, Theorem 4.3 (Fast2Sum).
//   [GLSL]  The OpenGL Shading Language 4.60 (2019), section 8.3 (common functions).

// df_sign: -1, 0 or +1, the sign of hi.
// Algorithm: sign of hi
// Source: JMP 2017, Definition 1.4 (the sign of a double-word number is the sign of hi)
// Bound: exact
// Flops: 1
// @widths 1 2 3 4
$DF df_sign($DF a) {
  $PRECISE $F s = $G(sign(a.hi));
  return $DF(s, $F(0.0));
}

// df_floor: largest integer <= x. hi not an integer: floor(hi); else hi + floor(lo), joined by
// Fast2Sum (|floor(lo)| <= |hi| since |lo| <= ulp(hi)/2 and |hi| >= 1).
// Special values: +-0 and +-Inf are integers whose lo is 0 (or, for an input Inf, NaN): they
// are returned as (hi, 0), as native floor does; the Fast2Sum would give +0 for -0 and
// Inf - Inf = NaN in lo. NaN fails f == hi and gives (NaN, 0).
// Algorithm: floor of hi, or Fast2Sum(hi, floor(lo)) when hi is a nonzero finite integer
// Source: JMP 2017, Definition 1.4; Dekker 1971, Theorem 4.3 (Fast2Sum); IEEE 754-2008 section 5.9
// Bound: exact
// Flops: 6 (plus 2 comparisons)
// @widths 1 2 3 4
// @per-component
$DF df_floor($DF a) {
  $PRECISE $F f = $G(floor(a.hi));
  $PRECISE $F af = $SAFE(abs(f));
  bool integer = all(bvec3(f == a.hi, af > 0.0, af <= 3.40282347e38));
  $PRECISE $F g = $G(floor(a.lo));
  $DF r = df_fast_two_sum(a.hi, g);
  $PRECISE $F h = $SAFE($SEL(integer, r.hi, f));
  $PRECISE $F l = $SAFE($SEL(integer, r.lo, 0.0));
  return $DF(h, l);
}

// df_ceil: smallest integer >= x, as -floor(-x): negation is exact, and the zero results get
// native's signs (ceil(-0.5) = -0, ceil(-1 + 2^-30) = -0), which hi + ceil(lo) would give as +0.
// Algorithm: df_neg, df_floor, df_neg
// Source: JMP 2017, Definition 1.4; IEEE 754-2008 section 5.9 (ceil(x) = -floor(-x))
// Bound: exact
// Flops: 10 (plus 2 comparisons)
// @widths 1 2 3 4
// @per-component
// @uses df_neg:1 df_floor:1
$DF df_ceil($DF a) {
  $DF n = df_neg(a);
  $DF f = df_floor(n);
  $DF r = df_neg(f);
  return r;
}

// df_trunc: the integer nearest x toward zero: ceil for negative x, floor otherwise, both computed
// and one selected. (Selecting the operand instead, floor(x < 0 ? -x : x), is one floor less, but
// Mesa's GLES compiler folds that select into abs(x), which turns trunc(-0) into +0.)
// Algorithm: df_ceil and df_floor, selected by the sign of hi
// Source: JMP 2017, Definition 1.4; GLSL 4.60 (2019) section 8.3 (trunc)
// Bound: exact
// Flops: 16
// @widths 1 2 3 4
// @per-component
// @uses df_ceil:1 df_floor:1 df_select:1
$DF df_trunc($DF a) {
  bool negative = a.hi < 0.0;
  $DF c = df_ceil(a);
  $DF f = df_floor(a);
  $DF r = df_select(negative, c, f);
  return r;
}

// df_fract: x - floor(x). hi an integer: lo - floor(lo), exact by TwoSum. Otherwise
// TwoSum(hi, -floor(hi)) is exact and lo is added with DWPlusFP (exact when hi >= 0 or
// |hi| >= 1, where hi - floor(hi) is a float). Special values: for +-Inf, hi is an "integer"
// and lo - floor(lo) is 0; df_finish then returns (hi - floor(hi), 0) = (NaN, 0), native's
// x - floor(x) (and +0 for every other integer, as before).
// Algorithm: TwoSum of the fractional words, then DWPlusFP (JMP Algorithm 4); df_finish for integers
// Source: Knuth TAOCP vol. 2, 1998, 4.2.2 Theorem B; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 29
// @widths 1 2 3 4
// @per-component
// @uses df_two_sum:1 df_add_f:1 df_finish:1 df_select:1
$DF df_fract($DF a) {
  $PRECISE $F f = $G(floor(a.hi));
  bool integer = f == a.hi;
  $PRECISE $F g = $G(floor(a.lo));
  $PRECISE $F ng = $G(0.0 - g);
  $DF r = df_two_sum(a.lo, ng);
  $PRECISE $F d = $G(a.hi - f);
  $DF q = df_finish(r, d);
  $PRECISE $F nf = $G(0.0 - f);
  $DF t = df_two_sum(a.hi, nf);
  $DF s = df_add_f(t, a.lo);
  $DF z = df_select(integer, q, s);
  return z;
}

// df_next_integer: f + 1 for an integer-valued f, with the sign of zero native round gives:
// f = -1 (x in [-1, 0) rounded up) gives -0. Computed as -((-f) - 1): negation is exact and
// (-f) - 1 is the mirror image of f + 1, whose zero is +0 (IEEE 754-2008 section 6.3).
// Algorithm: df_neg, DWPlusFP (JMP Algorithm 4), df_neg
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2; IEEE 754-2008 section 6.3
// Bound: exact
// Flops: 15
// Range: exact for the integers df_floor returns (f + 1 is a double-word integer).
// @widths 1 2 3 4
// @uses df_neg:W df_add_f:W
$DF df_next_integer($DF f) {
  $DF n = df_neg(f);
  $DF m = df_add_f(n, $F(-1.0));
  $DF r = df_neg(m);
  return r;
}

// df_round: nearest integer, halves away from zero (GLSL lets the implementation choose).
// A result of zero has the sign of x (round(-0.3) = -0), as native fp64 gives.
// Algorithm: floor(x) plus 1 (df_next_integer) when fract(x) > 1/2 (>= 1/2 for x >= 0)
// Source: GLSL 4.60 (2019) section 8.3 (round); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 50
// Range: the decision uses df_fract (2u^2): exact for x >= 0 or |x| >= 1.
// @widths 1 2 3 4
// @per-component
// @uses df_floor:1 df_fract:1 df_next_integer:1 df_select:1
$DF df_round($DF a) {
  $DF f = df_floor(a);
  $DF d = df_fract(a);
  bool above = any(bvec2(d.hi > 0.5, all(bvec2(d.hi == 0.5, d.lo > 0.0))));
  bool tie = all(bvec2(d.hi == 0.5, d.lo == 0.0));
  bool up = any(bvec2(above, all(bvec2(tie, a.hi >= 0.0))));
  $DF u = df_next_integer(f);
  $DF r = df_select(up, u, f);
  return r;
}

// df_round_even: nearest integer, halves to the even neighbour (roundEven). A result of zero
// has the sign of x (roundEven(-0.5) = -0), as native fp64 gives.
// Algorithm: floor(x) plus 1 (df_next_integer) when fract(x) > 1/2, or = 1/2 and floor(x) is odd
// Source: GLSL 4.60 (2019) section 8.3 (roundEven); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 56
// Range: the parity of floor(x) = fh + fl is the parity of fh + fl taken word by word
// (one of them is even: fl != 0 only when ulp(fh) >= 2).
// @widths 1 2 3 4
// @per-component
// @uses df_floor:1 df_fract:1 df_next_integer:1 df_select:1
$DF df_round_even($DF a) {
  $DF f = df_floor(a);
  $DF d = df_fract(a);
  $PRECISE float h2 = $G(f.hi * 0.5);
  $PRECISE float fh2 = $G(floor(h2));
  $PRECISE float ph = $G(h2 - fh2);
  $PRECISE float l2 = $G(f.lo * 0.5);
  $PRECISE float fl2 = $G(floor(l2));
  $PRECISE float pl = $G(l2 - fl2);
  $PRECISE float parity = $G(ph + pl);
  bool above = any(bvec2(d.hi > 0.5, all(bvec2(d.hi == 0.5, d.lo > 0.0))));
  bool tie = all(bvec2(d.hi == 0.5, d.lo == 0.0));
  bool up = any(bvec2(above, all(bvec2(tie, parity == 0.5))));
  $DF u = df_next_integer(f);
  $DF r = df_select(up, u, f);
  return r;
}

// df_mod: x - y * floor(x / y) (GLSL's definition). Where x / y is within df_div's error of an
// integer, floor may pick the neighbouring integer, and the result is off by y (the function is
// discontinuous there, in native fp64 as well). Otherwise the product has 7u^2 abs(y q) <=
// 7u^2 (abs(x) + abs(y)) and the subtraction 3u^2 abs(r).
// Algorithm: DWDivDW2, df_floor, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.3 (mod); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 10u^2 * (abs(x) + abs(y)) (absolute) when floor(x / y) is exact
// Flops: 97
// @widths 1 2 3 4
$DF df_mod($DF a, $DF b) {
  $DF q = df_div(a, b);
  $DF f = df_floor(q);
  $DF p = df_mul(b, f);
  $DF r = df_sub(a, p);
  return r;
}

// df_modf_fraction: x - i for i = trunc(x), with x's sign (GLSL: "the same sign as x"): for
// negative x it is -(i - x), the mirror image of x - i, so a zero fraction is -0 (modf(-3) = -0);
// for +-0 it is x itself; +-Inf gives NaN (Inf - Inf), as native fp64 does.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6) of x and -i, or of i and -x then df_neg
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1; GLSL 4.60 (2019) section 8.3 (modf); IEEE 754-2008 section 6.3
// Bound: 3u^2
// Flops: 25
// @widths 1 2 3 4
// @per-component
// The branches are selects around one df_sub: its operands are swapped and its result negated
// for negative x.
// @uses df_sub:1 df_neg:1 df_select:1
$DF df_modf_fraction($DF a, $DF i) {
  bool negative = a.hi < 0.0;
  bool zero = a.hi == 0.0;
  $DF x = df_select(negative, i, a);
  $DF y = df_select(negative, a, i);
  $DF d = df_sub(x, y);
  $DF n = df_neg(d);
  $DF m = df_select(negative, n, d);
  $PRECISE $F zh = $SAFE(a.hi);
  $DF z = $DF(zh, $F(0.0));
  $DF r = df_select(zero, z, m);
  return r;
}

// df_modf: integer part (toward zero) into i, fraction x - i returned, both with x's sign
// (modf(-3) = (-0, -3), modf(-0) = (-0, -0); native fp64 on Mesa gives +0 for both parts of -0).
// Algorithm: df_trunc, then df_modf_fraction (AccurateDWPlusDW)
// Source: GLSL 4.60 (2019) section 8.3 (modf); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2
// Flops: 41
// @widths 1 2 3 4
// @uses df_trunc:W df_modf_fraction:W
$DF df_modf($DF a, out $DF i) {
  i = df_trunc(a);
  $DF r = df_modf_fraction(a, i);
  return r;
}

// df_clamp: min(max(x, lo), hi).
// Algorithm: df_max then df_min (lexicographic compare and select)
// Source: GLSL 4.60 (2019) section 8.3 (clamp); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (6 comparisons per component)
// @widths 1 2 3 4
$DF df_clamp($DF x, $DF lo, $DF hi) {
  $DF m = df_max(x, lo);
  $DF r = df_min(m, hi);
  return r;
}

// df_mix: x + a * (y - x), as GLSL defines mix (r is the result).
// Algorithm: AccurateDWPlusDW, DWTimesDW1, AccurateDWPlusDW
// Source: GLSL 4.60 (2019) section 8.3 (mix); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r) + 10u^2 * abs(a * (y - x)) (absolute, first order)
// Flops: 73
// @widths 1 2 3 4
$DF df_mix($DF x, $DF y, $DF a) {
  $DF d = df_sub(y, x);
  $DF p = df_mul(a, d);
  $DF r = df_add(x, p);
  return r;
}

// df_mix_bool: a ? y : x per component (mix with a boolean selector).
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBDType)
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
// @per-component
// @uses df_select:1
$DF df_mix_bool($DF x, $DF y, $B a) {
  $DF r = df_select(a, y, x);
  return r;
}

// df_step: 0.0 if x < edge, else 1.0.
// Algorithm: lexicographic compare (df_lt)
// Source: GLSL 4.60 (2019) section 8.3 (step); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons)
// @widths 1 2 3 4
// @per-component
// @uses df_lt:1
$DF df_step($DF edge, $DF x) {
  bool below = df_lt(x, edge);
  $PRECISE $F h = $SAFE($SEL(below, 0.0, 1.0));
  return $DF(h, 0.0);
}

// df_smoothstep: t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2t). t has relative error
// 3 + 3 + 15 = 21u^2 (each subtraction is one AccurateDWPlusDW of exact inputs); the cubic's
// slope is at most 1.5 and its evaluation adds 7 + 9 + 7 u^2 on [0, 1].
// Algorithm: AccurateDWPlusDW, DWDivDW2, clamp, DWTimesDW1
// Source: GLSL 4.60 (2019) section 8.3 (smoothstep); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 55u^2 (absolute; the result is in [0, 1])
// Flops: 190
// @widths 1 2 3 4
$DF df_smoothstep($DF e0, $DF e1, $DF x) {
  $DF n = df_sub(x, e0);
  $DF d = df_sub(e1, e0);
  $DF q = df_div(n, d);
  $DF t = df_clamp(q, $DF($F(0.0), $F(0.0)), $DF($F(1.0), $F(0.0)));
  $DF s = df_mul(t, t);
  $DF t2 = df_add(t, t);
  $DF c = df_sub($DF($F(3.0), $F(0.0)), t2);
  $DF r = df_mul(s, c);
  return r;
}

// df_isnan: true where the value is NaN (NaN propagates to hi).
// Algorithm: isnan of hi
// Source: IEEE 754-2008 section 6.2; JMP 2017, Definition 1.4 (hi = RN(hi + lo))
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
// @min-es 300
$B df_isnan($DF a) {
  return isnan(a.hi);
}

// df_isinf: true where the value is infinite.
// Algorithm: isinf of hi
// Source: IEEE 754-2008 section 6.1; JMP 2017, Definition 1.4 (hi = RN(hi + lo))
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
// @min-es 300
$B df_isinf($DF a) {
  return isinf(a.hi);
}

// df_fma: a * b + c. Not fused: the product is rounded (DWTimesDW1), then added.
// Algorithm: DWTimesDW1 (JMP Algorithm 10), then AccurateDWPlusDW (JMP Algorithm 6)
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 3u^2 * abs(r) + 7u^2 * abs(a * b) (absolute, first order)
// Flops: 50
// @widths 1 2 3 4
$DF df_fma($DF a, $DF b, $DF c) {
  $DF p = df_mul(a, b);
  $DF r = df_add(p, c);
  return r;
}

// df_exp2i: the bit patterns of three floats whose product is 2^e, -300 <= e <= 300 (each factor
// is 2^k with |k| <= 100, a normal float; intBitsToFloat needs ES 3.00). 300 is beyond every
// float-float result: 2^-149 * 2^300 overflows and 2^128 * 2^-300 underflows to 0, so clamping
// e there changes nothing.
// Algorithm: IEEE 754 binary32 exponent field
// Source: IEEE 754-2008 section 3.4 (binary interchange format encodings)
// Bound: exact
// Flops: 0 (integer operations)
// @widths 1
// @min-es 300
ivec3 df_exp2i(int e) {
  int c = clamp(e, -300, 300);
  int e1 = c / 3;
  int e2 = (c - e1) / 2;
  int e3 = c - e1 - e2;
  int b1 = (e1 + 127) << 23;
  int b2 = (e2 + 127) << 23;
  int b3 = (e3 + 127) << 23;
  return ivec3(b1, b2, b3);
}

// df_ldexp: x * 2^e, both words scaled by powers of two in three exact steps, then df_finish:
// a result beyond float range is (+-Inf, 0) (lo alone would overflow to an infinity of the
// other sign, and Inf + -Inf is NaN), one below it (+-0, 0) with x's sign.
// Algorithm: scaling of hi and lo by 2^e in three exact steps, then df_finish
// Source: IEEE 754-2008 section 5.3.3 (scaleB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 7 (plus 2 comparisons)
// Range: exact while the result is a normal float-float; into float's subnormal range each word
// is rounded (at most twice), within one subnormal ulp (2^-149) absolute.
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_exp2i:1 df_finish:1
$DF df_ldexp($DF a, $I e) {
  ivec3 b = df_exp2i(e);
  $PRECISE float s1 = $G(intBitsToFloat(b.x));
  $PRECISE float s2 = $G(intBitsToFloat(b.y));
  $PRECISE float s3 = $G(intBitsToFloat(b.z));
  $PRECISE $F h1 = $G(a.hi * s1);
  $PRECISE $F h2 = $G(h1 * s2);
  $PRECISE $F h = $G(h2 * s3);
  $PRECISE $F l1 = $G(a.lo * s1);
  $PRECISE $F l2 = $G(l1 * s2);
  $PRECISE $F l = $G(l2 * s3);
  $DF z = $DF(h, l);
  $DF r = df_finish(z, h);
  return r;
}

// df_frexp: x = m * 2^e with 0.5 <= |m| < 1. The exponent is hi's; when hi = +-2^k and lo has
// the opposite sign, |x| < 2^k, so e is one less. A subnormal hi is first scaled by 2^64 (exact)
// to read its exponent. +-0 gives (+-0, e = 0); +-Inf and NaN give m = x and e = 1025, the
// values native fp64 gives on Mesa (GLSL leaves them undefined).
// Algorithm: exponent field of hi (of hi * 2^64 when subnormal), corrected by the sign of lo, then df_ldexp
// Source: IEEE 754-2008 section 5.3.3 (logB); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 9 (plus 4 comparisons)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_ldexp:1 df_select:1
$DF df_frexp($DF a, out $I e) {
  $PRECISE $F ah = $SAFE(abs(a.hi));
  bool regular = all(bvec2(ah > 0.0, ah <= 3.40282347e38));
  bool subnormal = ah < 1.17549435e-38;
  $PRECISE $F scale = $SAFE($SEL(subnormal, 1.8446744073709552e19, 1.0));
  $PRECISE $F h = $SAFE(a.hi * scale);
  int bits = floatBitsToInt(h);
  int k = ((bits >> 23) & 255) - (subnormal ? 190 : 126);
  int mantissa = bits & 8388607;
  bool opposite = any(bvec2(all(bvec2(a.hi > 0.0, a.lo < 0.0)), all(bvec2(a.hi < 0.0, a.lo > 0.0))));
  bool below = all(bvec2(mantissa == 0, opposite));
  int exponent = below ? k - 1 : k;
  int special = ah == 0.0 ? 0 : 1025;
  e = regular ? exponent : special;
  int undo = regular ? 0 - exponent : 0;
  $DF m = df_ldexp(a, undo);
  $PRECISE $F sh = $SAFE(a.hi);
  $DF x = $DF(sh, 0.0);
  $DF r = df_select(regular, m, x);
  return r;
}
