// rules/exact.glsl -- IEEE 754 binary64 in 32-bit integer arithmetic (mode `exact`).
//
// A double is a uvec2 holding its bit pattern: .x = low word (significand bits 0-31), .y = high
// word (sign bit 31, exponent bits 20-30, significand bits 32-51), the order of GLSL's
// unpackDouble2x32. Every operation is correctly rounded to nearest-even, with binary64's
// exponent range, subnormals, signed zeros, infinities and NaN. A NaN result is quiet; an
// invalid operation gives the x86 default NaN 0xFFF8000000000000.
//
// Sources:
//   [IEEE] IEEE Std 754-2019, sections 4.3.1 (roundTiesToEven), 5.4, 6 (infinity, NaN, signed zero).
//   [HAU]  J. R. Hauser, Berkeley SoftFloat Release 3e (2018), the round-and-pack scheme with a
//          jamming right shift (a sticky bit ORed into the lowest bit); read, not copied.
//   [MESA] Mesa src/compiler/glsl/float64.glsl (2018, soft-fp64 on uvec2): the uvec2 word order; read, not copied.
//   [ERN]  M. D. Ercegovac, T. Lang, Digital Arithmetic, Morgan Kaufmann 2004, ch. 5-6: restoring
//          division and digit-by-digit square root with the remainder as sticky bit.

// ex_add64: 64-bit sum of two (lo, hi) words, modulo 2^64.
// Algorithm: word sums with the carry of the low word (a.x + b.x < a.x)
// Source: two's-complement multiword addition (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm A)
// Bound: exact
// Flops: 0 (4 integer operations)
// @min-es 300
uvec2 ex_add64(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;
  return uvec2(lo, a.y + b.y + (lo < a.x ? 1u : 0u));
}

// ex_sub64: 64-bit difference, modulo 2^64.
// Algorithm: word differences with the borrow of the low word (a.x < b.x)
// Source: two's-complement multiword subtraction (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm S)
// Bound: exact
// Flops: 0 (4 integer operations)
// @min-es 300
uvec2 ex_sub64(uvec2 a, uvec2 b) {
  return uvec2(a.x - b.x, a.y - b.y - (a.x < b.x ? 1u : 0u));
}

// ex_lt64: unsigned a < b on 64-bit words.
// Algorithm: compare high words, then low words
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword comparison)
// Bound: exact
// Flops: 0 (3 integer comparisons)
// @min-es 300
bool ex_lt64(uvec2 a, uvec2 b) {
  return a.y < b.y || (a.y == b.y && a.x < b.x);
}

// ex_shl64: a << n for 0 <= n < 64 (GLSL shifts by 32 or more are undefined: split by case).
// Algorithm: word shift by case n == 0, n < 32, n >= 32
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword shifts)
// Bound: exact
// Flops: 0 (up to 6 integer operations)
// @min-es 300
uvec2 ex_shl64(uvec2 a, int n) {
  if (n == 0) return a;
  if (n >= 32) return uvec2(0u, a.x << uint(n - 32));
  return uvec2(a.x << uint(n), (a.y << uint(n)) | (a.x >> uint(32 - n)));
}

// ex_shr_jam64: a >> n for n >= 0, the shifted-out bits ORed into bit 0 (the sticky bit).
// Algorithm: word shift by case; any nonzero bit shifted out sets bit 0 ("jamming")
// Source: Hauser, Berkeley SoftFloat 3e, 2018 (shiftRightJam64 semantics)
// Bound: exact (as a sticky-rounded value)
// Flops: 0 (up to 10 integer operations)
// @min-es 300
uvec2 ex_shr_jam64(uvec2 a, int n) {
  if (n == 0) return a;
  if (n >= 64) return uvec2((a.x | a.y) != 0u ? 1u : 0u, 0u);
  uvec2 r;
  uint lost;
  if (n >= 32) {
    r = uvec2(n == 32 ? a.y : a.y >> uint(n - 32), 0u);
    lost = a.x | (n == 32 ? 0u : a.y << uint(64 - n));
  } else {
    r = uvec2((a.x >> uint(n)) | (a.y << uint(32 - n)), a.y >> uint(n));
    lost = a.x << uint(32 - n);
  }
  r.x |= lost != 0u ? 1u : 0u;
  return r;
}

// ex_clz32: count of leading zero bits of a 32-bit word (32 for 0); ES 3.00 has no findMSB.
// Algorithm: binary search over 16, 8, 4, 2, 1 bit halves
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3 (nlz, binary search)
// Bound: exact
// Flops: 0 (about 16 integer operations)
// @min-es 300
int ex_clz32(uint x) {
  if (x == 0u) return 32;
  int n = 0;
  if ((x & 0xFFFF0000u) == 0u) { n += 16; x <<= 16; }
  if ((x & 0xFF000000u) == 0u) { n += 8; x <<= 8; }
  if ((x & 0xF0000000u) == 0u) { n += 4; x <<= 4; }
  if ((x & 0xC0000000u) == 0u) { n += 2; x <<= 2; }
  if ((x & 0x80000000u) == 0u) { n += 1; }
  return n;
}

