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
//   [ERN]  M. D. Ercegovac, T. Lang, Digital Arithmetic, Morgan Kaufmann 2004, ch. 5-6: division
//          and square root by digit recurrence (high radix, digits selected by an estimate and
//          corrected), the remainder as sticky bit. Here the digits are 14-18 bits, estimated
//          with one float division and checked in integer arithmetic.
//   [VTN]  Mesa 22.3 (2022) src/compiler/spirv/vtn_glsl450.c and vtn_alu.c: the operation order of
//          native's determinant, inverse and matrix products (read as a fact source, not copied;
//          the orders kept here are the ones tests/exact measured to give native's bits).
//   [JMP]  M. Joldes, J.-M. Muller, V. Popescu, ACM TOMS 44(2), 2017: the float-float arithmetic
//          (rules/arith.glsl, rules/transcendental.glsl) the transcendental bridges call.
//
// Loops: an operation on a vector or matrix runs its per-component (per-element) operation in a
// loop, so drivers compile one copy of a few hundred integer instructions rather than one per
// component (the generated @per-component instances and matrix helpers do the same). The index is
// computed from the loop counter (W - 1 - counter), never the counter itself: Mesa's GLSL compiler
// unrolls, whatever the body's size, a loop whose counter indexes an array with as many elements as
// the loop has iterations (measured on the matrix helpers; for vector components no difference was
// measured, and the loops here count down all the same) (docs/performance.md, "Mode exact: vector
// and matrix operations as loops").

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
  bool highBelow = a.y < b.y;
  bool lowBelow = all(bvec2(a.y == b.y, a.x < b.x));
  return any(bvec2(highBelow, lowBelow));
}

// ex_sel64: c ? a : b on 64-bit words, one select per word (no branch: GLSL ES 3.00 has no mix on
// integers, and a ternary on a uvec2 becomes control flow in SPIR-V 1.0).
// Algorithm: per-word conditional selection
// Source: Khronos, The OpenGL ES Shading Language 3.00.6, 2016, 5.9 (the ternary selection operator); docs/rules-format.md, "No branches in a rule"
// Bound: exact
// Flops: 0 (2 selects)
// @min-es 300
uvec2 ex_sel64(bool c, uvec2 a, uvec2 b) {
  uint x = c ? a.x : b.x;
  uint y = c ? a.y : b.y;
  return uvec2(x, y);
}

// ex_shl64: a << n for 0 <= n < 64 (GLSL shifts by 32 or more are undefined: no shift here reaches 32).
// Algorithm: both word shifts by k = n mod 32, the bits carried into the high word as (a.x >> 1) >> (31 - k) (0 when k = 0); n >= 32 selects (0, a.x << k). No branch
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword shifts)
// Bound: exact
// Flops: 0 (about 9 integer operations)
// @min-es 300
uvec2 ex_shl64(uvec2 a, int n) {
  uint k = uint(n & 31);
  uint carry = (a.x >> 1u) >> (31u - k);
  uint low = a.x << k;
  uint high = (a.y << k) | carry;
  bool far = n >= 32;
  uint x = far ? 0u : low;
  uint y = far ? low : high;
  return uvec2(x, y);
}

// ex_shr_jam64: a >> n for n >= 0, the shifted-out bits ORed into bit 0 (the sticky bit).
// Algorithm: truncating shift by min(n, 63) (ex_shr64); a bit was lost when shifting back does not give a; n >= 64 leaves only the sticky bit of a != 0 ("jamming"). No branch
// Source: Hauser, Berkeley SoftFloat 3e, 2018 (shiftRightJam64 semantics)
// Bound: exact
// Flops: 0 (about 30 integer operations)
// @min-es 300
uvec2 ex_shr_jam64(uvec2 a, int n) {
  int m = min(n, 63);
  uvec2 kept = ex_shr64(a, m);
  uvec2 back = ex_shl64(kept, m);
  bool far = n >= 64;
  bool lostNear = any(notEqual(back, a));
  bool nonzero = (a.x | a.y) != 0u;
  bool lost = far ? nonzero : lostNear;
  uint x = far ? 0u : kept.x;
  uint y = far ? 0u : kept.y;
  uint jam = lost ? 1u : 0u;
  return uvec2(x | jam, y);
}

// ex_clz32: count of leading zero bits of a 32-bit word (32 for 0); ES 3.00 has no findMSB.
// Algorithm: binary search over 16, 8, 4, 2, 1 bit halves, each step by selects (no branch)
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3 (nlz, binary search)
// Bound: exact
// Flops: 0 (about 16 integer operations)
// @min-es 300
int ex_clz32(uint x) {
  bool z16 = (x & 0xFFFF0000u) == 0u;
  uint y16 = x << 16;
  uint y = z16 ? y16 : x;
  int n16 = z16 ? 16 : 0;
  bool z8 = (y & 0xFF000000u) == 0u;
  uint y8 = y << 8;
  y = z8 ? y8 : y;
  int n8 = z8 ? 8 : 0;
  bool z4 = (y & 0xF0000000u) == 0u;
  uint y4 = y << 4;
  y = z4 ? y4 : y;
  int n4 = z4 ? 4 : 0;
  bool z2 = (y & 0xC0000000u) == 0u;
  uint y2 = y << 2;
  y = z2 ? y2 : y;
  int n2 = z2 ? 2 : 0;
  int n1 = (y & 0x80000000u) == 0u ? 1 : 0;
  int n = n16 + n8 + n4 + n2 + n1;
  return x == 0u ? 32 : n;
}

// ex_clz32: ex_clz32 by findMSB, where the target has GLSL's integer functions.
// Algorithm: 31 - findMSB(x); findMSB(0) is -1, so 0 gives 32
// Source: Khronos, The OpenGL ES Shading Language 3.10, 2014, 8.8 (findMSB)
// Bound: exact
// Flops: 0 (2 integer operations)
// @min-es 310
// @variant integer-functions
int ex_clz32(uint x) {
  return 31 - findMSB(x);
}

// ex_clz64: leading zero bits of a 64-bit (lo, hi) value (64 for 0).
// Algorithm: ex_clz32 of the high word, else 32 + ex_clz32 of the low word
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3
// Bound: exact
// Flops: 0
// @min-es 300
int ex_clz64(uvec2 a) {
  int high = ex_clz32(a.y);
  int low = 32 + ex_clz32(a.x);
  return a.y != 0u ? high : low;
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

// ex_mul32: ex_mul32 by umulExtended, where the target has GLSL's integer functions (Mesa's soft-fp64 multiplies this way too).
// Algorithm: umulExtended: the 64-bit product's high and low words in one built-in
// Source: Khronos, The OpenGL ES Shading Language 3.10, 2014, 8.8 (umulExtended)
// Bound: exact
// Flops: 0 (1 integer multiplication)
// @min-es 310
// @variant integer-functions
uvec2 ex_mul32(uint a, uint b) {
  uint hi, lo;
  umulExtended(a, b, hi, lo);
  return uvec2(lo, hi);
}

// ex_round_pack: the binary64 nearest (ties to even) to sig * 2^(e - 1084), sign s. sig < 2^63; if e > 0 its top bit must be bit 62.
// Algorithm: e < 0: jamming shift to e = 0 (subnormal); keep 53 bits, 10 round bits; add half, clear the last bit on an exact tie; the significand's carry runs into the exponent field (up to infinity); e > 0x7FD selects infinity. No branch
// Source: IEEE 754-2019, 4.3.1; Hauser, Berkeley SoftFloat 3e, 2018 (roundPackToF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 30 integer operations)
// @min-es 300
uvec2 ex_round_pack(bool s, int e, uvec2 sig) {
  uint signWord = s ? 0x80000000u : 0u;
  bool tiny = e < 0;
  int shift = tiny ? -e : 0;
  int field = tiny ? 0 : e;
  uvec2 t = ex_shr_jam64(sig, shift);
  uint roundBits = t.x & 0x3FFu;
  uvec2 u = ex_add64(t, uvec2(0x200u, 0u));
  uint x = (u.x >> 10) | (u.y << 22);
  uint tie = roundBits == 0x200u ? 0xFFFFFFFEu : 0xFFFFFFFFu;
  uvec2 rounded = uvec2(x & tie, u.y >> 10);
  uvec2 finite = ex_add64(uvec2(0u, signWord | (uint(field) << 20)), rounded);
  return ex_sel64(e > 0x7FD, uvec2(0u, signWord | 0x7FF00000u), finite);
}

// ex_norm_round_pack: ex_round_pack for any nonzero 64-bit sig: first moved so its top bit is bit 62.
// Algorithm: count leading zeros; shift left (exact) or jam-shift right by one, both computed and one selected
// Source: Hauser, Berkeley SoftFloat 3e, 2018 (normRoundPackToF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
// @min-es 300
uvec2 ex_norm_round_pack(bool s, int e, uvec2 sig) {
  int z = ex_clz64(sig);
  bool top = z == 0;
  uvec2 right = ex_shr_jam64(sig, 1);
  uvec2 left = ex_shl64(sig, max(z - 1, 0));
  uvec2 m = ex_sel64(top, right, left);
  int f = top ? e + 1 : e - (z - 1);
  return ex_round_pack(s, f, m);
}

// ex_is_nan: true when the bit pattern is a NaN.
// Algorithm: exponent field all ones and a nonzero significand
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
bool ex_is_nan(uvec2 a) {
  uint m = a.y & 0x7FFFFFFFu;
  bool above = m > 0x7FF00000u;
  bool low = all(bvec2(m == 0x7FF00000u, a.x != 0u));
  return any(bvec2(above, low));
}

// ex_either_nan: true when a or b is a NaN (the first test of every two-operand operation).
// Algorithm: ex_is_nan of each, combined by any() on a bvec2 (no short-circuit branch)
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
bool ex_either_nan(uvec2 a, uvec2 b) {
  return any(bvec2(ex_is_nan(a), ex_is_nan(b)));
}

// ex_pick_nan: the NaN result of an operation with a NaN operand: a if it is a NaN, else b, made quiet.
// Algorithm: set the quiet bit (significand bit 51) of a if it is a NaN, else of b. Native fp64 on lavapipe (LLVM, x86 SSE) returns the first source operand's NaN, and LLVM passes a commutative operation's operands swapped: ex_add_bits and ex_mul_bits call ex_pick_nan(b, a), ex_sub_bits and ex_div_bits ex_pick_nan(a, b) (measured by tests/exact)
// Source: IEEE 754-2019, 6.2.3 (NaN propagation); Intel SDM vol. 1, 2016, 4.8.3.5 (first source)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_pick_nan(uvec2 a, uvec2 b) {
  uvec2 n = ex_sel64(ex_is_nan(a), a, b);
  return uvec2(n.x, n.y | 0x00080000u);
}

// ex_sig: the 53-bit integer significand (implicit bit set for normal numbers), as (lo, hi).
// Algorithm: low 52 bits of the pattern, bit 52 set when the exponent field is nonzero
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_sig(uvec2 a) {
  uint implicit = (a.y & 0x7FF00000u) != 0u ? 0x00100000u : 0u;
  uint hi = (a.y & 0x000FFFFFu) | implicit;
  return uvec2(a.x, hi);
}

// ex_exponent: the exponent of the integer significand, max(field, 1) (so value = ex_sig * 2^(ex_exponent - 1075)).
// Algorithm: exponent field, subnormals and zero counted as field 1
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
int ex_exponent(uvec2 a) {
  return max(int((a.y >> 20) & 0x7FFu), 1);
}

