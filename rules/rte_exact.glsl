// rules/rte_exact.glsl -- mode rte-exact's one exact operation: the difference of two binary64
// values rounded once to float (relative-to-eye without loss).
//
// Contract: ex_sub_to_float(a, b) = RN_float(a - b), the float nearest (ties to even) to the EXACT
// real difference of the two doubles, with float's subnormals and overflow to infinity. There is
// no intermediate binary64 rounding: float(a - b) evaluated in binary64 rounds twice and differs
// from it when a - b is not a double and its binary64 rounding lands on a float tie (or crosses
// one). Uses rules/exact.glsl's 64-bit word helpers; the doubles are mode exact's df_* words.
//
// Sources:
//   [IEEE] IEEE Std 754-2019, 4.3.1 (roundTiesToEven), 5.4.1 (subtraction), 7.4 (overflow).
//   [HAU]  J. R. Hauser, Berkeley SoftFloat Release 3e (2018): aligning the smaller significand by a
//          jamming right shift (a sticky bit in bit 0) keeps enough of it to round once; read, not copied.
//   [MUL]  J.-M. Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., Birkhauser 2018,
//          section 7.2 (floating-point addition: alignment, guard and sticky bits).

// ex_sub_to_float_bits: the float bits of RN_float(a - b) for binary64 patterns a, b (uvec2(low, high)), rounded once.
// Algorithm: NaN and infinities first; b's sign flipped; the larger magnitude x, the other y; the 53-bit significands shifted left 10 (bit 62 the top), y's jam-shifted right by the exponent difference; added or subtracted exactly in 64 bits; normalised to bit 63; 24 bits kept (fewer below float's normal range), one round bit and a jammed sticky bit; ties to even; a carry runs into the exponent up to infinity
// Source: IEEE 754-2019, 4.3.1 and 5.4.1; Hauser, SoftFloat 3e, 2018 (jamming alignment); Muller et al., Handbook of Floating-Point Arithmetic, 2018, 7.2
// Bound: 0.5 ulp of float (correctly rounded from the exact difference)
// Flops: 0 (about 80 integer operations)
// Range: every pair of doubles; a NaN operand gives a quiet NaN with its sign, Inf - Inf the default NaN 0xFFC00000
// @min-es 300
uint ex_sub_to_float_bits(uvec2 a, uvec2 b) {
  uvec2 ma = uvec2(a.x, a.y & 0x7FFFFFFFu);
  uvec2 mb = uvec2(b.x, b.y & 0x7FFFFFFFu);
  if (ma.y > 0x7FF00000u || (ma.y == 0x7FF00000u && ma.x != 0u)) return (a.y & 0x80000000u) | 0x7FC00000u;
  if (mb.y > 0x7FF00000u || (mb.y == 0x7FF00000u && mb.x != 0u)) return (b.y & 0x80000000u) | 0x7FC00000u;
  uint sa = a.y >> 31;
  uint sb = (b.y >> 31) ^ 1u;
  bool infA = ma.y == 0x7FF00000u;
  bool infB = mb.y == 0x7FF00000u;
  if (infA && infB) return sa == sb ? (sa << 31) | 0x7F800000u : 0xFFC00000u;
  if (infA) return (sa << 31) | 0x7F800000u;
  if (infB) return (sb << 31) | 0x7F800000u;
  bool swapped = ex_lt64(ma, mb);
  uvec2 mx = swapped ? mb : ma;
  uvec2 my = swapped ? ma : mb;
  uint sx = swapped ? sb : sa;
  bool subtract = sa != sb;
  int ex = int(mx.y >> 20);
  int ey = int(my.y >> 20);
  uvec2 sigX = uvec2(mx.x, mx.y & 0xFFFFFu);
  uvec2 sigY = uvec2(my.x, my.y & 0xFFFFFu);
  if (ex != 0) sigX.y |= 0x100000u; else ex = 1;
  if (ey != 0) sigY.y |= 0x100000u; else ey = 1;
  sigX = ex_shl64(sigX, 10);
  sigY = ex_shr_jam64(ex_shl64(sigY, 10), ex - ey);
  uvec2 m = subtract ? ex_sub64(sigX, sigY) : ex_add64(sigX, sigY);
  if ((m.x | m.y) == 0u) return subtract ? 0u : sx << 31;
  int lead = 63 - ex_clz64(m);
  uvec2 n = ex_shl64(m, 63 - lead);
  int fe = lead + ex - 958;
  if (fe >= 255) return (sx << 31) | 0x7F800000u;
  uvec2 r = ex_shr_jam64(n, 38 + max(0, 1 - fe));
  uint sig = r.x >> 2;
  uint rest = r.x & 3u;
  uint up = (rest == 3u || (rest == 2u && (sig & 1u) != 0u)) ? 1u : 0u;
  uint bits = fe >= 1 ? (uint(fe - 1) << 23) + sig : sig;
  return (sx << 31) | (bits + up);
}

// ex_sub_to_float: float(a - b) of two mode rte-exact doubles: the exact difference rounded once to float.
// Algorithm: ex_sub_to_float_bits on the patterns
// Source: IEEE 754-2019, 4.3.1 and 5.4.1 (one rounding of the exact result)
// Bound: 0.5 ulp of float (correctly rounded from the exact difference)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$F ex_sub_to_float($DF a, $DF b) {
  return uintBitsToFloat(ex_sub_to_float_bits(ex_bits(a), ex_bits(b)));
}