// ex_clz64: leading zero bits of a 64-bit (lo, hi) value (64 for 0).
// Algorithm: ex_clz32 of the high word, else 32 + ex_clz32 of the low word
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3
// Bound: exact
// Flops: 0
// @min-es 300
int ex_clz64(uvec2 a) {
  return a.y != 0u ? ex_clz32(a.y) : 32 + ex_clz32(a.x);
}

// ex_mul32: full 64-bit product of two 32-bit words from four 16x16-bit products (ES 3.00 has no umulExtended).
// Algorithm: schoolbook multiplication in 16-bit limbs, carries of the middle sum propagated
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm M
// Bound: exact
// Flops: 0 (4 integer multiplications, about 14 other integer operations)
// @min-es 300
uvec2 ex_mul32(uint a, uint b) {
  uint al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
  uint ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
  uint mid = lh + hl;
  uint midCarry = mid < lh ? 0x10000u : 0u;
  uint lo = ll + (mid << 16);
  uint hi = hh + (mid >> 16) + midCarry + (lo < ll ? 1u : 0u);
  return uvec2(lo, hi);
}

// ex_round_pack: the binary64 nearest (ties to even) to sig * 2^(e - 1084), sign s. sig < 2^63; if e > 0 its top bit must be bit 62.
// Algorithm: e < 0: jamming shift to e = 0 (subnormal); keep 53 bits, 10 round bits; add half, clear the last bit on an exact tie; the significand's carry runs into the exponent field (up to infinity)
// Source: IEEE 754-2019, 4.3.1; Hauser, Berkeley SoftFloat 3e, 2018 (roundPackToF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 30 integer operations)
// @min-es 300
uvec2 ex_round_pack(bool s, int e, uvec2 sig) {
  uint signWord = s ? 0x80000000u : 0u;
  if (e > 0x7FD) return uvec2(0u, signWord | 0x7FF00000u);
  if (e < 0) {
    sig = ex_shr_jam64(sig, -e);
    e = 0;
  }
  uint roundBits = sig.x & 0x3FFu;
  sig = ex_add64(sig, uvec2(0x200u, 0u));
  sig = uvec2((sig.x >> 10) | (sig.y << 22), sig.y >> 10);
  if (roundBits == 0x200u) sig.x &= 0xFFFFFFFEu;
  return ex_add64(uvec2(0u, signWord | (uint(e) << 20)), sig);
}

// ex_norm_round_pack: ex_round_pack for any nonzero 64-bit sig: first moved so its top bit is bit 62.
// Algorithm: count leading zeros; shift left (exact) or jam-shift right by one
// Source: Hauser, Berkeley SoftFloat 3e, 2018 (normRoundPackToF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
// @min-es 300
uvec2 ex_norm_round_pack(bool s, int e, uvec2 sig) {
  int z = ex_clz64(sig);
  if (z == 0) return ex_round_pack(s, e + 1, ex_shr_jam64(sig, 1));
  return ex_round_pack(s, e - (z - 1), ex_shl64(sig, z - 1));
}

// ex_is_nan: true when the bit pattern is a NaN.
// Algorithm: exponent field all ones and a nonzero significand
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
bool ex_is_nan(uvec2 a) {
  return (a.y & 0x7FFFFFFFu) > 0x7FF00000u || ((a.y & 0x7FFFFFFFu) == 0x7FF00000u && a.x != 0u);
}

// ex_pick_nan: the NaN result of an operation with a NaN operand: a if it is a NaN, else b, made quiet.
// Algorithm: set the quiet bit (significand bit 51) of a if it is a NaN, else of b. Native fp64 on lavapipe (LLVM, x86 SSE) returns the first source operand's NaN, and LLVM passes a commutative operation's operands swapped: ex_add and ex_mul call ex_pick_nan(b, a), ex_sub and ex_div ex_pick_nan(a, b) (measured by tests/exact)
// Source: IEEE 754-2019, 6.2.3 (NaN propagation); Intel SDM vol. 1, 2016, 4.8.3.5 (first source)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_pick_nan(uvec2 a, uvec2 b) {
  uvec2 n = ex_is_nan(a) ? a : b;
  return uvec2(n.x, n.y | 0x00080000u);
}