// ex_add_bits: a + b in binary64, correctly rounded (ties to even).
// Algorithm: order by magnitude; significands << 10; the smaller jam-shifted by the exponent difference; add or subtract; normalize and round once. Exact cancellation gives +0; (-0) + (-0) = -0. One branch: NaN, infinite or two zero operands return early (selected among themselves); the finite path is computed whole, cancellation selected (docs/performance.md, "Mode exact: one branch per operation")
// Source: IEEE 754-2019, 5.4.1, 6.3; Hauser, Berkeley SoftFloat 3e, 2018 (addMagsF64/subMagsF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 60 integer operations)
// @min-es 300
uvec2 ex_add_bits(uvec2 a, uvec2 b) {
  bool sa = a.y >= 0x80000000u, sb = b.y >= 0x80000000u;
  uvec2 ma = ex_sig(a), mb = ex_sig(b);
  bool zeros = (ma.x | ma.y | mb.x | mb.y) == 0u;
  bool topA = (a.y & 0x7FF00000u) == 0x7FF00000u, topB = (b.y & 0x7FF00000u) == 0x7FF00000u;
  if (any(bvec3(topA, topB, zeros))) {
    bool nan = ex_either_nan(a, b);
    bool invalid = all(bvec3(topA, topB, sa != sb));
    uvec2 infinite = ex_sel64(invalid, uvec2(0u, 0xFFF80000u), ex_sel64(topA, a, b));
    uint zeroSign = all(bvec2(sa, sb)) ? 0x80000000u : 0u;
    uvec2 special = ex_sel64(any(bvec2(topA, topB)), infinite, uvec2(0u, zeroSign));
    return ex_sel64(nan, ex_pick_nan(b, a), special);
  }
  int xa = ex_exponent(a), xb = ex_exponent(b);
  bool swap = any(bvec2(xb > xa, all(bvec2(xb == xa, ex_lt64(ma, mb)))));
  uvec2 m1 = ex_sel64(swap, mb, ma), m2 = ex_sel64(swap, ma, mb);
  int x1 = swap ? xb : xa, x2 = swap ? xa : xb;
  bool s1 = swap ? sb : sa, s2 = swap ? sa : sb;
  uvec2 big = ex_shl64(m1, 10);
  uvec2 small = ex_shr_jam64(ex_shl64(m2, 10), x1 - x2);
  bool same = s1 == s2;
  uvec2 d = ex_sel64(same, ex_add64(big, small), ex_sub64(big, small));
  bool cancelled = (d.x | d.y) == 0u;
  uvec2 r = ex_norm_round_pack(s1, x1 - 1, d);
  return ex_sel64(cancelled, uvec2(0u, 0u), r);
}

// ex_neg_bits: -a (flips the sign bit, NaN included, as GLSL's negation of a double does).
// Algorithm: sign bit flip
// Source: IEEE 754-2019, 5.5.1 (negate)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_neg_bits(uvec2 a) {
  return uvec2(a.x, a.y ^ 0x80000000u);
}

// ex_sub_bits: a - b = a + (-b), correctly rounded.
// Algorithm: NaN operands as ex_pick_nan(a, b); otherwise ex_add with the sign of b flipped
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
// @min-es 300
uvec2 ex_sub_bits(uvec2 a, uvec2 b) {
  bool nan = ex_either_nan(a, b);
  uvec2 r = ex_add_bits(a, ex_neg_bits(b));
  return ex_sel64(nan, ex_pick_nan(a, b), r);
}

// ex_normalize_sig: the 53-bit significand with its top bit at bit 52 and the matching exponent (a finite nonzero a).
// Algorithm: a normal number's significand as it is; subnormals shifted left by their leading zeros, exponent lowered by the same count (a zero shifts by 53 and stays 0; no branch)
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_normalize_sig(uvec2 a, out int x) {
  uvec2 m = ex_sig(a);
  bool normal = (a.y & 0x7FF00000u) != 0u;
  int lead = ex_clz64(m) - 11;
  int shift = normal ? 0 : lead;
  int field = int((a.y >> 20) & 0x7FFu);
  x = normal ? field : 1 - shift;
  return ex_shl64(m, shift);
}

// ex_mul_bits: a * b in binary64, correctly rounded (ties to even).
// Algorithm: 53x53-bit significand product in 32-bit words (ex_mul32), its top 64 bits with the rest as sticky bit, a one-bit jamming normalization, rounded once. One branch: NaN, infinite or zero operands return early (selected among themselves)
// Source: IEEE 754-2019, 5.4.1, 7.2 (0 * Inf invalid); Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm M
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (16 integer multiplications, about 80 other integer operations)
// @min-es 300
uvec2 ex_mul_bits(uvec2 a, uvec2 b) {
  uint signWord = (a.y ^ b.y) & 0x80000000u;
  uint absA = a.y & 0x7FFFFFFFu, absB = b.y & 0x7FFFFFFFu;
  bool zero = any(bvec2((absA | a.x) == 0u, (absB | b.x) == 0u));
  bool topA = absA >= 0x7FF00000u, topB = absB >= 0x7FF00000u;
  if (any(bvec3(topA, topB, zero))) {
    bool nan = ex_either_nan(a, b);
    uvec2 infinite = ex_sel64(zero, uvec2(0u, 0xFFF80000u), uvec2(0u, signWord | 0x7FF00000u));
    uvec2 special = ex_sel64(any(bvec2(topA, topB)), infinite, uvec2(0u, signWord));
    return ex_sel64(nan, ex_pick_nan(b, a), special);
  }
  int xa, xb;
  uvec2 ma = ex_normalize_sig(a, xa), mb = ex_normalize_sig(b, xb);
  uvec2 p00 = ex_mul32(ma.x, mb.x), p01 = ex_mul32(ma.x, mb.y);
  uvec2 p10 = ex_mul32(ma.y, mb.x), p11 = ex_mul32(ma.y, mb.y);
  uvec2 mid = ex_add64(ex_add64(uvec2(p00.y, 0u), uvec2(p01.x, 0u)), uvec2(p10.x, 0u));
  uvec2 top = ex_add64(ex_add64(uvec2(p01.y, 0u), uvec2(p10.y, 0u)), uvec2(mid.y, 0u));
  uint w1 = mid.x;
  uint w2 = top.x + p11.x;
  uint w3 = p11.y + top.y + (w2 < p11.x ? 1u : 0u);
  uint sticky = any(bvec2(p00.x != 0u, (w1 & 0x3FFu) != 0u)) ? 1u : 0u;
  uvec2 sig = uvec2((w1 >> 10) | (w2 << 22) | sticky, (w2 >> 10) | (w3 << 22));
  // The product of two significands in [2^52, 2^53) leaves sig's top bit at 63 or 62.
  bool carry = sig.y >= 0x80000000u;
  uvec2 halved = uvec2((sig.x >> 1) | (sig.y << 31) | (sig.x & 1u), sig.y >> 1);
  int e = xa + xb - 1024 + (carry ? 1 : 0);
  return ex_round_pack(signWord != 0u, e, ex_sel64(carry, halved, sig));
}

// ex_div_step: k more quotient bits of a long division by mb: (q, r) as (q.x, q.y, r.x, r.y), 0 <= r < 2mb, becomes (q * 2^k + d, r * 2^k - d * mb) with the digit d that leaves 0 <= r' < mb (k <= 18, mb < 2^53).
// Algorithm: d = r * 2^k / mb estimated by one float division: r and mb reach float with relative errors below 2^-23 each and the quotient is below 2^19, so the estimate is within 0.25 of r * 2^k / mb (also with the 2.5-ulp float division GLSL allows) and d within one of the true digit; r' in 64-bit words modulo 2^64 (the true r' is small and signed); one unit correction each way, by selects (no loop)
// Source: Ercegovac, Lang, Digital Arithmetic, 2004, ch. 5 (division by digit recurrence: high radix, digit selection by an estimate, correction); Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm D
// Bound: exact
// Flops: 8 (the digit estimate)
// @min-es 300
uvec4 ex_div_step(uvec4 qr, uvec2 mb, int k) {
  uvec2 q = qr.xy, r = qr.zw;
  float estimate = floor(ex_u64_to_float(r) * float(1u << uint(k)) / ex_u64_to_float(mb));
  uint d = uint(estimate);
  uvec2 dm = ex_mul32(d, mb.x);
  dm.y += d * mb.y;
  r = ex_sub64(ex_shl64(r, k), dm);
  q = ex_add64(ex_shl64(q, k), uvec2(d, 0u));
  bool quotientTooLarge = r.y >= 0x80000000u;
  q = ex_sub64(q, uvec2(quotientTooLarge ? 1u : 0u, 0u));
  r = ex_sel64(quotientTooLarge, ex_add64(r, mb), r);
  bool quotientTooSmall = !ex_lt64(r, mb);
  q = ex_add64(q, uvec2(quotientTooSmall ? 1u : 0u, 0u));
  r = ex_sel64(quotientTooSmall, ex_sub64(r, mb), r);
  return uvec4(q, r);
}

// ex_div_bits: a / b in binary64, correctly rounded (ties to even).
// Algorithm: long division of the normalized significands, 55 quotient bits in three 18-bit ex_div_step digits (float estimates checked in integers), the remainder as sticky bit; rounded once. One branch: NaN, infinite or zero operands return early (selected among themselves); no loop (each digit's correction is one select each way)
// Source: IEEE 754-2019, 5.4.1, 7.2-7.3; Ercegovac, Lang, Digital Arithmetic, 2004, ch. 5 (division by digit recurrence)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 24 (estimates: 8 per ex_div_step)
// @min-es 300
uvec2 ex_div_bits(uvec2 a, uvec2 b) {
  uint signWord = (a.y ^ b.y) & 0x80000000u;
  uint absA = a.y & 0x7FFFFFFFu, absB = b.y & 0x7FFFFFFFu;
  bool zeroA = (absA | a.x) == 0u, zeroB = (absB | b.x) == 0u;
  bool topA = absA >= 0x7FF00000u, topB = absB >= 0x7FF00000u;
  if (any(bvec4(topA, topB, zeroA, zeroB))) {
    bool nan = ex_either_nan(a, b);
    bool invalid = any(bvec2(all(bvec2(topA, topB)), all(bvec2(zeroA, zeroB))));
    bool infinite = any(bvec2(topA, zeroB));
    uvec2 special = ex_sel64(infinite, uvec2(0u, signWord | 0x7FF00000u), uvec2(0u, signWord));
    special = ex_sel64(invalid, uvec2(0u, 0xFFF80000u), special);
    return ex_sel64(nan, ex_pick_nan(a, b), special);
  }
  int xa, xb;
  uvec2 ma = ex_normalize_sig(a, xa), mb = ex_normalize_sig(b, xb);
  bool below = ex_lt64(ma, mb);
  uvec2 rem = ex_sel64(below, ex_shl64(ma, 1), ma);
  int e = xa - xb + 1022 - (below ? 1 : 0);
  // rem in [mb, 2mb): q = floor(rem * 2^54 / mb) has 55 bits.
  uvec4 qr = ex_div_step(uvec4(0u, 0u, rem), mb, 18);
  qr = ex_div_step(qr, mb, 18);
  qr = ex_div_step(qr, mb, 18);
  uvec2 q = ex_shl64(qr.xy, 8);
  uint remainderBit = (qr.z | qr.w) != 0u ? 1u : 0u;
  return ex_round_pack(signWord != 0u, e, uvec2(q.x | remainderBit, q.y));
}

// ex_u64_to_float: a 64-bit (lo, hi) integer as a float, rounded (an estimate for ex_sqrt_bits).
// Algorithm: float(hi) * 2^32 + float(lo)
// Source: IEEE 754-2019, 5.4.1 (convertFromInt)
// Bound: 0.5 ulp of float, twice (an estimate: relative error below 2^-23)
// Flops: 2
// @min-es 300
float ex_u64_to_float(uvec2 a) {
  return float(a.y) * 4294967296.0 + float(a.x);
}

