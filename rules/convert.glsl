// rules/convert.glsl -- conversions between float-float and float, int, uint, bool.
// ES 1.00 has no uint, trunc, round or bit operations: every rule here except the uint ones
// uses only sign, abs, floor, step, int()/float() constructors and + - * /.
//
// Sources:
//   [Knuth] D. E. Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (TwoSum, exact sums).
//   [JMP]   M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017, Definition 1.4
//           (double-word number: hi = RN(hi + lo), so |lo| <= ulp(hi)/2).
//   [Sterbenz] P. H. Sterbenz, Floating-Point Computation, Prentice-Hall, 1974 (exact
//           subtraction of nearby floats), as used for the fractional part hi - trunc(hi).
//   [GLSL]  The OpenGL ES Shading Language 3.00.6, 2016, sections 4.1.3 (32-bit two's complement
//           integers, wrap-around on overflow) and 5.4.1 (int(float) drops the fraction,
//           uint(int) keeps the bit pattern).

// df_from_float: the exact double-word (f, 0).
// Algorithm: hi = f, lo = 0
// Source: JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
$DF df_from_float($F f) {
  return $DF(f, $F(0.0));
}

// df_to_float: the float nearest to hi + lo (one correctly rounded addition; for a
// double-word number this is hi itself, but the addition also rounds unnormalized pairs).
// Values beyond float range are already +-Inf in hi (the rules saturate), so they stay +-Inf;
// df_finish keeps hi where the sum is zero (-0 + 0 would be +0), infinite or NaN.
// Algorithm: RN(hi + lo), then df_finish for zeros and non-finite values
// Source: JMP 2017, Definition 1.4 (hi = RN(hi + lo)); IEEE 754-2008 section 5.4.2 (formatOf conversions)
// Bound: 0.5 ulp (correctly rounded to float)
// Flops: 2
// @widths 1 2 3 4
$F df_to_float($DF a) {
  $PRECISE $F f = $G(a.hi + a.lo);
  $DF r = df_finish($DF(f, $F(0.0)), a.hi);
  return r.hi;
}

// df_from_int: exact for every 32-bit int i.
// Algorithm: 16-bit split of the integer, then TwoSum
// Steps: i = q*65536 + r with q = i/65536, r = i - q*65536 (integer ops, exact);
//   float(q)*65536 and float(r) are exact floats (|q| <= 32768, |r| < 65536), and TwoSum
//   of them is the exact double-word of i (i has at most 32 significant bits <= 48).
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (TwoSum)
// Bound: exact
// Flops: 7 (plus 2 integer ops and 2 conversions)
// Works whatever the rounding of integer division, as long as |q| <= 32768.
// @widths 1 2 3 4
$DF df_from_int($I i) {
  $I q = i / 65536;
  $I r = i - q * 65536;
  $PRECISE $F qf = $G($F(q) * 65536.0);
  $PRECISE $F rf = $G($F(r));
  $DF z = df_two_sum(qf, rf);
  return z;
}

// df_to_int: truncation toward zero, exact for every double-word whose truncation fits in int.
// Algorithm: truncate hi, correct by floor/ceil of lo when hi is an integer
// Steps: t = trunc(hi) = sign(hi)*floor(|hi|) (exact). If hi is not an integer,
//   |lo| <= ulp(hi)/2 < distance from hi to the nearest integer, so trunc(hi+lo) = t.
//   If hi is an integer, trunc(hi+lo) = hi + floor(lo) for hi > 0 and hi + ceil(lo) for
//   hi < 0, i.e. t + adj with adj = s*floor(s*lo), s = sign(hi) (lo = 0 when hi = 0).
//   t can be 2^31 when the answer is 2^31 - k (hi rounds up), so t is not converted
//   directly: h = int(t/2) (exact, |h| <= 2^30), e = t - 2h in {-1,0,1}, and the result is
//   h + (int(e + adj) + h), which never overflows when the answer fits.
// Source: JMP 2017, Definition 1.4 (abs(lo) <= ulp(hi)/2); Sterbenz 1974 (exact hi - t)
// Bound: exact
// Flops: 15 (float, including sign/abs/floor/step; plus 3 conversions and 2 integer adds)
// @widths 1 2 3 4
$I df_to_int($DF a) {
  $PRECISE $F s = $G(sign(a.hi));
  $PRECISE $F ah = $G(abs(a.hi));
  $PRECISE $F fh = $G(floor(ah));
  $PRECISE $F t = $G(s * fh);
  $PRECISE $F d = $G(a.hi - t);
  $PRECISE $F ad = $G(abs(d));
  $PRECISE $F m = $G(step(ad, $F(0.0)));
  $PRECISE $F sl = $G(s * a.lo);
  $PRECISE $F fl = $G(floor(sl));
  $PRECISE $F adj0 = $G(s * fl);
  $PRECISE $F adj = $G(adj0 * m);
  $PRECISE $F th = $G(t * 0.5);
  $I h = $I(th);
  $PRECISE $F h2 = $G($F(h) * 2.0);
  $PRECISE $F e = $G(t - h2);
  $PRECISE $F ea = $G(e + adj);
  $I k = $I(ea);
  $I hk = h + k;
  $I z = hk + h;
  return z;
}

