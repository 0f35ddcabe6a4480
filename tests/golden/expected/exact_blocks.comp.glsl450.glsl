#version 450 core
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct df_dvec2 {
  uvec2 hi;
  uvec2 lo;
};
struct df_dvec4 {
  uvec4 hi;
  uvec4 lo;
};
// doublet exact binary64 runtime (mode exact): 32 functions from rules/exact.glsl and rules/rte_exact.glsl, integer arithmetic (no optimizer guard needed)
struct df_double { uint hi; uint lo; };
struct df_dvec3 { uvec3 hi; uvec3 lo; };

// ex_from_bits: the mode-exact double of a binary64 pattern uvec2(low word, high word).
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (packDouble2x32 word order)
// Bound: exact
// Flops: 0
df_double ex_from_bits(uvec2 w) {
  return df_double(w.y, w.x);
}

// ex_sig: the 53-bit integer significand (implicit bit set for normal numbers), as (lo, hi).
// Algorithm: low 52 bits of the pattern, bit 52 set when the exponent field is nonzero
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
uvec2 ex_sig(uvec2 a) {
  uint implicit = (a.y & 0x7FF00000u) != 0u ? 0x00100000u : 0u;
  uint hi = (a.y & 0x000FFFFFu) | implicit;
  return uvec2(a.x, hi);
}

// ex_is_nan: true when the bit pattern is a NaN.
// Algorithm: exponent field all ones and a nonzero significand
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
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
bool ex_either_nan(uvec2 a, uvec2 b) {
  return any(bvec2(ex_is_nan(a), ex_is_nan(b)));
}

// ex_sel64: c ? a : b on 64-bit words, one select per word (no branch: GLSL ES 3.00 has no mix on
// integers, and a ternary on a uvec2 becomes control flow in SPIR-V 1.0).
// Algorithm: per-word conditional selection
// Source: Khronos, The OpenGL ES Shading Language 3.00.6, 2016, 5.9 (the ternary selection operator); docs/rules-format.md, "No branches in a rule"
// Bound: exact
// Flops: 0 (2 selects)
uvec2 ex_sel64(bool c, uvec2 a, uvec2 b) {
  uint x = c ? a.x : b.x;
  uint y = c ? a.y : b.y;
  return uvec2(x, y);
}

// ex_pick_nan: the NaN result of an operation with a NaN operand: a if it is a NaN, else b, made quiet.
// Algorithm: set the quiet bit (significand bit 51) of a if it is a NaN, else of b. Native fp64 on lavapipe (LLVM, x86 SSE) returns the first source operand's NaN, and LLVM passes a commutative operation's operands swapped: ex_add_bits and ex_mul_bits call ex_pick_nan(b, a), ex_sub_bits and ex_div_bits ex_pick_nan(a, b) (measured by tests/exact)
// Source: IEEE 754-2019, 6.2.3 (NaN propagation); Intel SDM vol. 1, 2016, 4.8.3.5 (first source)
// Bound: exact
// Flops: 0
uvec2 ex_pick_nan(uvec2 a, uvec2 b) {
  uvec2 n = ex_sel64(ex_is_nan(a), a, b);
  return uvec2(n.x, n.y | 0x00080000u);
}

// ex_exponent: the exponent of the integer significand, max(field, 1) (so value = ex_sig * 2^(ex_exponent - 1075)).
// Algorithm: exponent field, subnormals and zero counted as field 1
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
int ex_exponent(uvec2 a) {
  return max(int((a.y >> 20) & 0x7FFu), 1);
}

// ex_lt64: unsigned a < b on 64-bit words.
// Algorithm: compare high words, then low words
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword comparison)
// Bound: exact
// Flops: 0 (3 integer comparisons)
bool ex_lt64(uvec2 a, uvec2 b) {
  bool highBelow = a.y < b.y;
  bool lowBelow = all(bvec2(a.y == b.y, a.x < b.x));
  return any(bvec2(highBelow, lowBelow));
}

// ex_shl64: a << n for 0 <= n < 64 (GLSL shifts by 32 or more are undefined: no shift here reaches 32).
// Algorithm: both word shifts by k = n mod 32, the bits carried into the high word as (a.x >> 1) >> (31 - k) (0 when k = 0); n >= 32 selects (0, a.x << k). No branch
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword shifts)
// Bound: exact
// Flops: 0 (about 9 integer operations)
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

// ex_shr64: a >> n for 0 <= n < 64 (bits shifted out are dropped: truncation).
// Algorithm: both word shifts by k = n mod 32, the bits carried into the low word as (a.y << 1) << (31 - k) (0 when k = 0); n >= 32 selects (a.y >> k, 0). No branch
// Source: Knuth TAOCP vol. 2, 1997, 4.3.1 (multiword shifts)
// Bound: exact
// Flops: 0
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