// ex_root_step: 14 more bits of an integer square root: (q, r) as (q.x, q.y, r.x, r.y), q = floor(sqrt(n)) and r = n - q^2, becomes the root of n * 2^28 and its remainder (2^26 <= q < 2^41).
// Algorithm: digit d = r * 2^14 / (2q) estimated by one float division: the estimate is within 2^-7 of r * 2^14 / (2q) (float errors below 2^-21 of a digit below 2^14), which is within 2^-13 of the true digit's real root (q >= 2^26), so d is within one of the true digit; r' = r * 2^28 - d * (2q * 2^14 + d) in 64-bit words modulo 2^64 (the true r' is small and signed); q' = q * 2^14 + d; then one unit correction each way, by selects (no loop), leaves 0 <= r' <= 2q'
// Source: Ercegovac, Lang, Digital Arithmetic, 2004, ch. 6 (square root by digit recurrence: partial remainder, digit selection by an estimate, correction); Knuth TAOCP vol. 2, 1997, 4.3.1
// Bound: exact
// Flops: 8 (the digit estimate)
// @min-es 300
uvec4 ex_root_step(uvec4 qr) {
  uvec2 q = qr.xy, r = qr.zw;
  float estimate = floor(ex_u64_to_float(r) * 8192.0 / ex_u64_to_float(q));
  uint d = uint(min(estimate, 16383.0));
  uvec2 t = ex_add64(ex_shl64(q, 15), uvec2(d, 0u));
  uvec2 dt = ex_mul32(d, t.x);
  dt.y += d * t.y;
  r = ex_sub64(ex_shl64(r, 28), dt);
  q = ex_add64(ex_shl64(q, 14), uvec2(d, 0u));
  bool digitTooLarge = r.y >= 0x80000000u;
  q = ex_sub64(q, uvec2(digitTooLarge ? 1u : 0u, 0u));
  r = ex_sel64(digitTooLarge, ex_add64(r, ex_add64(ex_shl64(q, 1), uvec2(1u, 0u))), r);
  bool digitTooSmall = ex_lt64(ex_shl64(q, 1), r);
  r = ex_sel64(digitTooSmall, ex_sub64(r, ex_add64(ex_shl64(q, 1), uvec2(1u, 0u))), r);
  q = ex_add64(q, uvec2(digitTooSmall ? 1u : 0u, 0u));
  return uvec4(q, r);
}

// ex_sqrt_bits: sqrt(a) in binary64, correctly rounded; sqrt(-0) = -0, sqrt(x < 0) = NaN.
// Algorithm: the 55-bit integer root Q = floor(sqrt(m * 2^56)) of the significand m (exponent made even) and its exact remainder, the sticky bit: 27 bits from the float sqrt of m (within 40 of the root, even with the few-ulp float sqrt GLSL allows) with one Newton correction (then at most one too large) and one unit correction each way against the exact remainder m - q^2, then two ex_root_step digits of 14 bits; rounded once. Float arithmetic only estimates; every accepted digit is checked in integers. One branch: NaN, zero, negative or infinite operands return early (selected among themselves); no loop (corrections by selects)
// Source: IEEE 754-2019, 5.4.1, 7.2; Ercegovac, Lang, Digital Arithmetic, 2004, ch. 6 (digit recurrence square root with estimated digits)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 26 (estimates: 10 here, 8 per ex_root_step)
// @min-es 300
uvec2 ex_sqrt_bits(uvec2 a) {
  uint absA = a.y & 0x7FFFFFFFu;
  bool zero = (absA | a.x) == 0u, negative = a.y >= 0x80000000u;
  if (any(bvec3(zero, negative, absA >= 0x7FF00000u))) {
    // NaN: made quiet; zeros and +Inf: themselves; other negatives, -Inf included: the default NaN.
    uvec2 special = ex_sel64(any(bvec2(zero, !negative)), a, uvec2(0u, 0xFFF80000u));
    return ex_sel64(ex_is_nan(a), ex_pick_nan(a, a), special);
  }
  int x;
  uvec2 normalized = ex_normalize_sig(a, x);
  int unbiased = x - 1075;
  bool odd = (unbiased & 1) != 0;
  uvec2 m = ex_sel64(odd, ex_shl64(normalized, 1), normalized);
  int e2 = unbiased - (odd ? 1 : 0);
  // m in [2^52, 2^54): q = floor(sqrt(m)) has 27 bits, rem = m - q^2 <= 2q.
  float mf = ex_u64_to_float(m);
  uint q = uint(sqrt(mf));
  uvec2 rem = ex_sub64(m, ex_mul32(q, q));
  float remBelow = -ex_u64_to_float(ex_sub64(uvec2(0u), rem));
  float remAbove = ex_u64_to_float(rem);
  float rf = rem.y >= 0x80000000u ? remBelow : remAbove;
  float correction = floor(rf / (2.0 * float(q)) + 0.5);
  q = uint(int(q) + int(correction));
  rem = ex_sub64(m, ex_mul32(q, q));
  bool rootTooLarge = rem.y >= 0x80000000u;
  q -= rootTooLarge ? 1u : 0u;
  rem = ex_sel64(rootTooLarge, ex_add64(rem, uvec2(2u * q + 1u, 0u)), rem);
  bool rootTooSmall = ex_lt64(uvec2(2u * q, 0u), rem);
  rem = ex_sel64(rootTooSmall, ex_sub64(rem, uvec2(2u * q + 1u, 0u)), rem);
  q += rootTooSmall ? 1u : 0u;
  uvec4 qr = ex_root_step(ex_root_step(uvec4(q, 0u, rem)));
  uvec2 root = ex_shl64(qr.xy, 8);
  uint rootRemainderBit = (qr.z | qr.w) != 0u ? 1u : 0u;
  return ex_round_pack(false, 1048 + e2 / 2, uvec2(root.x | rootRemainderBit, root.y));
}

// ex_fma_bits: fma(a, b, c) as native fp64 on lavapipe computes it: a * b rounded to binary64, then + c rounded (two roundings, not IEEE fusedMultiplyAdd).
// Algorithm: p = ex_mul_bits(a, b), then ex_add_bits(p, c); with NaN operands native passes on the first NaN of a, b (then p, c) in operand order, not swapped as for a * b (measured by tests/exact/exact_fma_test.cpp)
// Source: GLSL 4.60 specification, 2017, 8.3 (fma: "may" be a single operation; precision of a*b+c otherwise); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (two roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_fma_bits(uvec2 a, uvec2 b, uvec2 c) {
  bool nan = ex_either_nan(a, b);
  uvec2 p = ex_mul_bits(a, b);
  uvec2 r = ex_sel64(ex_is_nan(p), p, ex_add_bits(p, c));
  return ex_sel64(nan, ex_pick_nan(a, b), r);
}

// ex_shr64: a >> n for 0 <= n < 64 (bits shifted out are dropped: truncation).
// Algorithm: both word shifts by k = n mod 32, the bits carried into the low word as (a.y << 1) << (31 - k) (0 when k = 0); n >= 32 selects (a.y >> k, 0). No branch
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword shifts)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_shr64(uvec2 a, int n) {
  uint k = uint(n & 31);
  uint carry = (a.y << 1u) << (31u - k);
  uint low = (a.x >> k) | carry;
  uint high = a.y >> k;
  bool far = n >= 32;
  uint x = far ? high : low;
  uint y = far ? 0u : high;
  return uvec2(x, y);
}

// ex_lt_bits: a < b on binary64 patterns: false with a NaN; -0 == +0.
// Algorithm: sign-magnitude order: opposite signs: a negative and not both zero; equal signs: magnitudes compared as 64-bit integers (reversed for negatives)
// Source: IEEE 754-2019, 5.11 (comparison predicates)
// Bound: exact
// Flops: 0
// @min-es 300
bool ex_lt_bits(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return false;
  bool sa = a.y >= 0x80000000u, sb = b.y >= 0x80000000u;
  if (sa != sb) return sa && ((a.y | b.y) & 0x7FFFFFFFu | a.x | b.x) != 0u;
  return sa ? ex_lt64(b, a) : ex_lt64(a, b);
}

// ex_eq_bits: a == b on binary64 patterns: false with a NaN; -0 == +0.
// Algorithm: equal patterns, or both zero; never with a NaN
// Source: IEEE 754-2019, 5.11 (comparison predicates)
// Bound: exact
// Flops: 0
// @min-es 300
bool ex_eq_bits(uvec2 a, uvec2 b) {
  if (ex_is_nan(a) || ex_is_nan(b)) return false;
  return a == b || ((a.y | b.y) & 0x7FFFFFFFu | a.x | b.x) == 0u;
}

// ex_from_float_bits: the binary64 pattern of a float (exact; a float subnormal becomes a normal double; a NaN stays NaN, made quiet).
// Algorithm: re-bias the exponent (127 -> 1023), subnormals normalized with ex_clz32, significand moved up 29 bits
// Source: IEEE 754-2019, 5.4.2 (formatOf conversions); 3.4 (binary32, binary64 encodings)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_from_float_bits(float f) {
  uint u = floatBitsToUint(f);
  uint signWord = u & 0x80000000u;
  int e = int((u >> 23) & 0xFFu);
  uint m = u & 0x7FFFFFu;
  if (e == 0xFF) {
    if (m != 0u) m |= 0x400000u;
    return uvec2(m << 29, signWord | 0x7FF00000u | (m >> 3));
  }
  if (e == 0) {
    if (m == 0u) return uvec2(0u, signWord);
    int shift = ex_clz32(m) - 8;
    m = (m << uint(shift)) & 0x7FFFFFu;
    e = 1 - shift;
  }
  return uvec2(m << 29, signWord | (uint(e - 127 + 1023) << 20) | (m >> 3));
}

// ex_to_float_bits: the float nearest (ties to even) to a binary64 pattern, as float bits; overflow gives Inf, tiny values float subnormals or zero.
// Algorithm: significand cut to 31 bits with a sticky bit, exponent re-biased (1023 -> 127); round-and-pack with 7 round bits (jamming shift into the float subnormal range)
// Source: IEEE 754-2019, 5.4.2, 4.3.1; Hauser, Berkeley SoftFloat 3e, 2018 (roundPackToF32 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
// @min-es 300
uint ex_to_float_bits(uvec2 a) {
  uint signWord = a.y & 0x80000000u;
  int field = int((a.y >> 20) & 0x7FFu);
  uint fracHi = a.y & 0xFFFFFu;
  if (field == 0x7FF) {
    if ((fracHi | a.x) == 0u) return signWord | 0x7F800000u;
    return signWord | 0x7FC00000u | (fracHi << 3) | (a.x >> 29);
  }
  if (field == 0) return signWord;
  uint sig = 0x40000000u | (fracHi << 10) | (a.x >> 22);
  if ((a.x & 0x3FFFFFu) != 0u) sig |= 1u;
  int e = field - 1023 + 127 - 1;
  if (e > 0xFD) return signWord | 0x7F800000u;
  if (e < 0) {
    int n = -e;
    sig = n >= 31 ? 1u : (sig >> uint(n)) | ((sig << uint(32 - n)) != 0u ? 1u : 0u);
    e = 0;
  }
  uint roundBits = sig & 0x7Fu;
  sig = (sig + 0x40u) >> 7;
  if (roundBits == 0x40u) sig &= 0xFFFFFFFEu;
  return signWord + (uint(e) << 23) + sig;
}

// ex_from_uint_bits: the binary64 pattern of a uint (exact: 32 bits fit in 53).
// Algorithm: the integer as a 64-bit significand, normalized and packed (no rounding happens)
// Source: IEEE 754-2019, 5.4.1 (convertFromInt)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_from_uint_bits(bool negative, uint m) {
  if (m == 0u) return uvec2(0u);
  return ex_norm_round_pack(negative, 1084, uvec2(m, 0u));
}

// ex_trunc_magnitude: the integer part of |a| as a 64-bit integer, for |a| < 2^64 (0 for |a| < 1).
// Algorithm: the 53-bit significand shifted by the exponent (right: bits dropped, truncation; left up to 11 bits,
// so that uint64_t's top bit is reached)
// Source: IEEE 754-2019, 5.8 (convertToIntegerTowardZero)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_trunc_magnitude(uvec2 a) {
  int field = int((a.y >> 20) & 0x7FFu);
  if (field < 1023) return uvec2(0u);
  uvec2 m = ex_sig(a);
  return field <= 1075 ? ex_shr64(m, 1075 - field) : ex_shl64(m, min(field - 1075, 11));
}