// ex_sig: the 53-bit integer significand (implicit bit set for normal numbers), as (lo, hi).
// Algorithm: low 52 bits of the pattern, bit 52 set when the exponent field is nonzero
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_sig(uvec2 a) {
  uint hi = a.y & 0x000FFFFFu;
  if ((a.y & 0x7FF00000u) != 0u) hi |= 0x00100000u;
  return uvec2(a.x, hi);
}

// ex_exp: the exponent of the integer significand, max(field, 1) (so value = ex_sig * 2^(ex_exp - 1075)).
// Algorithm: exponent field, subnormals and zero counted as field 1
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
int ex_exp(uvec2 a) {
  return max(int((a.y >> 20) & 0x7FFu), 1);
}

// ex_add: a + b in binary64, correctly rounded (ties to even).
// Algorithm: order by magnitude; significands << 10; the smaller jam-shifted by the exponent difference; add or subtract; normalize and round once. Exact cancellation gives +0; (-0) + (-0) = -0
// Source: IEEE 754-2019, 5.4.1, 6.3; Hauser, Berkeley SoftFloat 3e, 2018 (addMagsF64/subMagsF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 60 integer operations)
// @min-es 300
uvec2 ex_add(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return ex_pick_nan(b, a);
  bool sa = a.y >= 0x80000000u, sb = b.y >= 0x80000000u;
  bool infA = (a.y & 0x7FFFFFFFu) == 0x7FF00000u, infB = (b.y & 0x7FFFFFFFu) == 0x7FF00000u;
  if (infA || infB) {
    if (infA && infB && sa != sb) return uvec2(0u, 0xFFF80000u);
    return infA ? a : b;
  }
  uvec2 ma = ex_sig(a), mb = ex_sig(b);
  int xa = ex_exp(a), xb = ex_exp(b);
  if ((ma.x | ma.y | mb.x | mb.y) == 0u) return uvec2(0u, (sa && sb) ? 0x80000000u : 0u);
  if (xb > xa || (xb == xa && ex_lt64(ma, mb))) {
    uvec2 tm = ma; ma = mb; mb = tm;
    int tx = xa; xa = xb; xb = tx;
    bool ts = sa; sa = sb; sb = ts;
  }
  uvec2 big = ex_shl64(ma, 10);
  uvec2 small = ex_shr_jam64(ex_shl64(mb, 10), xa - xb);
  if (sa == sb) return ex_norm_round_pack(sa, xa - 1, ex_add64(big, small));
  uvec2 d = ex_sub64(big, small);
  if ((d.x | d.y) == 0u) return uvec2(0u, 0u);
  return ex_norm_round_pack(sa, xa - 1, d);
}

// ex_neg: -a (flips the sign bit, NaN included, as GLSL's negation of a double does).
// Algorithm: sign bit flip
// Source: IEEE 754-2019, 5.5.1 (negate)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_neg(uvec2 a) {
  return uvec2(a.x, a.y ^ 0x80000000u);
}

// ex_sub: a - b = a + (-b), correctly rounded.
// Algorithm: NaN operands as ex_pick_nan(a, b); otherwise ex_add with the sign of b flipped
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
// @min-es 300
uvec2 ex_sub(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return ex_pick_nan(a, b);
  return ex_add(a, ex_neg(b));
}

// ex_normalize: the 53-bit significand with its top bit at bit 52 and the matching exponent (a finite nonzero a).
// Algorithm: subnormals shifted left by their leading zeros, exponent lowered by the same count
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_normalize(uvec2 a, out int x) {
  uvec2 m = ex_sig(a);
  int shift = ex_clz64(m) - 11;
  x = ex_exp(a) - shift;
  return ex_shl64(m, shift);
}

// ex_mul: a * b in binary64, correctly rounded (ties to even).
// Algorithm: 53x53-bit significand product in 32-bit words (ex_mul32), its top 64 bits with the rest as sticky bit, rounded once
// Source: IEEE 754-2019, 5.4.1, 7.2 (0 * Inf invalid); Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm M
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (16 integer multiplications, about 80 other integer operations)
// @min-es 300
uvec2 ex_mul(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return ex_pick_nan(b, a);
  uint signWord = (a.y ^ b.y) & 0x80000000u;
  uint absA = a.y & 0x7FFFFFFFu, absB = b.y & 0x7FFFFFFFu;
  bool zeroA = (absA | a.x) == 0u, zeroB = (absB | b.x) == 0u;
  if (absA == 0x7FF00000u || absB == 0x7FF00000u) {
    if (zeroA || zeroB) return uvec2(0u, 0xFFF80000u);
    return uvec2(0u, signWord | 0x7FF00000u);
  }
  if (zeroA || zeroB) return uvec2(0u, signWord);
  int xa, xb;
  uvec2 ma = ex_normalize(a, xa), mb = ex_normalize(b, xb);
  uvec2 p00 = ex_mul32(ma.x, mb.x), p01 = ex_mul32(ma.x, mb.y);
  uvec2 p10 = ex_mul32(ma.y, mb.x), p11 = ex_mul32(ma.y, mb.y);
  uvec2 mid = ex_add64(ex_add64(uvec2(p00.y, 0u), uvec2(p01.x, 0u)), uvec2(p10.x, 0u));
  uvec2 top = ex_add64(ex_add64(uvec2(p01.y, 0u), uvec2(p10.y, 0u)), uvec2(mid.y, 0u));
  uint w1 = mid.x;
  uint w2 = top.x + p11.x;
  uint w3 = p11.y + top.y + (w2 < p11.x ? 1u : 0u);
  uvec2 sig = uvec2((w1 >> 10) | (w2 << 22), (w2 >> 10) | (w3 << 22));
  if (p00.x != 0u || (w1 & 0x3FFu) != 0u) sig.x |= 1u;
  return ex_norm_round_pack(signWord != 0u, xa + xb - 1024, sig);
}