// ex_shr_jam64: a >> n for n >= 0, the shifted-out bits ORed into bit 0 (the sticky bit).
// Algorithm: truncating shift by min(n, 63) (ex_shr64); a bit was lost when shifting back does not give a; n >= 64 leaves only the sticky bit of a != 0 ("jamming"). No branch
// Source: Hauser, Berkeley SoftFloat 3e, 2018 (shiftRightJam64 semantics)
// Bound: exact
// Flops: 0 (about 30 integer operations)
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

// ex_add64: 64-bit sum of two (lo, hi) words, modulo 2^64.
// Algorithm: word sums with the carry of the low word (a.x + b.x < a.x)
// Source: two's-complement multiword addition (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm A)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_add64(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;
  return uvec2(lo, a.y + b.y + (lo < a.x ? 1u : 0u));
}

// ex_sub64: 64-bit difference, modulo 2^64.
// Algorithm: word differences with the borrow of the low word (a.x < b.x)
// Source: two's-complement multiword subtraction (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm S)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_sub64(uvec2 a, uvec2 b) {
  return uvec2(a.x - b.x, a.y - b.y - (a.x < b.x ? 1u : 0u));
}

// ex_clz32: ex_clz32 by findMSB, where the target has GLSL's integer functions.
// Algorithm: 31 - findMSB(x); findMSB(0) is -1, so 0 gives 32
// Source: Khronos, The OpenGL ES Shading Language 3.10, 2014, 8.8 (findMSB)
// Bound: exact
// Flops: 0 (2 integer operations)
int ex_clz32(uint x) {
  return 31 - findMSB(x);
}

// ex_clz64: leading zero bits of a 64-bit (lo, hi) value (64 for 0).
// Algorithm: ex_clz32 of the high word, else 32 + ex_clz32 of the low word
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3
// Bound: exact
// Flops: 0
int ex_clz64(uvec2 a) {
  int high = ex_clz32(a.y);
  int low = 32 + ex_clz32(a.x);
  return a.y != 0u ? high : low;
}

// ex_round_pack: the binary64 nearest (ties to even) to sig * 2^(e - 1084), sign s. sig < 2^63; if e > 0 its top bit must be bit 62.
// Algorithm: e < 0: jamming shift to e = 0 (subnormal); keep 53 bits, 10 round bits; add half, clear the last bit on an exact tie; the significand's carry runs into the exponent field (up to infinity); e > 0x7FD selects infinity. No branch
// Source: IEEE 754-2019, 4.3.1; Hauser, Berkeley SoftFloat 3e, 2018 (roundPackToF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 30 integer operations)
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
uvec2 ex_norm_round_pack(bool s, int e, uvec2 sig) {
  int z = ex_clz64(sig);
  bool top = z == 0;
  uvec2 right = ex_shr_jam64(sig, 1);
  uvec2 left = ex_shl64(sig, max(z - 1, 0));
  uvec2 m = ex_sel64(top, right, left);
  int f = top ? e + 1 : e - (z - 1);
  return ex_round_pack(s, f, m);
}

// ex_add_bits: a + b in binary64, correctly rounded (ties to even).
// Algorithm: order by magnitude; significands << 10; the smaller jam-shifted by the exponent difference; add or subtract; normalize and round once. Exact cancellation gives +0; (-0) + (-0) = -0. One branch: NaN, infinite or two zero operands return early (selected among themselves); the finite path is computed whole, cancellation selected (docs/performance.md, "Mode exact: one branch per operation")
// Source: IEEE 754-2019, 5.4.1, 6.3; Hauser, Berkeley SoftFloat 3e, 2018 (addMagsF64/subMagsF64 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (about 60 integer operations)
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

// ex_bits: the binary64 pattern of a mode-exact double as uvec2(low word, high word), the order of unpackDouble2x32.
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32 word order)
// Bound: exact
// Flops: 0
uvec2 ex_bits(df_double a) {
  return uvec2(a.lo, a.hi);
}

// ex_add: a + b (mode exact), correctly rounded.
// Algorithm: ex_add_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
df_double ex_add(df_double a, df_double b) {
  return ex_from_bits(ex_add_bits(ex_bits(a), ex_bits(b)));
}