// ex_round_integral_bits: a rounded to an integral binary64 value: mode 0 toward zero (trunc), 1 toward -Inf (floor), 2 toward +Inf (ceil), 3 to nearest even.
// Algorithm: clear the fraction bits of the pattern; add one unit of the integer part's last place (a carry into the exponent is right) when the mode says so; |a| < 1 handled apart; NaN made quiet
// Source: IEEE 754-2019, 5.3.1 (roundToIntegral*)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_round_integral_bits(uvec2 a, int mode) {
  if (ex_is_nan(a)) return ex_pick_nan(a, a);
  int field = int((a.y >> 20) & 0x7FFu);
  if (field >= 1075) return a;
  bool negative = a.y >= 0x80000000u;
  uint signWord = a.y & 0x80000000u;
  bool zero = ((a.y & 0x7FFFFFFFu) | a.x) == 0u;
  if (field < 1023) {
    bool up = (mode == 1 && negative && !zero) || (mode == 2 && !negative && !zero) ||
              (mode == 3 && field == 1022 && ((a.y & 0xFFFFFu) | a.x) != 0u);
    return uvec2(0u, signWord | (up ? 0x3FF00000u : 0u));
  }
  int n = 1075 - field;
  uvec2 unit = ex_shl64(uvec2(1u, 0u), n);
  uvec2 mask = ex_sub64(unit, uvec2(1u, 0u));
  uvec2 frac = uvec2(a.x & mask.x, a.y & mask.y);
  uvec2 t = uvec2(a.x & ~mask.x, a.y & ~mask.y);
  if ((frac.x | frac.y) == 0u) return a;
  bool up = (mode == 1 && negative) || (mode == 2 && !negative);
  if (mode == 3) {
    uvec2 halfUnit = ex_shr64(unit, 1);
    up = ex_lt64(halfUnit, frac) || (frac == halfUnit && (ex_shr64(t, n).x & 1u) != 0u);
  }
  return up ? ex_add64(t, unit) : t;
}

// ex_bits: the binary64 pattern of a mode-exact double as uvec2(low word, high word), the order of unpackDouble2x32.
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32 word order)
// Bound: exact
// Flops: 0
// @min-es 300
uvec2 ex_bits(df_double a) {
  return uvec2(a.lo, a.hi);
}

// ex_from_bits: the mode-exact double of a binary64 pattern uvec2(low word, high word).
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (packDouble2x32 word order)
// Bound: exact
// Flops: 0
// @min-es 300
df_double ex_from_bits(uvec2 w) {
  return df_double(w.y, w.x);
}

// ex_add: a + b (mode exact), correctly rounded.
// Algorithm: ex_add_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_add($DF a, $DF b) {
  return ex_from_bits(ex_add_bits(ex_bits(a), ex_bits(b)));
}

// ex_sub: a - b (mode exact), correctly rounded.
// Algorithm: ex_sub_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_sub($DF a, $DF b) {
  return ex_from_bits(ex_sub_bits(ex_bits(a), ex_bits(b)));
}

// ex_mul: a * b (mode exact), correctly rounded.
// Algorithm: ex_mul_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_mul($DF a, $DF b) {
  return ex_from_bits(ex_mul_bits(ex_bits(a), ex_bits(b)));
}

// ex_div: a / b (mode exact), correctly rounded.
// Algorithm: ex_div_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_div($DF a, $DF b) {
  return ex_from_bits(ex_div_bits(ex_bits(a), ex_bits(b)));
}

// ex_sqrt: sqrt(a) (mode exact), correctly rounded.
// Algorithm: ex_sqrt_bits on the pattern
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_sqrt($DF a) {
  return ex_from_bits(ex_sqrt_bits(ex_bits(a)));
}

// ex_fma: fma(a, b, c) (mode exact): as native fp64 on lavapipe, a * b rounded, then + c rounded.
// Algorithm: ex_fma_bits on the patterns
// Source: GLSL 4.60 specification, 2017, 8.3 (fma); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (two roundings)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_fma($DF a, $DF b, $DF c) {
  return ex_from_bits(ex_fma_bits(ex_bits(a), ex_bits(b), ex_bits(c)));
}

// ex_neg: -a (mode exact): the sign bit flipped.
// Algorithm: sign bit flip of the high word
// Source: IEEE 754-2019, 5.5.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @min-es 300
$DF ex_neg($DF a) {
  return $DF(a.hi ^ $U(0x80000000u), a.lo);
}

// ex_abs: abs(a) (mode exact): the sign bit cleared.
// Algorithm: sign bit cleared in the high word
// Source: IEEE 754-2019, 5.5.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @min-es 300
$DF ex_abs($DF a) {
  return $DF(a.hi & $U(0x7FFFFFFFu), a.lo);
}

// ex_from_float: double(f) (mode exact), exact.
// Algorithm: ex_from_float_bits
// Source: IEEE 754-2019, 5.4.2
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_from_float($F f) {
  return ex_from_bits(ex_from_float_bits(f));
}

// ex_to_float: float(a) (mode exact), rounded to nearest even.
// Algorithm: ex_to_float_bits
// Source: IEEE 754-2019, 5.4.2
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$F ex_to_float($DF a) {
  return uintBitsToFloat(ex_to_float_bits(ex_bits(a)));
}

// ex_from_int: double(i) (mode exact), exact.
// Algorithm: sign and magnitude (0u - uint(i) for negatives, -2^31 included), ex_from_uint_bits
// Source: IEEE 754-2019, 5.4.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_from_int($I i) {
  return ex_from_bits(ex_from_uint_bits(i < 0, i < 0 ? 0u - uint(i) : uint(i)));
}

// ex_from_uint: double(u) (mode exact), exact.
// Algorithm: ex_from_uint_bits
// Source: IEEE 754-2019, 5.4.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_from_uint($U u) {
  return ex_from_bits(ex_from_uint_bits(false, u));
}

// ex_to_int: int(a) (mode exact): truncated toward zero; undefined outside the int range (GLSL).
// Algorithm: ex_trunc_magnitude, then the sign
// Source: IEEE 754-2019, 5.8; GLSL ES 3.20, 2019, 5.4.1 (conversion truncates)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$I ex_to_int($DF a) {
  uvec2 w = ex_bits(a);
  uint m = ex_trunc_magnitude(w).x;
  return w.y >= 0x80000000u ? -int(m) : int(m);
}

// ex_to_uint: uint(a) (mode exact): truncated toward zero; undefined outside the uint range (GLSL).
// Algorithm: ex_trunc_magnitude
// Source: IEEE 754-2019, 5.8; GLSL ES 3.20, 2019, 5.4.1 (conversion truncates)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$U ex_to_uint($DF a) {
  return ex_trunc_magnitude(ex_bits(a)).x;
}

// ex_from_bool: double(b) (mode exact): 1.0 or 0.0.
// Algorithm: select of the patterns of 1.0 and 0.0
// Source: GLSL ES 3.20, 2019, 5.4.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_from_bool($B b) {
  if (b) return df_double(0x3FF00000u, 0u);  // no struct ternary: WebGL 2.0 forbids it
  return df_double(0u, 0u);
}

// ex_to_bool: bool(a) (mode exact): a != 0.0 (true for NaN).
// Algorithm: not ex_eq_bits(a, 0)
// Source: GLSL ES 3.20, 2019, 5.4.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_to_bool($DF a) {
  return !ex_eq_bits(ex_bits(a), uvec2(0u));
}

// ex_lt: a < b (mode exact).
// Algorithm: ex_lt_bits
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_lt($DF a, $DF b) {
  return ex_lt_bits(ex_bits(a), ex_bits(b));
}

// ex_le: a <= b (mode exact).
// Algorithm: ex_lt_bits or ex_eq_bits
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_le($DF a, $DF b) {
  return ex_lt_bits(ex_bits(a), ex_bits(b)) || ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_gt: a > b (mode exact).
// Algorithm: ex_lt_bits(b, a)
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_gt($DF a, $DF b) {
  return ex_lt_bits(ex_bits(b), ex_bits(a));
}

// ex_ge: a >= b (mode exact).
// Algorithm: ex_lt_bits(b, a) or ex_eq_bits
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_ge($DF a, $DF b) {
  return ex_lt_bits(ex_bits(b), ex_bits(a)) || ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_equal_components: equal(a, b) per component (mode exact).
// Algorithm: ex_eq_bits per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_equal_components($DF a, $DF b) {
  return ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_not_equal_components: notEqual(a, b) per component (mode exact): true with a NaN.
// Algorithm: not ex_eq_bits per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_not_equal_components($DF a, $DF b) {
  return !ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_less_than: lessThan(a, b) (mode exact).
// Algorithm: ex_lt_bits per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_less_than($DF a, $DF b) {
  return ex_lt_bits(ex_bits(a), ex_bits(b));
}

// ex_less_than_equal: lessThanEqual(a, b) (mode exact).
// Algorithm: ex_lt_bits or ex_eq_bits per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_less_than_equal($DF a, $DF b) {
  return ex_lt_bits(ex_bits(a), ex_bits(b)) || ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_greater_than: greaterThan(a, b) (mode exact).
// Algorithm: ex_lt_bits(b, a) per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_greater_than($DF a, $DF b) {
  return ex_lt_bits(ex_bits(b), ex_bits(a));
}

// ex_greater_than_equal: greaterThanEqual(a, b) (mode exact).
// Algorithm: ex_lt_bits(b, a) or ex_eq_bits per component
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_greater_than_equal($DF a, $DF b) {
  return ex_lt_bits(ex_bits(b), ex_bits(a)) || ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_trunc: trunc(a) (mode exact).
// Algorithm: ex_round_integral_bits toward zero
// Source: IEEE 754-2019, 5.3.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_trunc($DF a) {
  return ex_from_bits(ex_round_integral_bits(ex_bits(a), 0));
}

// ex_floor: floor(a) (mode exact).
// Algorithm: ex_round_integral_bits toward -Inf
// Source: IEEE 754-2019, 5.3.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_floor($DF a) {
  return ex_from_bits(ex_round_integral_bits(ex_bits(a), 1));
}

// ex_ceil: ceil(a) (mode exact).
// Algorithm: ex_round_integral_bits toward +Inf
// Source: IEEE 754-2019, 5.3.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_ceil($DF a) {
  return ex_from_bits(ex_round_integral_bits(ex_bits(a), 2));
}

// ex_round_even: roundEven(a) (mode exact).
// Algorithm: ex_round_integral_bits to nearest even
// Source: IEEE 754-2019, 5.3.1
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_round_even($DF a) {
  return ex_from_bits(ex_round_integral_bits(ex_bits(a), 3));
}

// ex_round: round(a) (mode exact): halves to even, as native fp64 on Mesa (GLSL leaves the direction to the implementation).
// Algorithm: ex_round_integral_bits to nearest even
// Source: IEEE 754-2019, 5.3.1; GLSL ES 3.20, 2019, 8.3 (round)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_round($DF a) {
  return ex_from_bits(ex_round_integral_bits(ex_bits(a), 3));
}

// ex_fract: fract(a) = a - floor(a) (mode exact), as GLSL defines it.
// Algorithm: ex_sub(a, ex_floor(a)): one rounding
// Source: GLSL ES 3.20, 2019, 8.3 (fract); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_fract($DF a) {
  return ex_sub(a, ex_floor(a));
}

// ex_mod: mod(a, b) = a - b * floor(a / b) (mode exact), as GLSL defines it, each step rounded.
// Algorithm: ex_div, ex_floor, ex_mul, ex_sub
// Source: GLSL ES 3.20, 2019, 8.3 (mod); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_mod($DF a, $DF b) {
  return ex_sub(a, ex_mul(b, ex_floor(ex_div(a, b))));
}

// ex_min: min(a, b) (mode exact): the other operand when one is NaN (IEEE minNum, as native fp64 on lavapipe gives; GLSL leaves it undefined), else a < b ? a : b.
// Algorithm: ex_lt_bits and select
// Source: GLSL ES 3.20, 2019, 8.3 (min); IEEE 754-2008, 5.3.1 (minNum)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_min($DF a, $DF b) {
  if (ex_is_nan(ex_bits(a))) return b;
  if (ex_is_nan(ex_bits(b))) return a;
  if (ex_lt_bits(ex_bits(a), ex_bits(b))) return a;
  return b;
}

// ex_max: max(a, b) (mode exact): the other operand when one is NaN (IEEE maxNum, as native fp64 on lavapipe gives), else a > b ? a : b.
// Algorithm: ex_lt_bits and select
// Source: GLSL ES 3.20, 2019, 8.3 (max); IEEE 754-2008, 5.3.1 (maxNum)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_max($DF a, $DF b) {
  if (ex_is_nan(ex_bits(a))) return b;
  if (ex_is_nan(ex_bits(b))) return a;
  if (ex_lt_bits(ex_bits(b), ex_bits(a))) return a;
  return b;
}