// df_from_uint: exact for every 32-bit uint.
// Algorithm: 16-bit split of the integer, then TwoSum
// Steps: u = q*65536 + r (unsigned integer ops, exact); float(q)*65536 and float(r) are
//   exact; TwoSum gives the exact double-word (at most 32 significant bits).
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B (TwoSum)
// Bound: exact
// Flops: 7 (plus 2 integer ops and 2 conversions)
// @widths 1 2 3 4
// @min-es 300
$DF df_from_uint($U u) {
  $U q = u / 65536u;
  $U r = u - q * 65536u;
  $PRECISE $F qf = $G($F(q) * 65536.0);
  $PRECISE $F rf = $G($F(r));
  $DF z = df_two_sum(qf, rf);
  return z;
}

// df_to_uint: truncation toward zero, exact for every value in [0, 2^32) (negative values are
// undefined, like GLSL uint(double)). Same derivation as df_to_int; t may be 2^32 when the
// answer is 2^32 - k, so h = uint(t/2) <= 2^31, and h + (uint(int(e + adj)) + h) is computed
// modulo 2^32 (ES 3.00 4.1.3: wrap-around; uint(int) keeps the bit pattern), which is exact.
// Algorithm: truncate hi, correct by floor of lo when hi is an integer (as df_to_int)
// Source: JMP 2017, Definition 1.4 (abs(lo) <= ulp(hi)/2); Sterbenz 1974 (exact hi - t)
// Bound: exact
// Flops: 15 (float, including sign/abs/floor/step; plus 4 conversions and 2 integer adds)
// @widths 1 2 3 4
// @min-es 300
$U df_to_uint($DF a) {
  $PRECISE $F s = $G(sign(a.hi));
  $PRECISE $F ah = $G(abs(a.hi));
  $PRECISE $F fh = $G(floor(ah));
  $PRECISE $F t = $G(s * fh);
  $PRECISE $F d = $G(a.hi - t);
  $PRECISE $F ad = $G(abs(d));
  $PRECISE $F m = $G(step(ad, $F(0.0)));
  $PRECISE $F sl = $G(s * a.lo);
  $PRECISE $F fl = $G(floor(sl));
  $PRECISE $F adj0 = $G(s * fl);
  $PRECISE $F adj = $G(adj0 * m);
  $PRECISE $F th = $G(t * 0.5);
  $U h = $U(th);
  $PRECISE $F h2 = $G($F(h) * 2.0);
  $PRECISE $F e = $G(t - h2);
  $PRECISE $F ea = $G(e + adj);
  $I k = $I(ea);
  $U ku = $U(k);
  $U hk = h + ku;
  $U z = hk + h;
  return z;
}

// df_from_bool: 1.0 for true, 0.0 for false, exactly.
// Algorithm: float(b), lo = 0
// Source: The OpenGL ES Shading Language 3.00.6 (2016), section 5.4.1 (bool to float conversion)
// Bound: exact
// Flops: 0
// @widths 1 2 3 4
$DF df_from_bool($B b) {
  $PRECISE $F f = $G($F(b));
  return $DF(f, $F(0.0));
}

// df_to_bool: value != 0 (NaN is true). |hi| + |lo| is zero only when both words are zero,
// so this is right even for an unnormalized pair.
// Algorithm: bool(abs(hi) + abs(lo))
// Source: The OpenGL ES Shading Language 3.00.6 (2016), section 5.4.1 (float to bool: nonzero is true)
// Bound: exact
// Flops: 3
// @widths 1 2 3 4
$B df_to_bool($DF a) {
  $PRECISE $F ah = $G(abs(a.hi));
  $PRECISE $F al = $G(abs(a.lo));
  $PRECISE $F s = $G(ah + al);
  return $B(s);
}