// ex_normalize_sig: the 53-bit significand with its top bit at bit 52 and the matching exponent (a finite nonzero a).
// Algorithm: a normal number's significand as it is; subnormals shifted left by their leading zeros, exponent lowered by the same count (a zero shifts by 53 and stays 0; no branch)
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
uvec2 ex_normalize_sig(uvec2 a, out int x) {
  uvec2 m = ex_sig(a);
  bool normal = (a.y & 0x7FF00000u) != 0u;
  int lead = ex_clz64(m) - 11;
  int shift = normal ? 0 : lead;
  int field = int((a.y >> 20) & 0x7FFu);
  x = normal ? field : 1 - shift;
  return ex_shl64(m, shift);
}

// ex_mul32: ex_mul32 by umulExtended, where the target has GLSL's integer functions (Mesa's soft-fp64 multiplies this way too).
// Algorithm: umulExtended: the 64-bit product's high and low words in one built-in
// Source: Khronos, The OpenGL ES Shading Language 3.10, 2014, 8.8 (umulExtended)
// Bound: exact
// Flops: 0 (1 integer multiplication)
uvec2 ex_mul32(uint a, uint b) {
  uint hi, lo;
  umulExtended(a, b, hi, lo);
  return uvec2(lo, hi);
}

// ex_mul_bits: a * b in binary64, correctly rounded (ties to even).
// Algorithm: 53x53-bit significand product in 32-bit words (ex_mul32), its top 64 bits with the rest as sticky bit, a one-bit jamming normalization, rounded once. One branch: NaN, infinite or zero operands return early (selected among themselves)
// Source: IEEE 754-2019, 5.4.1, 7.2 (0 * Inf invalid); Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm M
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (16 integer multiplications, about 80 other integer operations)
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

// ex_mul: a * b (mode exact), correctly rounded.
// Algorithm: ex_mul_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
df_double ex_mul(df_double a, df_double b) {
  return ex_from_bits(ex_mul_bits(ex_bits(a), ex_bits(b)));
}

// ex_add: a + b (mode exact), correctly rounded.
// Algorithm: ex_add_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// (width 3: the width-1 ex_add applied to each component, in a loop)
df_dvec3 ex_add(df_dvec3 a, df_dvec3 b) {
  df_dvec3 per_r;
  for (int per_k = 0; per_k < 3; ++per_k) {
    int per_i = 2 - per_k;
    df_double per_c = ex_add(df_double(a.hi[per_i], a.lo[per_i]), df_double(b.hi[per_i], b.lo[per_i]));
    per_r.hi[per_i] = per_c.hi;
    per_r.lo[per_i] = per_c.lo;
  }
  return per_r;
}

// ex_from_uint_bits: the binary64 pattern of a uint (exact: 32 bits fit in 53).
// Algorithm: the integer as a 64-bit significand, normalized and packed (no rounding happens)
// Source: IEEE 754-2019, 5.4.1 (convertFromInt)
// Bound: exact
// Flops: 0
uvec2 ex_from_uint_bits(bool negative, uint m) {
  if (m == 0u) return uvec2(0u);
  return ex_norm_round_pack(negative, 1084, uvec2(m, 0u));
}

// ex_from_int: double(i) (mode exact), exact.
// Algorithm: sign and magnitude (0u - uint(i) for negatives, -2^31 included), ex_from_uint_bits
// Source: IEEE 754-2019, 5.4.1
// Bound: exact
// Flops: 0 (integer arithmetic)
df_double ex_from_int(int i) {
  return ex_from_bits(ex_from_uint_bits(i < 0, i < 0 ? 0u - uint(i) : uint(i)));
}

// ex_from_float_bits: the binary64 pattern of a float (exact; a float subnormal becomes a normal double; a NaN stays NaN, made quiet).
// Algorithm: re-bias the exponent (127 -> 1023), subnormals normalized with ex_clz32, significand moved up 29 bits
// Source: IEEE 754-2019, 5.4.2 (formatOf conversions); 3.4 (binary32, binary64 encodings)
// Bound: exact
// Flops: 0
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

// ex_from_float: double(f) (mode exact), exact.
// Algorithm: ex_from_float_bits
// Source: IEEE 754-2019, 5.4.2
// Bound: exact
// Flops: 0 (integer arithmetic)
df_double ex_from_float(float f) {
  return ex_from_bits(ex_from_float_bits(f));
}

// ex_neg_bits: -a (flips the sign bit, NaN included, as GLSL's negation of a double does).
// Algorithm: sign bit flip
// Source: IEEE 754-2019, 5.5.1 (negate)
// Bound: exact
// Flops: 0
uvec2 ex_neg_bits(uvec2 a) {
  return uvec2(a.x, a.y ^ 0x80000000u);
}