// ex_clamp: clamp(x, lo, hi) = min(max(x, lo), hi) (mode exact).
// Algorithm: ex_max then ex_min
// Source: GLSL ES 3.20, 2019, 8.3 (clamp)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_clamp($DF x, $DF lo, $DF hi) {
  return ex_min(ex_max(x, lo), hi);
}

// ex_sign: sign(a) (mode exact): 1.0, -1.0, else +0 (for -0 and NaN too, as native fp64 on lavapipe gives).
// Algorithm: two ex_lt_bits against 0
// Source: GLSL ES 3.20, 2019, 8.3 (sign)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_sign($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_lt_bits(uvec2(0u), w)) return df_double(0x3FF00000u, 0u);
  if (ex_lt_bits(w, uvec2(0u))) return df_double(0xBFF00000u, 0u);
  return df_double(0u, 0u);
}

// ex_isnan: isnan(a) (mode exact).
// Algorithm: ex_is_nan
// Source: IEEE 754-2019, 5.7.2
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_isnan($DF a) {
  return ex_is_nan(ex_bits(a));
}

// ex_isinf: isinf(a) (mode exact).
// Algorithm: exponent all ones, significand zero
// Source: IEEE 754-2019, 5.7.2
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$B ex_isinf($DF a) {
  return (a.hi & 0x7FFFFFFFu) == 0x7FF00000u && a.lo == 0u;
}

// ex_equal: a == b (mode exact): every component equal; false with a NaN.
// Algorithm: ex_eq_bits
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_equal(df_double a, df_double b) {
  return ex_eq_bits(ex_bits(a), ex_bits(b));
}

// ex_equal: a == b (mode exact): every component equal; false with a NaN.
// Algorithm: all(ex_equal_components)
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @min-es 300
bool ex_equal($DF a, $DF b) {
  return all(ex_equal_components(a, b));
}

// ex_not_equal: a != b (mode exact): some component differs; true with a NaN.
// Algorithm: not ex_equal
// Source: IEEE 754-2019, 5.11
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @min-es 300
bool ex_not_equal($DF a, $DF b) {
  return !ex_equal(a, b);
}

// ex_pack_double2x32: packDouble2x32(v) (mode exact): v is already the pattern (v.x low word, v.y high word).
// Algorithm: ex_from_bits
// Source: GLSL 4.60 specification, 2017, 8.4 (packDouble2x32)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_pack_double2x32(uvec2 v) {
  return ex_from_bits(v);
}

// ex_unpack_double2x32: unpackDouble2x32(a) (mode exact): the pattern as uvec2(low word, high word).
// Algorithm: ex_bits
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_unpack_double2x32(df_double a) {
  return ex_bits(a);
}

// ex_to_ff: the float-float pair nearest a binary64 pattern: hi = float(a), lo = float(a - hi); (float(a), 0) when hi is not finite (|a| > FLT_MAX, Inf, NaN).
// Algorithm: two roundings to float (ex_to_float_bits); a - hi is exact in binary64. hi + lo keeps 48 of a's 53 bits; ex_ff_residual gives the rest
// Source: Dekker, Numer. Math. 18, 1971 (double-word representation); IEEE 754-2019, 5.4.2
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
ff_double ex_to_ff(uvec2 a) {
  uint h = ex_to_float_bits(a);
  if ((h & 0x7F800000u) == 0x7F800000u) return ff_double(uintBitsToFloat(h), 0.0);
  uvec2 rest = ex_sub_bits(a, ex_from_float_bits(uintBitsToFloat(h)));
  return ff_double(uintBitsToFloat(h), uintBitsToFloat(ex_to_float_bits(rest)));
}

// ex_ff_residual: a - (f.hi + f.lo), the part of a binary64 its float-float pair f = ex_to_ff(a) lost, rounded to float (0 when f is not finite).
// Algorithm: two exact binary64 subtractions (a - hi, then the rounding error of lo), rounded once to float
// Source: IEEE 754-2019, 5.4.1; Boldo, Daumas, ARITH-16, 2003 (the error of a rounding is representable)
// Bound: 0.5 ulp (correctly rounded, of the residual)
// Flops: 0 (integer arithmetic)
// @min-es 300
float ex_ff_residual(uvec2 a, ff_double f) {
  if ((floatBitsToUint(f.hi) & 0x7F800000u) == 0x7F800000u) return 0.0;
  uvec2 rest = ex_sub_bits(ex_sub_bits(a, ex_from_float_bits(f.hi)), ex_from_float_bits(f.lo));
  return uintBitsToFloat(ex_to_float_bits(rest));
}

// ex_from_ff: the binary64 nearest f.hi + f.lo (one rounding); a non-finite hi, or lo = 0 (which keeps the sign of a zero hi), gives float(hi) exactly.
// Algorithm: both words widened exactly (ex_from_float_bits), then ex_add_bits
// Source: IEEE 754-2019, 5.4.1, 5.4.2
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_from_ff(ff_double f) {
  uvec2 h = ex_from_float_bits(f.hi);
  if ((floatBitsToUint(f.hi) & 0x7F800000u) == 0x7F800000u || f.lo == 0.0) return h;
  return ex_add_bits(h, ex_from_float_bits(f.lo));
}

// ex_ff_corrected: y + c for a float correction c (the first-order term f'(x) * residual), skipped when c is 0 or not finite or y is not finite.
// Algorithm: DWPlusFP (df_add_f) when it applies, then ex_from_ff: one rounding to binary64
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 2.2 (DWPlusFP, 2u^2)
// Bound: 2u^2 + 0.5 ulp of binary64
// Flops: 11 (df_add_f)
// @min-es 300
// @uses df_add_f:1
uvec2 ex_ff_corrected(ff_double y, float c) {
  bool finite = (floatBitsToUint(y.hi) & 0x7F800000u) != 0x7F800000u && (floatBitsToUint(c) & 0x7F800000u) != 0x7F800000u;
  if (!finite || c == 0.0) return ex_from_ff(y);
  return ex_from_ff(df_add_f(y, c));
}

// ex_exp: exp(a) (mode exact, doublet extension) through float-float: df_exp of the float-float pair of a, plus y * residual, rounded once.
// Algorithm: ex_to_ff; df_exp (rules/transcendental.glsl); first-order correction exp(x + d) = y (1 + d); ex_ff_corrected
// Source: Cody, Waite, 1980 (df_exp); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_exp's bound (10u^2) + 2u^2 + 2^-53, for -70.7 <= a <= 88.72 (float's range: above, +Inf; below, lo turns subnormal, then 0)
// Flops: 570 (df_exp, df_add_f; integer conversions besides)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_exp:1
$DF ex_exp($DF a) {
  uvec2 w = ex_bits(a);
  ff_double x = ex_to_ff(w);
  ff_double y = df_exp(x);
  return ex_from_bits(ex_ff_corrected(y, y.hi * ex_ff_residual(w, x)));
}

// ex_exp2: exp2(a) (mode exact, doublet extension) through float-float, with the first-order correction y ln2 * residual.
// Algorithm: ex_to_ff; df_exp2; exp2(x + d) = y (1 + d ln2); ex_ff_corrected
// Source: Cody, Waite, 1980 (df_exp2); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_exp2's bound (12u^2) + 2u^2 + 2^-53, for -102 <= a < 128 (float's range)
// Flops: 560 (df_exp2, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_exp2:1
$DF ex_exp2($DF a) {
  uvec2 w = ex_bits(a);
  ff_double x = ex_to_ff(w);
  ff_double y = df_exp2(x);
  return ex_from_bits(ex_ff_corrected(y, y.hi * (ex_ff_residual(w, x) * 0.693147182)));
}

// ex_log_scaled: a positive finite a outside [2^-90, 2^90] written m * 2^e, m in [1, 2) (subnormals normalized first); elsewhere m = a, e = 0.
// Algorithm: exponent field replaced by the bias (1023), the unbiased exponent returned in e
// Source: IEEE 754-2019, 5.3.3 (logB, scaleB)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_log_scaled(uvec2 a, out int e) {
  e = 0;
  int field = int((a.y >> 20) & 0x7FFu);
  if (a.y >= 0x80000000u || field >= 0x7FF || (a.x | (a.y & 0x7FFFFFFFu)) == 0u || (field >= 933 && field <= 1113)) return a;
  int x;
  uvec2 m = ex_normalize_sig(a, x);
  e = x - 1023;
  return uvec2(m.x, (m.y & 0x000FFFFFu) | 0x3FF00000u);
}

// ex_log: log(a) (mode exact, doublet extension) through float-float, every positive finite binary64 (outside [2^-90, 2^90] as log m + e ln2), with the first-order correction residual / x.
// Algorithm: ex_log_scaled; ex_to_ff; df_log; + residual / m.hi; + e * ln2 (a float-float ln2, DWTimesFP, DWPlusDW); ex_from_ff
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_log); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_log's bound (28u^2) + 2u^2 + 2^-53 for every positive finite a; log(0) = -Inf, log(a < 0) = NaN, log(+Inf) = +Inf
// Flops: 510 (df_log, df_add_f; df_mul_f and df_add beyond [2^-90, 2^90])
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_log:1 df_add_f:1 df_mul_f:1 df_add:1
$DF ex_log($DF a) {
  int e;
  uvec2 w = ex_log_scaled(ex_bits(a), e);
  ff_double x = ex_to_ff(w);
  ff_double y = df_log(x);
  float d = ex_ff_residual(w, x);
  if (d != 0.0 && x.hi != 0.0) y = df_add_f(y, d / x.hi);
  if (e != 0) y = df_add(y, df_mul_f(ff_double(0.693147182, -1.90465421e-09), float(e)));
  return ex_from_bits(ex_from_ff(y));
}

// ex_log2: log2(a) (mode exact, doublet extension) through float-float, every positive finite binary64 (outside [2^-90, 2^90] as log2 m + e), with the first-order correction residual / (x ln2).
// Algorithm: ex_log_scaled; ex_to_ff; df_log2; + residual / (m.hi ln2); + e (exact float); ex_from_ff
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_log2); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_log2's bound (37u^2) + 2u^2 + 2^-53 for every positive finite a
// Flops: 520 (df_log2, df_add_f twice)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_log2:1 df_add_f:1
$DF ex_log2($DF a) {
  int e;
  uvec2 w = ex_log_scaled(ex_bits(a), e);
  ff_double x = ex_to_ff(w);
  ff_double y = df_log2(x);
  float d = ex_ff_residual(w, x);
  if (d != 0.0 && x.hi != 0.0) y = df_add_f(y, d / x.hi * 1.44269502);
  if (e != 0) y = df_add_f(y, float(e));
  return ex_from_bits(ex_from_ff(y));
}

// ex_pow: pow(a, b) (mode exact, doublet extension) through float-float, with the first-order corrections p (b/a da + log(a) db).
// Algorithm: ex_to_ff of both; df_pow; ex_ff_corrected with the float partial derivatives
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_pow = exp(y log x)); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_pow's bound (40u^2 + 31u^2 |b log a|) + 2u^2 + 2^-53, for a, b and the result inside float's range
// Flops: 1040 (df_pow, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_pow:1
$DF ex_pow($DF a, $DF b) {
  uvec2 wa = ex_bits(a), wb = ex_bits(b);
  ff_double x = ex_to_ff(wa), y = ex_to_ff(wb);
  ff_double p = df_pow(x, y);
  float dx = ex_ff_residual(wa, x), dy = ex_ff_residual(wb, y);
  float c = 0.0;
  if (dx != 0.0 && x.hi != 0.0) c += y.hi * (dx / x.hi);
  if (dy != 0.0 && x.hi > 0.0) c += log(x.hi) * dy;
  return ex_from_bits(ex_ff_corrected(p, p.hi * c));
}