// df_pack_double2x32: the double whose IEEE binary64 bits are (v.x = low word, v.y = high word),
// as float-float. Significand 1.m (52 bits) = t (21 bits) + mid (24 bits) + low (8 bits), each an
// exact float; TwoSum joins the first two exactly, DWPlusFP adds the last (the only rounding:
// 53 bits to a double-word), then df_ldexp scales by the exponent (exact unless the value is
// outside float range, which gives Inf or 0). Zero and subnormal doubles give +-0.
// Algorithm: TwoSum, DWPlusFP (JMP Algorithm 4), exponent scaling
// Source: IEEE 754-2008 section 3.4; Knuth TAOCP vol. 2, 1998, 4.2.2 Theorem B; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2
// Bound: 2u^2
// Flops: 28
// @widths 1
// @min-es 300
// @uses df_two_sum:1 df_add_f:1 df_ldexp:1 df_neg:1 df_select:1
df_double df_pack_double2x32(uvec2 v) {
  uint exponent = (v.y >> 20u) & 2047u;
  uint top = (v.y & 1048575u) | 1048576u;
  uint mid = v.x >> 8u;
  uint low = v.x & 255u;
  uint sign_bit = v.y & 2147483648u;
  bool zero = exponent == 0u;
  bool special = exponent == 2047u;
  bool nan = any(bvec2((v.y & 1048575u) != 0u, v.x != 0u));
  uint edge_bits = zero ? sign_bit : (nan ? 2143289344u : (sign_bit | 2139095040u));
  $PRECISE float eh = $G(uintBitsToFloat(edge_bits));
  $PRECISE float t = $G(float(top));
  $PRECISE float tn = $G(t * 9.5367431640625e-07);
  $PRECISE float m = $G(float(mid));
  $PRECISE float mn = $G(m * 5.684341886080802e-14);
  $PRECISE float l = $G(float(low));
  $PRECISE float ln = $G(l * 2.220446049250313e-16);
  df_double s = df_two_sum(tn, mn);
  df_double r = df_add_f(s, ln);
  int scale = int(exponent) - 1023;
  df_double x = df_ldexp(r, scale);
  df_double n = df_neg(x);
  df_double y = df_select(sign_bit != 0u, n, x);
  df_double edge = df_double(eh, 0.0);
  df_double z = df_select(any(bvec2(zero, special)), edge, y);
  return z;
}

// df_unpack_double2x32: the IEEE binary64 bits (low word, high word) of the double nearest to a
// (ties to even). With x = abs(a) * 2^-k in [1, 2): M = round(x * 2^52) = hi * 2^52 + roundEven(lo *
// 2^52) exactly (hi * 2^52 is an integer), assembled in two 32-bit words with carry.
// Algorithm: exponent of hi, exact scaling, integer assembly of the rounded significand
// Source: IEEE 754-2008 section 3.4; JMP 2017, Definition 1.4 (abs(lo) <= ulp(hi)/2)
// Bound: 0.5 ulp of binary64 (correctly rounded; exact when the value has at most 53 bits)
// Flops: 8
// @widths 1
// @min-es 300
// @uses df_abs:1 df_ldexp:1
uvec2 df_unpack_double2x32(df_double a) {
  uint sign_bit = floatBitsToUint(a.hi) & 2147483648u;
  bool zero = a.hi == 0.0;
  bool nan = isnan(a.hi);
  bool special = any(bvec3(zero, nan, isinf(a.hi)));
  uint inf_bits = sign_bit | 2146435072u;
  uint edge_high = zero ? sign_bit : (nan ? 2146959360u : inf_bits);
  df_double m = df_abs(a);
  int bits = floatBitsToInt(m.hi);
  int e = ((bits >> 23) & 255) - 127;
  bool below = all(bvec2((bits & 8388607) == 0, m.lo < 0.0));
  int k = below ? e - 1 : e;
  int nk = 0 - k;
  df_double x = df_ldexp(m, nk);
  $PRECISE float hs = $G(x.hi * 8388608.0);
  $PRECISE float ls = $G(x.lo * 4503599627370496.0);
  $PRECISE float lr = $G(roundEven(ls));
  uint big = uint(hs);
  uint high = big >> 3u;
  uint low = big << 29u;
  int li = int(lr);
  uint add = uint(li >= 0 ? li : 0 - li);
  uint sum = low + add;
  uint difference = low - add;
  uint carry = sum < low ? 1u : 0u;
  uint borrow = low < add ? 1u : 0u;
  uint low_word = li >= 0 ? sum : difference;
  uint high_sig = li >= 0 ? high + carry : high - borrow;
  bool overflow = high_sig >= 2097152u;
  uint significand = overflow ? 1048576u : high_sig;
  int biased = (overflow ? k + 1 : k) + 1023;
  uint high_word = sign_bit | (uint(biased) << 20u) | (significand & 1048575u);
  uint lw = special ? 0u : low_word;
  uint hw = special ? edge_high : high_word;
  return uvec2(lw, hw);
}