// ex_sub_bits: a - b = a + (-b), correctly rounded.
// Algorithm: NaN operands as ex_pick_nan(a, b); otherwise ex_add with the sign of b flipped
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
uvec2 ex_sub_bits(uvec2 a, uvec2 b) {
  bool nan = ex_either_nan(a, b);
  uvec2 r = ex_add_bits(a, ex_neg_bits(b));
  return ex_sel64(nan, ex_pick_nan(a, b), r);
}

// ex_sub: a - b (mode exact), correctly rounded.
// Algorithm: ex_sub_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
df_double ex_sub(df_double a, df_double b) {
  return ex_from_bits(ex_sub_bits(ex_bits(a), ex_bits(b)));
}

df_double df_assign_component_dvec4(inout df_dvec4 v, int i, df_double x) {
  v.hi[i] = x.hi;
  v.lo[i] = x.lo;
  return x;
}

df_dvec4 ex_each_addsub(df_dvec4 a, df_dvec4 b, int w, int n) {
  df_dvec4 r = a;
  uint sign = uint(n) << 31;
  for (int k = 0; k < w; ++k) {
    int i = w - 1 - k;
    uvec2 x = uvec2(a.lo[i], a.hi[i]);
    uvec2 y = uvec2(b.lo[i], b.hi[i]);
    uvec2 s = ex_add_bits(x, uvec2(y.x, y.y ^ sign));
    s = ex_sel64(all(bvec2(n == 1, ex_either_nan(x, y))), ex_pick_nan(x, y), s);
    r.hi[i] = s.y;
    r.lo[i] = s.x;
  }
  return r;
}

df_dvec4 ex_widen_dvec3(df_dvec3 x) {
  return df_dvec4(uvec4(x.hi, 0u), uvec4(x.lo, 0u));
}

df_dvec3 ex_narrow_dvec3(df_dvec4 x) {
  return df_dvec3(x.hi.xyz, x.lo.xyz);
}

df_dvec4 ex_widen_double(df_double x) {
  return df_dvec4(uvec4(x.hi, 0u, 0u, 0u), uvec4(x.lo, 0u, 0u, 0u));
}

df_double ex_narrow_double(df_dvec4 x) {
  return df_double(x.hi.x, x.lo.x);
}

struct ex_dvec3_words {
  uvec4 xy;
  uvec2 z;
};
struct ex_dvec4_words {
  uvec4 xy;
  uvec4 zw;
};
struct P {
  df_dvec3 pos;
  float w;
  df_double m;
  df_dvec4 q[2];
};
struct P_words {
  uvec4 pos_xy;
  uvec2 pos_z;
  float w;
  uint ex_pad11;
  uvec2 m;
  uvec2 ex_pad12;
  uvec4 ex_pad13;
  ex_dvec4_words q[2];
};

df_double ex_load_double(uvec2 w) {
  return df_double(w.y, w.x);
}

df_dvec4 ex_load_dvec4(uvec4 xy, uvec4 zw) {
  return df_dvec4(uvec4(xy.yw, zw.yw), uvec4(xy.xz, zw.xz));
}
df_dvec4 ex_load_dvec4(ex_dvec4_words w) {
  return ex_load_dvec4(w.xy, w.zw);
}

uvec2 ex_words_double(df_double v) {
  return uvec2(v.lo, v.hi);
}

df_dvec3 ex_load_dvec3(uvec4 xy, uvec2 z) {
  return df_dvec3(uvec3(xy.yw, z.y), uvec3(xy.xz, z.x));
}
df_dvec3 ex_load_dvec3(ex_dvec3_words w) {
  return ex_load_dvec3(w.xy, w.z);
}

df_dvec3 ex_store_dvec3(out uvec4 xy, out uvec2 z, df_dvec3 v) {
  xy = uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y);
  z = uvec2(v.lo.z, v.hi.z);
  return v;
}

ex_dvec4_words ex_words_dvec4(df_dvec4 v) {
  return ex_dvec4_words(uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y), uvec4(v.lo.z, v.hi.z, v.lo.w, v.hi.w));
}

P ex_load_P_words(P_words w) {
  return P(ex_load_dvec3(w.pos_xy, w.pos_z), w.w, ex_load_double(w.m), df_dvec4[2](ex_load_dvec4(w.q[0]), ex_load_dvec4(w.q[1])));
}

P_words ex_words_P_words(P v) {
  P_words w;
  ex_store_dvec3(w.pos_xy, w.pos_z, v.pos);
  w.w = v.w;
  w.m = ex_words_double(v.m);
  w.q[0] = ex_words_dvec4(v.q[0]);
  w.q[1] = ex_words_dvec4(v.q[1]);
  w.ex_pad11 = 0u;
  w.ex_pad12 = uvec2(0u);
  w.ex_pad13 = uvec4(0u);
  return w;
}