// ex_below_2m28: |a| < 2^-28 (zeros and subnormals included): there sin, tan, asin, atan, sinh and tanh of a round to a itself (a(1 +- a^2/3) is within half an ulp), which the float-float path could not give below float's range.
// Algorithm: high word of |a| against that of 2^-28
// Source: Muller, Elementary Functions, 3rd ed., 2016, section 10.1 (f(x) = x for tiny x); IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_below_2m28(uvec2 a) {
  return (a.y & 0x7FFFFFFFu) < 0x3E300000u;
}

// ex_trig_reduce: the binary64 a reduced by pi/2: a = r + k pi/2, |r| <= pi/4 about, r as float-float: df_trig_reduce on a's float-float pair, then the residual (the part of a the pair lost, at most 5 bits, exact in float) added to r.
// Algorithm: ex_to_ff; df_trig_reduce (Cody-Waite, four-word pi/2); r + residual (DWPlusFP)
// Source: Cody, Waite, 1980; Muller, Elementary Functions, 3rd ed., 2016, section 11.2; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_trig_reduce's bound (6u^2 * abs(r) + abs(a) * 2^-96 absolute) + 2u^2 * abs(r)
// Flops: 280 (df_trig_reduce, df_add_f)
// Range: |a| < 2^40; without `precise` (mode exact has no guard) Mesa costs bits beyond 2^20 (docs/modes.md).
// @min-es 300
// @uses df_trig_reduce:1 df_add_f:1
ff_double ex_trig_reduce(uvec2 a, out int k) {
  ff_double x = ex_to_ff(a);
  ff_double r = df_trig_reduce(x, k);
  float d = ex_ff_residual(a, x);
  if (d != 0.0) r = df_add_f(r, d);
  return r;
}

// ex_trig_outside: true when sin, cos and tan of a are NaN here (a NaN a passed on, quiet; else the default NaN): |a| >= 2^40, Inf or NaN (float-float's reduction ends at 2^40).
// Algorithm: high word of |a| against that of 2^40
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
bool ex_trig_outside(uvec2 a) {
  return (a.y & 0x7FFFFFFFu) >= 0x42700000u;
}

// ex_sin: sin(a) (mode exact, doublet extension) through float-float: a reduced by pi/2 (ex_trig_reduce, the residual included), the quadrant's kernel, one rounding. sin(+-0) = +-0; |a| >= 2^40: NaN.
// Algorithm: ex_trig_reduce; df_sin_quadrant at quadrant k; ex_from_ff
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: df_sin's bound (20u^2 relative plus abs(a) * 2^-96 absolute) + 2u^2 + 2^-53
// Flops: 600 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_sin_quadrant:1
$DF ex_sin($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_trig_outside(w)) return ex_from_bits(ex_is_nan(w) ? ex_pick_nan(w, w) : uvec2(0u, 0xFFF80000u));
  if (ex_below_2m28(w)) return a;
  int k;
  ff_double r = ex_trig_reduce(w, k);
  return ex_from_bits(ex_from_ff(df_sin_quadrant(r, k)));
}

// ex_cos: cos(a) (mode exact, doublet extension) = sin(a + pi/2) through float-float. |a| >= 2^40: NaN.
// Algorithm: ex_trig_reduce; df_sin_quadrant at quadrant k + 1; ex_from_ff
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001
// Bound: df_cos's bound (20u^2 relative plus abs(a) * 2^-96 absolute) + 2u^2 + 2^-53
// Flops: 600 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_sin_quadrant:1
$DF ex_cos($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_trig_outside(w)) return ex_from_bits(ex_is_nan(w) ? ex_pick_nan(w, w) : uvec2(0u, 0xFFF80000u));
  int k;
  ff_double r = ex_trig_reduce(w, k);
  return ex_from_bits(ex_from_ff(df_sin_quadrant(r, (k + 1) & 3)));
}

// ex_tan: tan(a) (mode exact, doublet extension) = sin / cos of the reduced argument through float-float (the residual included before the kernels, so no first-order step near the poles). tan(+-0) = +-0; |a| >= 2^40: NaN.
// Algorithm: ex_trig_reduce; df_sin_quadrant at k and k + 1 (sin r / cos r, or -cos r / sin r); DWDivDW2; ex_from_ff
// Source: Cody, Waite, 1980; Hida, Li, Bailey, ARITH-15, 2001; Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: 40u^2 (relative) plus abs(a) * 2^-96 absolute times (1 + tan(a)^2), + 2u^2 + 2^-53 (df_tan's bound: the same kernels and division)
// Flops: 960 (on the path taken)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_sin_quadrant:1 df_div:1
$DF ex_tan($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_trig_outside(w)) return ex_from_bits(ex_is_nan(w) ? ex_pick_nan(w, w) : uvec2(0u, 0xFFF80000u));
  if (ex_below_2m28(w)) return a;
  int k;
  ff_double r = ex_trig_reduce(w, k);
  ff_double t = df_div(df_sin_quadrant(r, k), df_sin_quadrant(r, (k + 1) & 3));
  return ex_from_bits(ex_from_ff(t));
}

// ex_asin_slope: 1 / sqrt(1 - x^2) in float from the float-float x (|x| <= 1), 0 where it is not finite: the derivative asin' for the first-order correction.
// Algorithm: (1 - hi - lo)(1 + hi + lo) in float (1 - hi exact by Sterbenz), inversesqrt
// Source: Sterbenz, Floating-Point Computation, 1974 (exact subtraction)
// Bound: float accuracy (a few 2^-24 relative): it scales a correction below 2^-48 of the result, so its error stays below u^2 of the result
// Flops: 7
// @min-es 300
float ex_asin_slope(ff_double x) {
  float s = ((1.0 - abs(x.hi)) - sign(x.hi) * x.lo) * ((1.0 + abs(x.hi)) + sign(x.hi) * x.lo);
  if (!(s > 0.0)) return 0.0;
  return inversesqrt(s);
}

// ex_asin: asin(a) (mode exact, doublet extension) through float-float, with the first-order correction residual / sqrt(1 - x^2).
// Algorithm: ex_to_ff; df_asin; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_asin = atan(x, sqrt((1-x)(1+x)))); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_asin's bound (75u^2) + 2u^2 + 2^-53, |a| <= 1
// Flops: 470 (df_asin, df_add_f, ex_asin_slope)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_asin:1
$DF ex_asin($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_below_2m28(w)) return a;
  ff_double x = ex_to_ff(w);
  ff_double y = df_asin(x);
  return ex_from_bits(ex_ff_corrected(y, ex_asin_slope(x) * ex_ff_residual(w, x)));
}

// ex_acos: acos(a) (mode exact, doublet extension) through float-float, with the first-order correction -residual / sqrt(1 - x^2).
// Algorithm: ex_to_ff; df_acos; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_acos); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_acos's bound (75u^2) + 2u^2 + 2^-53, |a| <= 1
// Flops: 470 (df_acos, df_add_f, ex_asin_slope)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_acos:1
$DF ex_acos($DF a) {
  uvec2 w = ex_bits(a);
  ff_double x = ex_to_ff(w);
  ff_double y = df_acos(x);
  return ex_from_bits(ex_ff_corrected(y, -ex_asin_slope(x) * ex_ff_residual(w, x)));
}

// ex_atan: atan(a) (mode exact, doublet extension) through float-float, with the first-order correction residual / (1 + x^2).
// Algorithm: ex_to_ff; df_atan; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_atan); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_atan's bound (70u^2) + 2u^2 + 2^-53; |a| > FLT_MAX gives +-pi/2 rounded
// Flops: 635 (df_atan, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_atan:1
$DF ex_atan($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_below_2m28(w)) return a;
  ff_double x = ex_to_ff(w);
  ff_double y = df_atan(x);
  return ex_from_bits(ex_ff_corrected(y, ex_ff_residual(w, x) / (1.0 + x.hi * x.hi)));
}

// ex_atan2_scale: the power of two that brings the larger exponent of y and x to about 0 when it is outside 2^+-30 (atan2 is invariant to scaling both), so that the smaller one keeps float-float's full precision; 1 otherwise (and for Inf and NaN).
// Algorithm: 2^(1023 - max exponent field) as a pattern; multiplying by it is exact unless the smaller operand becomes subnormal (then one rounding; ex_atan2 has already answered a ratio below 2^-28 by a division, so the loss is far below the result's ulp)
// Source: IEEE 754-2019, 5.3.3 (scaleB); C99 Annex F.9.1.4 (atan2)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_atan2_scale(uvec2 y, uvec2 x) {
  int e = max(int((y.y >> 20) & 0x7FFu), int((x.y >> 20) & 0x7FFu));
  if (e == 0x7FF || (e >= 993 && e <= 1053)) return uvec2(0u, 0x3FF00000u);
  return uvec2(0u, uint(2046 - e) << 20);
}

// ex_atan2: atan(a, b) = the angle of (b, a) (mode exact, doublet extension) through float-float, every finite a, b (both scaled by a power of two into float's range; a / b rounded once when b > 0 and |a / b| < 2^-28), with the first-order correction (b da - a db) / (a^2 + b^2) (in float, scaled by the larger magnitude).
// Algorithm: ex_div_bits for a tiny positive-x ratio (atan t rounds to t); else both scaled by ex_atan2_scale, ex_to_ff of both, df_atan2, ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_atan2); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_atan2's bound (70u^2) + 2u^2 + 2^-53
// Flops: 650 (df_atan2, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_atan2:1
$DF ex_atan2($DF a, $DF b) {
  uvec2 wy = ex_bits(a), wx = ex_bits(b);
  int fy = max(int((wy.y >> 20) & 0x7FFu), 1), fx = int((wx.y >> 20) & 0x7FFu);
  if (wx.y < 0x80000000u && fx >= 1 && fx < 0x7FF && fy + 29 < fx) return ex_from_bits(ex_div_bits(wy, wx));
  uvec2 scale = ex_atan2_scale(wy, wx);
  wy = ex_mul_bits(wy, scale);
  wx = ex_mul_bits(wx, scale);
  ff_double y = ex_to_ff(wy), x = ex_to_ff(wx);
  ff_double t = df_atan2(y, x);
  float dy = ex_ff_residual(wy, y), dx = ex_ff_residual(wx, x);
  float m = max(abs(x.hi), abs(y.hi));
  float c = 0.0;
  if ((dx != 0.0 || dy != 0.0) && m > 0.0) {
    float xs = x.hi / m, ys = y.hi / m;
    c = (xs * dy - ys * dx) / (m * (xs * xs + ys * ys));
  }
  return ex_from_bits(ex_ff_corrected(t, c));
}

// ex_sinh: sinh(a) (mode exact, doublet extension) through float-float, with the first-order correction cosh(a) * residual, cosh = sqrt(1 + y^2).
// Algorithm: ex_to_ff; df_sinh; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_sinh); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_sinh's bound (50u^2) + 2u^2 + 2^-53, |a| <= 88.72 (beyond: +-Inf, float's range)
// Flops: 600 (df_sinh, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_sinh:1
$DF ex_sinh($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_below_2m28(w)) return a;
  ff_double x = ex_to_ff(w);
  ff_double y = df_sinh(x);
  float slope = abs(y.hi) > 1e18 ? abs(y.hi) : sqrt(1.0 + y.hi * y.hi);
  return ex_from_bits(ex_ff_corrected(y, slope * ex_ff_residual(w, x)));
}

// ex_cosh: cosh(a) (mode exact, doublet extension) through float-float, with the first-order correction sinh(a) * residual, |sinh| = sqrt(y^2 - 1).
// Algorithm: ex_to_ff; df_cosh; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_cosh); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_cosh's bound (20u^2) + 2u^2 + 2^-53, |a| <= 88.72 (beyond: +Inf, float's range)
// Flops: 580 (df_cosh, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_cosh:1
$DF ex_cosh($DF a) {
  uvec2 w = ex_bits(a);
  ff_double x = ex_to_ff(w);
  ff_double y = df_cosh(x);
  float slope = abs(y.hi) > 1e18 ? y.hi : sqrt(max(y.hi * y.hi - 1.0, 0.0));
  return ex_from_bits(ex_ff_corrected(y, sign(x.hi) * slope * ex_ff_residual(w, x)));
}

