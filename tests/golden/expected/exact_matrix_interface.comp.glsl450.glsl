#version 450 core
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct df_dvec2 {
  uvec2 hi;
  uvec2 lo;
};
struct df_dvec3 {
  uvec3 hi;
  uvec3 lo;
};
struct df_dmat2 {
  uvec2 hi[2];
  uvec2 lo[2];
};
struct df_dmat2x3 {
  uvec3 hi[2];
  uvec3 lo[2];
};
struct df_dmat3x2 {
  uvec2 hi[3];
  uvec2 lo[3];
};
struct df_dmat3 {
  uvec3 hi[3];
  uvec3 lo[3];
};
struct df_dmat4 {
  uvec4 hi[4];
  uvec4 lo[4];
};
// doublet exact binary64 runtime (mode exact): 30 functions from rules/exact.glsl and rules/rte_exact.glsl, integer arithmetic (no optimizer guard needed)
struct df_double { uint hi; uint lo; };
struct df_dvec4 { uvec4 hi; uvec4 lo; };

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

// ex_add64: 64-bit sum of two (lo, hi) words, modulo 2^64.
// Algorithm: word sums with the carry of the low word (a.x + b.x < a.x)
// Source: two's-complement multiword addition (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm A)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_add64(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;
  return uvec2(lo, a.y + b.y + (lo < a.x ? 1u : 0u));
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