uvec4 ex_words_dvec4_xy(df_dvec4 v) {
  return uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y);
}

uvec4 ex_words_dvec4_zw(df_dvec4 v) {
  return uvec4(v.lo.z, v.hi.z, v.lo.w, v.hi.w);
}


layout(std430, binding = 0) buffer In {
  float f;
  uint ex_pad0;
  uvec2 ex_pad1;
  uvec4 ex_pad2;
  uvec4 v3_xy;
  uvec2 v3_z;
  uvec2 d[];
} inb;
layout(std140, binding = 1) buffer Consts {
  float s;
  uint ex_pad3;
  uvec2 ex_pad4;
  uvec4 ex_pad5;
  uvec4 v4_xy;
  uvec4 v4_zw;
  uvec2 k;
  uvec2 ex_pad6;
  uvec4 v2[2];
  uvec4 ex_pad7;
  ex_dvec3_words v3s[2];
};
layout(std430, binding = 2) buffer Ps {
  int n;
  uint ex_pad8;
  uvec2 ex_pad9;
  uvec4 ex_pad10;
  P_words p[];
};

void bump(inout df_double x);

void bump(inout df_double x)
{
  x = ex_add(x, df_double(1072693248u, 0u));
}

void main()
{
  int ex_op;
  df_dvec4 ex_k1_1_a0;
  df_dvec4 ex_k1_1_a1;
  df_dvec4 ex_k1_1_r;
  int ex_k1_1_w;
  int ex_k1_1_n;
  df_dvec3 ex_c1_1;
  df_dvec3 ex_c1_2;
  df_double ex_c1_3;
  uint i = gl_GlobalInvocationID.x;
  inb.d[i] = ex_words_double(ex_add(ex_mul(ex_load_double(inb.d[i]), ex_load_double(k)), df_double(ex_load_dvec4(v4_xy, v4_zw).hi.y, ex_load_dvec4(v4_xy, v4_zw).lo.y)));
  df_double ex_member0 = ex_load_double(inb.d[i]);
  bump(ex_member0);
  inb.d[i] = ex_words_double(ex_member0);
  P q = ex_load_P_words(p[i]);
  df_dvec4 ex_member1;
  for (int ex_pc1 = 0; ex_pc1 < 3; ++ex_pc1)
  {
    switch (ex_pc1)
    {
    case 0:
      ex_k1_1_a0 = ex_widen_dvec3(df_dvec3(q.q[1].hi.xyz, q.q[1].lo.xyz));
      ex_k1_1_a1 = ex_widen_dvec3(ex_load_dvec3(v3s[i & 1u]));
      ex_k1_1_w = 3;
      ex_k1_1_n = 0;
      ex_op = 1;
      break;
    case 1:
      ex_c1_1 = ex_narrow_dvec3(ex_k1_1_r);
      ex_k1_1_a0 = ex_widen_dvec3(q.pos);
      ex_k1_1_a1 = ex_widen_dvec3(ex_c1_1);
      ex_k1_1_w = 3;
      ex_k1_1_n = 0;
      ex_op = 1;
      break;
    case 2:
      ex_c1_2 = ex_narrow_dvec3(ex_k1_1_r);
      q.pos = ex_c1_2;
      p[i] = ex_words_P_words(q);
      ex_member1 = ex_load_dvec4(p[i].q[0]);
      ex_k1_1_a0 = ex_widen_double(ex_from_int(n));
      ex_k1_1_a1 = ex_widen_double(q.m);
      ex_k1_1_w = 1;
      ex_k1_1_n = 0;
      ex_op = 1;
      break;
    }
    if (ex_op == 1)
    {
      ex_k1_1_r = ex_each_addsub(ex_k1_1_a0, ex_k1_1_a1, ex_k1_1_w, ex_k1_1_n);
    }
  }
  ex_c1_3 = ex_narrow_double(ex_k1_1_r);
  df_assign_component_dvec4(ex_member1, 3, ex_c1_3);
  p[i].q[0] = ex_words_dvec4(ex_member1);
  if (i == 0u)
  {
    df_dvec4 ex_member2 = ex_load_dvec4(v4_xy, v4_zw);
    df_dvec4 ex_member3;
    df_assign_component_dvec4(ex_member2, 3, ex_mul(ex_load_double(k), ex_from_float(s)));
    ex_member3 = ex_member2;
    v4_xy = ex_words_dvec4_xy(ex_member3);
    v4_zw = ex_words_dvec4_zw(ex_member3);
  }
}