// ex_tanh: tanh(a) (mode exact, doublet extension) through float-float, with the first-order correction (1 - y^2) * residual.
// Algorithm: ex_to_ff; df_tanh; ex_ff_corrected
// Source: Muller, Elementary Functions, 3rd ed., 2016 (df_tanh); Joldes, Muller, Popescu, ACM TOMS 44(2), 2017
// Bound: df_tanh's bound (50u^2) + 2u^2 + 2^-53; every a (+-1 beyond |a| > 22)
// Flops: 600 (df_tanh, df_add_f)
// @widths 1 2 3 4
// @per-component
// @min-es 300
// @uses df_tanh:1
$DF ex_tanh($DF a) {
  uvec2 w = ex_bits(a);
  if (ex_below_2m28(w)) return a;
  ff_double x = ex_to_ff(w);
  ff_double y = df_tanh(x);
  return ex_from_bits(ex_ff_corrected(y, (1.0 - y.hi * y.hi) * ex_ff_residual(w, x)));
}

// ex_mul_first: a * b with a's NaN passed on first, as native's built-in sequences (dot, cross, smoothstep...) order their products (measured by tests/exact/exact_builtins_test.cpp).
// Algorithm: ex_mul_bits(b, a): multiplication is commutative in value; only the NaN choice changes
// Source: IEEE 754-2019, 5.4.1, 6.2.3
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_mul_first(uvec2 a, uvec2 b) {
  return ex_mul_bits(b, a);
}

// ex_add_first: a + b with a's NaN passed on first (the order of native's dot-product chains).
// Algorithm: ex_add_bits(b, a): addition is commutative in value, signed zeros included; only the NaN choice changes
// Source: IEEE 754-2019, 5.4.1, 6.2.3, 6.3
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_add_first(uvec2 a, uvec2 b) {
  return ex_add_bits(b, a);
}

// ex_sub_last: a - b with b's NaN passed on first (the last subtraction of native's reflect and refract).
// Algorithm: NaN operands: ex_pick_nan(b, a); else ex_sub_bits
// Source: IEEE 754-2019, 5.4.1, 6.2.3
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_sub_last(uvec2 a, uvec2 b) {
  bool nan = ex_either_nan(a, b);
  return ex_sel64(nan, ex_pick_nan(b, a), ex_sub_bits(a, b));
}

// ex_inversesqrt: inversesqrt(a) (mode exact) as native fp64 on lavapipe computes it: 1 / sqrt(a), two roundings.
// Algorithm: ex_div_bits(1, ex_sqrt_bits(a))
// Source: GLSL ES 3.20, 2019, 8.2 (inversesqrt); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (two roundings)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_inversesqrt($DF a) {
  return ex_from_bits(ex_div_bits(uvec2(0u, 0x3FF00000u), ex_sqrt_bits(ex_bits(a))));
}

// ex_mix: mix(x, y, a) (mode exact) as native fp64 on lavapipe computes it: fma(y, a, x * (1 - a)), its fma rounding twice (ex_fma_bits).
// Algorithm: ex_fma_bits(y, a, ex_mul_bits(x, ex_sub_bits(1, a))): x(1 - a) + ya, every step rounded
// Source: GLSL ES 3.20, 2019, 8.3 (mix = x(1 - a) + ya); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (four roundings)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_mix($DF x, $DF y, $DF a) {
  uvec2 wa = ex_bits(a);
  uvec2 rest = ex_mul_bits(ex_bits(x), ex_sub_bits(uvec2(0u, 0x3FF00000u), wa));
  return ex_from_bits(ex_fma_bits(ex_bits(y), wa, rest));
}

// ex_mix_bool: mix(x, y, a) with a boolean a (mode exact): y where a is true, else x.
// Algorithm: selection per component
// Source: GLSL ES 3.20, 2019, 8.3 (mix with a bool selector)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_mix_bool($DF x, $DF y, $B a) {
  if (a) return y;
  return x;
}

// ex_step: step(edge, x) (mode exact): 0 when x < edge, else 1 (1 with a NaN, as native's x < edge test gives).
// Algorithm: ex_lt_bits(x, edge) and select
// Source: GLSL ES 3.20, 2019, 8.3 (step)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_step($DF edge, $DF x) {
  if (ex_lt_bits(ex_bits(x), ex_bits(edge))) return df_double(0u, 0u);
  return df_double(0x3FF00000u, 0u);
}

// ex_smoothstep: smoothstep(e0, e1, x) (mode exact) as native fp64 on lavapipe computes it: t = clamp((x - e0) / (e1 - e0), 0, 1) (a NaN quotient gives 0), then t * (t * (3 - 2t)), every step rounded.
// Algorithm: ex_sub_bits, ex_div_bits, min/max with the non-NaN operand (as ex_min/ex_max), ex_mul_first and ex_sub_bits in native's order
// Source: GLSL ES 3.20, 2019, 8.3 (smoothstep); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (seven roundings)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_smoothstep($DF e0, $DF e1, $DF x) {
  uvec2 w0 = ex_bits(e0);
  uvec2 q = ex_div_bits(ex_sub_bits(ex_bits(x), w0), ex_sub_bits(ex_bits(e1), w0));
  uvec2 one = uvec2(0u, 0x3FF00000u);
  uvec2 t = q;
  if (ex_is_nan(q) || ex_lt_bits(q, uvec2(0u))) t = uvec2(0u);
  if (ex_lt_bits(one, t)) t = one;
  uvec2 s = ex_sub_bits(uvec2(0u, 0x40080000u), ex_mul_first(uvec2(0u, 0x40000000u), t));
  return ex_from_bits(ex_mul_first(t, ex_mul_first(t, s)));
}

// ex_pow2_field: 2^h built from its exponent field, for -1023 <= h <= 1023 (h = -1023 gives 0, not the subnormal 2^-1023: native's power of two has a normal exponent field only).
// Algorithm: exponent field h + 1023, significand 0
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_pow2_field(int h) {
  if (h + 1023 <= 0) return uvec2(0u);
  return uvec2(0u, uint(h + 1023) << 20);
}

// ex_ldexp: ldexp(a, e) (mode exact) as native fp64 on lavapipe computes it: e clamped to [-2046, 2046], then a * 2^(e >> 1) * 2^(e - (e >> 1)), each product rounded (so a subnormal result can be rounded twice, and a factor 2^-1023 is 0).
// Algorithm: clamp; two ex_mul_bits by powers of two built from exponent fields (ex_pow2_field)
// Source: GLSL ES 3.20, 2019, 8.3 (ldexp: undefined when the result overflows); IEEE 754-2019, 5.3.3 (scaleB); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (two roundings; exact unless the result is subnormal)
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @per-component
// @min-es 300
$DF ex_ldexp($DF a, $I e) {
  int c = clamp(e, -2046, 2046);
  int h = c >> 1;
  return ex_from_bits(ex_mul_bits(ex_mul_bits(ex_bits(a), ex_pow2_field(h)), ex_pow2_field(c - h)));
}

// ex_frexp: frexp(a, e) (mode exact) as native fp64 on lavapipe computes it: the exponent field replaced by 1022 (significand bits kept, so a subnormal gives a significand below 0.5), e = field - 1022; +-0 gives (+-0, 0); Inf and NaN keep their bits with e = 1025.
// Algorithm: exponent field arithmetic on the pattern
// Source: GLSL ES 3.20, 2019, 8.3 (frexp: undefined for Inf and NaN); IEEE 754-2019, 5.3.3 (logB); measured by tests/exact/exact_builtins_test.cpp
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_frexp(df_double a, out int e) {
  uint absHi = a.hi & 0x7FFFFFFFu;
  if ((absHi | a.lo) == 0u) {
    e = 0;
    return a;
  }
  e = int(absHi >> 20) - 1022;
  if (absHi >= 0x7FF00000u) return a;
  return df_double((a.hi & 0x800FFFFFu) | 0x3FE00000u, a.lo);
}

// ex_frexp: frexp(a, e) on a vector (mode exact): ex_frexp per component.
// Algorithm: ex_frexp per component
// Source: GLSL ES 3.20, 2019, 8.3 (frexp)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @min-es 300
// @uses ex_frexp:1
$DF ex_frexp($DF a, out $I e) {
  $DF m = a;
  for (int kk = 0; kk < $W; ++kk) {
    int k = $W - 1 - kk;  // not the counter: see the file header (loops)
    int ek;
    df_double c = ex_frexp(df_double(a.hi[k], a.lo[k]), ek);
    e[k] = ek;
    m.hi[k] = c.hi;
    m.lo[k] = c.lo;
  }
  return m;
}

// ex_modf_bits: the fraction of a with its integral part in i, as native fp64 on lavapipe computes them: t = trunc(|a|), f = |a| - t (0 for Inf), both negated when a < 0 (so -0 gives +0 and +0; a NaN gives itself quiet with the sign cleared).
// Algorithm: ex_round_integral_bits toward zero on |a|, ex_sub_bits, sign by ex_lt_bits(a, 0)
// Source: GLSL ES 3.20, 2019, 8.3 (modf); IEEE 754-2019, 5.3.1; measured by tests/exact/exact_builtins_test.cpp
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_modf_bits(uvec2 a, out uvec2 i) {
  uvec2 m = uvec2(a.x, a.y & 0x7FFFFFFFu);
  uvec2 t = ex_round_integral_bits(m, 0);
  uvec2 f = (m.y == 0x7FF00000u && m.x == 0u) ? uvec2(0u) : ex_sub_bits(m, t);
  bool negative = ex_lt_bits(a, uvec2(0u));
  i = negative ? ex_neg_bits(t) : t;
  return negative ? ex_neg_bits(f) : f;
}

// ex_modf: modf(a, i) (mode exact): ex_modf_bits per component.
// Algorithm: ex_modf_bits
// Source: GLSL ES 3.20, 2019, 8.3 (modf)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_modf(df_double a, out df_double i) {
  uvec2 w;
  uvec2 f = ex_modf_bits(ex_bits(a), w);
  i = ex_from_bits(w);
  return ex_from_bits(f);
}

// ex_modf: modf(a, i) on a vector (mode exact): ex_modf_bits per component.
// Algorithm: ex_modf_bits per component
// Source: GLSL ES 3.20, 2019, 8.3 (modf)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_modf_bits:1
// @min-es 300
$DF ex_modf($DF a, out $DF i) {
  $DF f = a;
  i = a;
  for (int kk = 0; kk < $W; ++kk) {
    int k = $W - 1 - kk;  // not the counter: see the file header (loops)
    uvec2 w;
    uvec2 r = ex_modf_bits(uvec2(a.lo[k], a.hi[k]), w);
    f.hi[k] = r.y;
    f.lo[k] = r.x;
    i.hi[k] = w.y;
    i.lo[k] = w.x;
  }
  return f;
}

// ex_dot: dot(a, b) of two doubles (mode exact): a * b.
// Algorithm: ex_mul_first
// Source: GLSL ES 3.20, 2019, 8.5 (dot)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_dot(df_double a, df_double b) {
  return ex_from_bits(ex_mul_first(ex_bits(a), ex_bits(b)));
}

// ex_dot: dot(a, b) (mode exact) as native fp64 on lavapipe computes it: ((a.x b.x + a.y b.y) + a.z b.z) + a.w b.w, every product and sum rounded, each operation passing on its first operand's NaN.
// Algorithm: left-to-right chain of ex_mul_first and ex_add_first
// Source: GLSL ES 3.20, 2019, 8.5 (dot); IEEE 754-2019, 5.4.1; measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (2W - 1 roundings)
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_mul_first:1 ex_add_first:1 ex_from_bits:1
// @min-es 300
df_double ex_dot($DF a, $DF b) {
  uvec2 s = ex_mul_first(uvec2(a.lo.x, a.hi.x), uvec2(b.lo.x, b.hi.x));
  for (int k = 1; k < $W; ++k) s = ex_add_first(s, ex_mul_first(uvec2(a.lo[k], a.hi[k]), uvec2(b.lo[k], b.hi[k])));
  return ex_from_bits(s);
}