// ex_mul_first: a * b with a's NaN passed on first, as native's built-in sequences (dot, cross, smoothstep...) order their products (measured by tests/exact/exact_builtins_test.cpp).
// Algorithm: ex_mul_bits(b, a): multiplication is commutative in value; only the NaN choice changes
// Source: IEEE 754-2019, 5.4.1, 6.2.3
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
uvec2 ex_mul_first(uvec2 a, uvec2 b) {
  return ex_mul_bits(b, a);
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

// ex_sub64: 64-bit difference, modulo 2^64.
// Algorithm: word differences with the borrow of the low word (a.x < b.x)
// Source: two's-complement multiword subtraction (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm S)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_sub64(uvec2 a, uvec2 b) {
  return uvec2(a.x - b.x, a.y - b.y - (a.x < b.x ? 1u : 0u));
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

// ex_fma_bits: fma(a, b, c) as native fp64 on lavapipe computes it: a * b rounded to binary64, then + c rounded (two roundings, not IEEE fusedMultiplyAdd).
// Algorithm: p = ex_mul_bits(a, b), then ex_add_bits(p, c); with NaN operands native passes on the first NaN of a, b (then p, c) in operand order, not swapped as for a * b (measured by tests/exact/exact_fma_test.cpp)
// Source: GLSL 4.60 specification, 2017, 8.3 (fma: "may" be a single operation; precision of a*b+c otherwise); IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp per step (two roundings)
// Flops: 0 (integer arithmetic)
uvec2 ex_fma_bits(uvec2 a, uvec2 b, uvec2 c) {
  bool nan = ex_either_nan(a, b);
  uvec2 p = ex_mul_bits(a, b);
  uvec2 r = ex_sel64(ex_is_nan(p), p, ex_add_bits(p, c));
  return ex_sel64(nan, ex_pick_nan(a, b), r);
}

// ex_from_bits: the mode-exact double of a binary64 pattern uvec2(low word, high word).
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (packDouble2x32 word order)
// Bound: exact
// Flops: 0
df_double ex_from_bits(uvec2 w) {
  return df_double(w.y, w.x);
}

// ex_bits: the binary64 pattern of a mode-exact double as uvec2(low word, high word), the order of unpackDouble2x32.
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32 word order)
// Bound: exact
// Flops: 0
uvec2 ex_bits(df_double a) {
  return uvec2(a.lo, a.hi);
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
df_double ex_add(df_double a, df_double b) {
  return ex_from_bits(ex_add_bits(ex_bits(a), ex_bits(b)));
}

// ex_add: a + b (mode exact), correctly rounded.
// Algorithm: ex_add_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
// (width 4: the width-1 ex_add applied to each component, in a loop)
df_dvec4 ex_add(df_dvec4 a, df_dvec4 b) {
  df_dvec4 per_r;
  for (int per_k = 0; per_k < 4; ++per_k) {
    int per_i = 3 - per_k;
    df_double per_c = ex_add(df_double(a.hi[per_i], a.lo[per_i]), df_double(b.hi[per_i], b.lo[per_i]));
    per_r.hi[per_i] = per_c.hi;
    per_r.lo[per_i] = per_c.lo;
  }
  return per_r;
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

// ex_mul_dmat4_dvec4: (m * v)[i] = fma(m[0][i], v[0], fma(m[1][i], v[1], ...)), the last column
// first, every step rounded as native's (each fma twice).
df_dvec4 ex_mul_dmat4_dvec4(df_dmat4 m, df_dvec4 v) {
  df_dvec4 p;
  for (int k = 0; k < 4; ++k) {
    int i = 3 - k;
    uvec2 s = ex_mul_first(uvec2(m.lo[3][i], m.hi[3][i]), uvec2(v.lo[3], v.hi[3]));
    for (int t = 2; t >= 0; --t) s = ex_fma_bits(uvec2(m.lo[t][i], m.hi[t][i]), uvec2(v.lo[t], v.hi[t]), s);
    p.hi[i] = s.y;
    p.lo[i] = s.x;
  }
  return p;
}

// ex_mul_dmat3_dvec3: (m * v)[i] = fma(m[0][i], v[0], fma(m[1][i], v[1], ...)), the last column
// first, every step rounded as native's (each fma twice).
df_dvec3 ex_mul_dmat3_dvec3(df_dmat3 m, df_dvec3 v) {
  df_dvec3 p;
  for (int k = 0; k < 3; ++k) {
    int i = 2 - k;
    uvec2 s = ex_mul_first(uvec2(m.lo[2][i], m.hi[2][i]), uvec2(v.lo[2], v.hi[2]));
    for (int t = 1; t >= 0; --t) s = ex_fma_bits(uvec2(m.lo[t][i], m.hi[t][i]), uvec2(v.lo[t], v.hi[t]), s);
    p.hi[i] = s.y;
    p.lo[i] = s.x;
  }
  return p;
}

df_double df_component_dvec2(df_dvec2 v, int i) {
  return df_double(v.hi[i], v.lo[i]);
}

df_dvec4 df_make_dvec4_3_1(df_dvec3 a0, df_double a1) {
  return df_dvec4(uvec4(a0.hi.x, a0.hi.y, a0.hi.z, a1.hi), uvec4(a0.lo.x, a0.lo.y, a0.lo.z, a1.lo));
}

df_double df_swizzle_dvec3_z(df_dvec3 v) {
  return df_double(v.hi.z, v.lo.z);
}

df_dvec4 df_assign_column_dmat4(inout df_dmat4 m, int j, df_dvec4 v) {
  m.hi[j] = v.hi;
  m.lo[j] = v.lo;
  return v;
}

df_double df_swizzle_dvec4_w(df_dvec4 v) {
  return df_double(v.hi.w, v.lo.w);
}

df_double df_assign_element_dmat4(inout df_dmat4 m, int j, int i, df_double x) {
  m.hi[j][i] = x.hi;
  m.lo[j][i] = x.lo;
  return x;
}

// ex_mul_dmat2_dvec2: (m * v)[i] = fma(m[0][i], v[0], fma(m[1][i], v[1], ...)), the last column
// first, every step rounded as native's (each fma twice).
df_dvec2 ex_mul_dmat2_dvec2(df_dmat2 m, df_dvec2 v) {
  df_dvec2 p;
  for (int k = 0; k < 2; ++k) {
    int i = 1 - k;
    uvec2 s = ex_mul_first(uvec2(m.lo[1][i], m.hi[1][i]), uvec2(v.lo[1], v.hi[1]));
    for (int t = 0; t >= 0; --t) s = ex_fma_bits(uvec2(m.lo[t][i], m.hi[t][i]), uvec2(v.lo[t], v.hi[t]), s);
    p.hi[i] = s.y;
    p.lo[i] = s.x;
  }
  return p;
}

// ex_mul_dmat2_dmat3x2: column j of a * b is a * (column j of b) (ex_mul_dmat2_dvec2).
df_dmat3x2 ex_mul_dmat2_dmat3x2(df_dmat2 a, df_dmat3x2 b) {
  df_dmat3x2 m;
  for (int k = 0; k < 3; ++k) {
    int j = 2 - k;
    df_dvec2 cj = ex_mul_dmat2_dvec2(a, df_dvec2(b.hi[j], b.lo[j]));
    m.hi[j] = cj.hi;
    m.lo[j] = cj.lo;
  }
  return m;
}

df_double df_swizzle_dvec2_y(df_dvec2 v) {
  return df_double(v.hi.y, v.lo.y);
}

df_double df_assign_element_dmat3x2(inout df_dmat3x2 m, int j, int i, df_double x) {
  m.hi[j][i] = x.hi;
  m.lo[j][i] = x.lo;
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
struct ex_dmat3x3_words {
  ex_dvec3_words c[3];
};
struct ex_dmat2x3_words {
  ex_dvec3_words c[2];
};
struct ex_dmat2x2_words {
  uvec4 c[2];
};
struct ex_dvec4_words {
  uvec4 xy;
  uvec4 zw;
};
struct ex_dmat4x4_words {
  ex_dvec4_words c[4];
};
struct ex_dmat3x2_words {
  uvec4 c[3];
};

df_dvec4 ex_load_dvec4(uvec4 xy, uvec4 zw) {
  return df_dvec4(uvec4(xy.yw, zw.yw), uvec4(xy.xz, zw.xz));
}
df_dvec4 ex_load_dvec4(ex_dvec4_words w) {
  return ex_load_dvec4(w.xy, w.zw);
}

df_dvec2 ex_load_dvec2(uvec4 w) {
  return df_dvec2(w.yw, w.xz);
}

df_double ex_load_double(uvec2 w) {
  return df_double(w.y, w.x);
}

ex_dvec4_words ex_words_dvec4(df_dvec4 v) {
  return ex_dvec4_words(uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y), uvec4(v.lo.z, v.hi.z, v.lo.w, v.hi.w));
}

ex_dmat4x4_words ex_words_dmat4(df_dmat4 v) {
  return ex_dmat4x4_words(ex_dvec4_words[4](ex_words_dvec4(df_dvec4(v.hi[0], v.lo[0])), ex_words_dvec4(df_dvec4(v.hi[1], v.lo[1])), ex_words_dvec4(df_dvec4(v.hi[2], v.lo[2])), ex_words_dvec4(df_dvec4(v.hi[3], v.lo[3]))));
}

df_dvec3 ex_load_dvec3(uvec4 xy, uvec2 z) {
  return df_dvec3(uvec3(xy.yw, z.y), uvec3(xy.xz, z.x));
}
df_dvec3 ex_load_dvec3(ex_dvec3_words w) {
  return ex_load_dvec3(w.xy, w.z);
}

uvec2 ex_words_double(df_double v) {
  return uvec2(v.lo, v.hi);
}

df_dmat2 ex_load_dmat2(ex_dmat2x2_words w) {
  df_dvec2 c0 = ex_load_dvec2(w.c[0]);
  df_dvec2 c1 = ex_load_dvec2(w.c[1]);
  return df_dmat2(uvec2[2](c0.hi, c1.hi), uvec2[2](c0.lo, c1.lo));
}

df_dmat3x2 ex_load_dmat3x2(ex_dmat3x2_words w) {
  df_dvec2 c0 = ex_load_dvec2(w.c[0]);
  df_dvec2 c1 = ex_load_dvec2(w.c[1]);
  df_dvec2 c2 = ex_load_dvec2(w.c[2]);
  return df_dmat3x2(uvec2[3](c0.hi, c1.hi, c2.hi), uvec2[3](c0.lo, c1.lo, c2.lo));
}

uvec4 ex_words_dvec2(df_dvec2 v) {
  return uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y);
}

ex_dmat3x2_words ex_words_dmat3x2(df_dmat3x2 v) {
  return ex_dmat3x2_words(uvec4[3](ex_words_dvec2(df_dvec2(v.hi[0], v.lo[0])), ex_words_dvec2(df_dvec2(v.hi[1], v.lo[1])), ex_words_dvec2(df_dvec2(v.hi[2], v.lo[2]))));
}


uniform uvec4 u_model[8];
df_dmat4 u_model_value;
uniform uvec4 r[9];
df_dmat3 r_value[2];
layout(std140, binding = 0) uniform Mats {
  float s;
  uint ex_pad0;
  uvec2 ex_pad1;
  uvec4 ex_pad2;
  ex_dmat3x3_words a;
  ex_dmat2x3_words b;
  ex_dmat2x2_words c;
  uvec2 k;
};
layout(std430, binding = 1) buffer Io {
  float f;
  uint ex_pad3;
  uvec2 ex_pad4;
  uvec4 ex_pad5;
  ex_dmat4x4_words m;
  ex_dmat3x2_words n[2];
  ex_dvec4_words v[];
} io;


void main()
{
  int ex_op;
  df_dvec4 ex_k1_1_a0;
  df_dvec4 ex_k1_1_a1;
  df_dvec4 ex_k1_1_r;
  int ex_k1_1_w;
  int ex_k1_1_n;
  df_dvec4 ex_c1_1;
  df_double ex_c1_2;
  u_model_value = df_dmat4(uvec4[4](uvec4(u_model[0].y, u_model[0].w, u_model[1].y, u_model[1].w), uvec4(u_model[2].y, u_model[2].w, u_model[3].y, u_model[3].w), uvec4(u_model[4].y, u_model[4].w, u_model[5].y, u_model[5].w), uvec4(u_model[6].y, u_model[6].w, u_model[7].y, u_model[7].w)), uvec4[4](uvec4(u_model[0].x, u_model[0].z, u_model[1].x, u_model[1].z), uvec4(u_model[2].x, u_model[2].z, u_model[3].x, u_model[3].z), uvec4(u_model[4].x, u_model[4].z, u_model[5].x, u_model[5].z), uvec4(u_model[6].x, u_model[6].z, u_model[7].x, u_model[7].z)));
  r_value[0] = df_dmat3(uvec3[3](uvec3(r[0].y, r[0].w, r[1].y), uvec3(r[1].w, r[2].y, r[2].w), uvec3(r[3].y, r[3].w, r[4].y)), uvec3[3](uvec3(r[0].x, r[0].z, r[1].x), uvec3(r[1].z, r[2].x, r[2].z), uvec3(r[3].x, r[3].z, r[4].x)));
  r_value[1] = df_dmat3(uvec3[3](uvec3(r[4].w, r[5].y, r[5].w), uvec3(r[6].y, r[6].w, r[7].y), uvec3(r[7].w, r[8].y, r[8].w)), uvec3[3](uvec3(r[4].z, r[5].x, r[5].z), uvec3(r[6].x, r[6].z, r[7].x), uvec3(r[7].z, r[8].x, r[8].z)));
  uint i = gl_GlobalInvocationID.x;
  df_dvec4 x = ex_load_dvec4(io.v[i]);
  io.v[i] = ex_words_dvec4(ex_add(ex_mul_dmat4_dvec4(u_model_value, x), df_make_dvec4_3_1(ex_mul_dmat3_dvec3(r_value[i & 1u], df_dvec3(x.hi.xyz, x.lo.xyz)), ex_mul(df_component_dvec2(ex_load_dvec2(c.c[1]), int(i & 1u)), ex_load_double(k)))));
  if (i == 0u)
  {
    io.m = ex_words_dmat4(u_model_value);
    for (int ex_pc1 = 0; ex_pc1 < 2; ++ex_pc1)
    {
      switch (ex_pc1)
      {
      case 0:
        ex_k1_1_a0 = ex_load_dvec4(io.m.c[1]);
        ex_k1_1_a1 = df_make_dvec4_3_1(ex_load_dvec3(a.c[0]), df_swizzle_dvec3_z(ex_load_dvec3(b.c[1])));
        ex_k1_1_w = 4;
        ex_k1_1_n = 0;
        ex_op = 1;
        break;
      case 1:
        ex_c1_1 = ex_k1_1_r;
        io.m.c[2] = ex_words_dvec4(ex_c1_1);
        io.m.c[3].xy.zw = ex_words_double(ex_mul(df_swizzle_dvec4_w(ex_load_dvec4(io.m.c[0])), ex_load_double(k)));
        io.n[1] = ex_words_dmat3x2(ex_mul_dmat2_dmat3x2(ex_load_dmat2(c), ex_load_dmat3x2(io.n[0])));
        ex_k1_1_a0 = ex_widen_double(df_swizzle_dvec2_y(ex_load_dvec2(io.n[0].c[2])));
        ex_k1_1_a1 = ex_widen_double(df_swizzle_dvec3_z(ex_load_dvec3(a.c[2])));
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
    ex_c1_2 = ex_narrow_double(ex_k1_1_r);
    io.n[0].c[2].zw = ex_words_double(ex_c1_2);
  }
}