// ex_div: a / b in binary64, correctly rounded (ties to even).
// Algorithm: restoring binary long division of the normalized significands, 55 quotient bits, the remainder as sticky bit; rounded once
// Source: IEEE 754-2019, 5.4.1, 7.2-7.3; Ercegovac, Lang, Digital Arithmetic, 2004, ch. 5 (restoring division)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (55 iterations of about 12 integer operations)
// @min-es 300
uvec2 ex_div(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return ex_pick_nan(a, b);
  uint signWord = (a.y ^ b.y) & 0x80000000u;
  uint absA = a.y & 0x7FFFFFFFu, absB = b.y & 0x7FFFFFFFu;
  bool zeroA = (absA | a.x) == 0u, zeroB = (absB | b.x) == 0u;
  bool infA = absA == 0x7FF00000u, infB = absB == 0x7FF00000u;
  if ((infA && infB) || (zeroA && zeroB)) return uvec2(0u, 0xFFF80000u);
  if (infA || zeroB) return uvec2(0u, signWord | 0x7FF00000u);
  if (infB || zeroA) return uvec2(0u, signWord);
  int xa, xb;
  uvec2 rem = ex_normalize(a, xa), mb = ex_normalize(b, xb);
  int e = xa - xb + 1022;
  if (ex_lt64(rem, mb)) {
    rem = ex_shl64(rem, 1);
    e -= 1;
  }
  uvec2 q = uvec2(0u);
  for (int i = 0; i < 55; ++i) {
    q = ex_shl64(q, 1);
    if (!ex_lt64(rem, mb)) {
      rem = ex_sub64(rem, mb);
      q.x |= 1u;
    }
    rem = ex_shl64(rem, 1);
  }
  q = ex_shl64(q, 8);
  if ((rem.x | rem.y) != 0u) q.x |= 1u;
  return ex_round_pack(signWord != 0u, e, q);
}

// ex_sqrt: sqrt(a) in binary64, correctly rounded; sqrt(-0) = -0, sqrt(x < 0) = NaN.
// Algorithm: digit-by-digit binary square root of the significand (exponent made even) scaled by 2^56, 55 root bits, the remainder as sticky bit; rounded once
// Source: IEEE 754-2019, 5.4.1, 7.2; Ercegovac, Lang, Digital Arithmetic, 2004, ch. 6 (digit recurrence square root)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (55 iterations of about 16 integer operations)
// @min-es 300
uvec2 ex_sqrt(uvec2 a) {
  if (ex_is_nan(a)) return ex_pick_nan(a, a);
  uint absA = a.y & 0x7FFFFFFFu;
  if ((absA | a.x) == 0u) return a;
  if (a.y >= 0x80000000u) return uvec2(0u, 0xFFF80000u);
  if (absA == 0x7FF00000u) return a;
  int x;
  uvec2 m = ex_normalize(a, x);
  int e2 = x - 1075;
  if ((e2 & 1) != 0) {
    m = ex_shl64(m, 1);
    e2 -= 1;
  }
  uvec2 pending = ex_shl64(m, 10);
  uvec2 root = uvec2(0u), rem = uvec2(0u);
  for (int i = 0; i < 55; ++i) {
    rem = ex_shl64(rem, 2);
    rem.x |= pending.y >> 30;
    pending = ex_shl64(pending, 2);
    uvec2 trial = ex_shl64(root, 2);
    trial.x |= 1u;
    root = ex_shl64(root, 1);
    if (!ex_lt64(rem, trial)) {
      rem = ex_sub64(rem, trial);
      root.x |= 1u;
    }
  }
  root = ex_shl64(root, 8);
  if ((rem.x | rem.y) != 0u) root.x |= 1u;
  return ex_round_pack(false, 1048 + e2 / 2, root);
}