// ex_length: length(a) of a double (mode exact) as native fp64 on lavapipe computes it: sqrt(a * a) (so it overflows to Inf for |a| > 2^512 and is 0 for |a| < 2^-538, as native).
// Algorithm: ex_sqrt_bits(ex_mul_bits(a, a))
// Source: GLSL ES 3.20, 2019, 8.5 (length); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (two roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_length(df_double a) {
  uvec2 w = ex_bits(a);
  return ex_from_bits(ex_sqrt_bits(ex_mul_bits(w, w)));
}

// ex_length: length(a) (mode exact) as native fp64 on lavapipe computes it: sqrt(dot(a, a)), no scaling.
// Algorithm: ex_sqrt_bits of ex_dot
// Source: GLSL ES 3.20, 2019, 8.5 (length)
// Bound: 0.5 ulp per step (2W roundings)
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_sqrt_bits:1 ex_bits:1 ex_from_bits:1
// @min-es 300
df_double ex_length($DF a) {
  return ex_from_bits(ex_sqrt_bits(ex_bits(ex_dot(a, a))));
}

// ex_distance: distance(a, b) = length(a - b) (mode exact), as native.
// Algorithm: ex_sub then ex_length
// Source: GLSL ES 3.20, 2019, 8.5 (distance)
// Bound: 0.5 ulp per step
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @min-es 300
df_double ex_distance($DF a, $DF b) {
  return ex_length(ex_sub(a, b));
}

// ex_normalize: normalize(a) of a double (mode exact) as native fp64 on lavapipe computes it: a / sqrt(a * a) (NaN for 0, 0 for |a| > 2^512).
// Algorithm: ex_div_bits(a, ex_length)
// Source: GLSL ES 3.20, 2019, 8.5 (normalize); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (three roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_normalize(df_double a) {
  return ex_from_bits(ex_div_bits(ex_bits(a), ex_bits(ex_length(a))));
}

// ex_normalize: normalize(a) (mode exact) as native fp64 on lavapipe computes it: each component divided by length(a).
// Algorithm: ex_length, then ex_div_bits per component
// Source: GLSL ES 3.20, 2019, 8.5 (normalize); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (2W + 1 roundings)
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_bits:1 ex_div_bits:1
// @min-es 300
$DF ex_normalize($DF a) {
  uvec2 len = ex_bits(ex_length(a));
  $DF r = a;
  for (int kk = 0; kk < $W; ++kk) {
    int k = $W - 1 - kk;  // not the counter: see the file header (loops)
    uvec2 q = ex_div_bits(uvec2(a.lo[k], a.hi[k]), len);
    r.hi[k] = q.y;
    r.lo[k] = q.x;
  }
  return r;
}

// ex_cross_component: p * q - r * s, the products and the difference rounded, each passing on its first operand's NaN (one component of native's cross).
// Algorithm: ex_sub_bits(ex_mul_first(p, q), ex_mul_first(r, s))
// Source: GLSL ES 3.20, 2019, 8.5 (cross); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (three roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_cross_component(uvec2 p, uvec2 q, uvec2 r, uvec2 s) {
  return ex_sub_bits(ex_mul_first(p, q), ex_mul_first(r, s));
}

// ex_cross: cross(a, b) (mode exact) as native: (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x), every step rounded.
// Algorithm: ex_cross_component per component
// Source: GLSL ES 3.20, 2019, 8.5 (cross)
// Bound: 0.5 ulp per step (three roundings per component)
// Flops: 0 (integer arithmetic)
// @widths 3
// @uses ex_cross_component:1
// @min-es 300
df_dvec3 ex_cross(df_dvec3 a, df_dvec3 b) {
  df_dvec3 r = a;
  for (int kk = 0; kk < 3; ++kk) {
    int k = 2 - kk;  // not the counter: see the file header (loops)
    int p = (k + 1) % 3, q = (k + 2) % 3;
    uvec2 c = ex_cross_component(uvec2(a.lo[p], a.hi[p]), uvec2(b.lo[q], b.hi[q]), uvec2(a.lo[q], a.hi[q]),
                                 uvec2(b.lo[p], b.hi[p]));
    r.hi[k] = c.y;
    r.lo[k] = c.x;
  }
  return r;
}

// ex_faceforward: faceforward(n, i, nref) (mode exact): n if dot(nref, i) < 0, else -n (a NaN dot gives -n).
// Algorithm: ex_dot, ex_lt_bits against 0, ex_neg
// Source: GLSL ES 3.20, 2019, 8.5 (faceforward)
// Bound: exact
// Flops: 0 (integer arithmetic)
// @widths 1 2 3 4
// @uses ex_bits:1 ex_lt_bits:1
// @min-es 300
$DF ex_faceforward($DF n, $DF i, $DF nref) {
  if (ex_lt_bits(ex_bits(ex_dot(nref, i)), uvec2(0u))) return n;
  return ex_neg(n);
}

// ex_reflect: reflect(i, n) of doubles (mode exact) as native fp64 on lavapipe computes it: i - ((2 i) n) n (Mesa reassociates the constant of i - 2 (n i) n for scalars, so 2 i can overflow), every step rounded; the last subtraction passes on the product's NaN first.
// Algorithm: ex_mul_first three times, ex_sub_last
// Source: GLSL ES 3.20, 2019, 8.5 (reflect); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (four roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_reflect(df_double i, df_double n) {
  uvec2 wi = ex_bits(i), wn = ex_bits(n);
  uvec2 t = ex_mul_first(ex_mul_first(ex_mul_first(uvec2(0u, 0x40000000u), wi), wn), wn);
  return ex_from_bits(ex_sub_last(wi, t));
}

// ex_reflect: reflect(i, n) (mode exact) as native fp64 on lavapipe computes it: i - (2 dot(i, n)) n per component, every step rounded; the last subtraction passes on the product's NaN first.
// Algorithm: ex_dot(i, n), ex_mul_first by 2, then ex_sub_last(i_k, t n_k) per component
// Source: GLSL ES 3.20, 2019, 8.5 (reflect); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_mul_first:1 ex_bits:1 ex_sub_last:1
// @min-es 300
$DF ex_reflect($DF i, $DF n) {
  uvec2 t = ex_mul_first(uvec2(0u, 0x40000000u), ex_bits(ex_dot(i, n)));
  $DF r = i;
  for (int kk = 0; kk < $W; ++kk) {
    int k = $W - 1 - kk;  // not the counter: see the file header (loops)
    uvec2 c = ex_sub_last(uvec2(i.lo[k], i.hi[k]), ex_mul_first(t, uvec2(n.lo[k], n.hi[k])));
    r.hi[k] = c.y;
    r.lo[k] = c.x;
  }
  return r;
}

// ex_refract_k: 1 - eta (eta (1 - d d)) for d = dot(i, n), every step rounded (native's order), the radicand of refract.
// Algorithm: ex_mul_first, ex_sub_bits
// Source: GLSL ES 3.20, 2019, 8.5 (refract); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step (five roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_refract_k(uvec2 d, uvec2 eta) {
  uvec2 one = uvec2(0u, 0x3FF00000u);
  uvec2 inner = ex_sub_bits(one, ex_mul_first(d, d));
  return ex_sub_bits(one, ex_mul_first(eta, ex_mul_first(eta, inner)));
}

// ex_refract_component: eta i - (eta d + sqrt(k)) n for one component, every step rounded (native's order; the last subtraction passes on the product's NaN first).
// Algorithm: ex_mul_first, ex_add_first, ex_sqrt_bits, ex_sub_last
// Source: GLSL ES 3.20, 2019, 8.5 (refract)
// Bound: 0.5 ulp per step
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_refract_component(uvec2 i, uvec2 n, uvec2 eta, uvec2 d, uvec2 k) {
  uvec2 s = ex_add_first(ex_mul_first(eta, d), ex_sqrt_bits(k));
  return ex_sub_last(ex_mul_first(eta, i), ex_mul_first(s, n));
}

// ex_refract: refract(i, n, eta) of doubles (mode exact) as native: k = 1 - eta (eta (1 - d d)), d = i n; 0 if k < 0, else eta i - (eta d + sqrt(k)) n.
// Algorithm: ex_dot, ex_refract_k, ex_refract_component
// Source: GLSL ES 3.20, 2019, 8.5 (refract)
// Bound: 0.5 ulp per step
// Flops: 0 (integer arithmetic)
// @min-es 300
df_double ex_refract(df_double i, df_double n, df_double eta) {
  uvec2 d = ex_bits(ex_dot(i, n)), e = ex_bits(eta);
  uvec2 k = ex_refract_k(d, e);
  if (ex_lt_bits(k, uvec2(0u))) return df_double(0u, 0u);
  return ex_from_bits(ex_refract_component(ex_bits(i), ex_bits(n), e, d, k));
}

// ex_refract: refract(i, n, eta) (mode exact) as native: k = 1 - eta (eta (1 - d d)), d = dot(i, n); 0 if k < 0, else eta i - (eta d + sqrt(k)) n per component, every step rounded.
// Algorithm: ex_dot, ex_refract_k, ex_refract_component per component
// Source: GLSL ES 3.20, 2019, 8.5 (refract); measured by tests/exact/exact_builtins_test.cpp
// Bound: 0.5 ulp per step
// Flops: 0 (integer arithmetic)
// @widths 2 3 4
// @uses ex_bits:1 ex_dot:1,W ex_refract_k:1 ex_lt_bits:1 ex_refract_component:1
// @min-es 300
$DF ex_refract($DF i, $DF n, df_double eta) {
  uvec2 d = ex_bits(ex_dot(i, n)), e = ex_bits(eta);
  uvec2 k = ex_refract_k(d, e);
  $DF r = $DF($U(0u), $U(0u));
  if (ex_lt_bits(k, uvec2(0u))) return r;
  for (int cc = 0; cc < $W; ++cc) {
    int c = $W - 1 - cc;  // not the counter: see the file header (loops)
    uvec2 v = ex_refract_component(uvec2(i.lo[c], i.hi[c]), uvec2(n.lo[c], n.hi[c]), e, d, k);
    r.hi[c] = v.y;
    r.lo[c] = v.x;
  }
  return r;
}

// ex_det2_bits: the determinant of the 2x2 matrix with columns (a, b) and (c, d) as native fp64 on lavapipe computes it: a d - b c, every step rounded (Mesa's spirv_to_nir build_mat2_det).
// Algorithm: ex_mul_first twice, ex_sub_bits
// Source: Mesa 22.3 (2022), src/compiler/spirv/vtn_glsl450.c (build_mat2_det), read, not copied; measured by tests/exact/exact_matrix_test.cpp
// Bound: 0.5 ulp per step (three roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_det2_bits(uvec2 a, uvec2 b, uvec2 c, uvec2 d) {
  return ex_sub_bits(ex_mul_first(a, d), ex_mul_first(b, c));
}

// ex_det3_bits: the determinant of the 3x3 matrix with columns (a, b, c), (d, e, f), (g, h, i) as native fp64 on lavapipe computes it: Mesa's a (e i) - a (f h), ... factored by its optimizer into x = (e i - f h) a, y' = (d i - f g) b, z = (d h - e g) c, then z + (x - y'), every step rounded (the order shows in the last bit, and in the sign of an exactly zero determinant).
// Algorithm: ex_mul_first, ex_sub_bits, ex_sub_last, ex_add_first in the measured order
// Source: Mesa 22.3 (2022), src/compiler/spirv/vtn_glsl450.c (build_mat3_det) and nir_opt_algebraic (inexact factoring), read, not copied; measured by tests/exact/exact_matrix_test.cpp
// Bound: 0.5 ulp per step (14 roundings)
// Flops: 0 (integer arithmetic)
// @min-es 300
uvec2 ex_det3_bits(uvec2 a, uvec2 b, uvec2 c, uvec2 d, uvec2 e, uvec2 f, uvec2 g, uvec2 h, uvec2 i) {
  uvec2 x = ex_mul_first(ex_sub_bits(ex_mul_first(e, i), ex_mul_first(f, h)), a);
  uvec2 y = ex_mul_first(ex_sub_last(ex_mul_first(d, i), ex_mul_first(f, g)), b);
  uvec2 z = ex_mul_first(ex_sub_bits(ex_mul_first(d, h), ex_mul_first(e, g)), c);
  return ex_add_first(z, ex_sub_bits(x, y));
}
