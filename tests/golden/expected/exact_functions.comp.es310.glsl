#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

struct df_dvec2 {
  vec2 hi;
  vec2 lo;
};
// doublet float-float runtime: 9 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
struct ex_dvec2 {
  uvec2 hi;
  uvec2 lo;
};
// doublet exact binary64 runtime (mode exact): 36 functions from rules/exact.glsl and rules/rte_exact.glsl, integer arithmetic (no optimizer guard needed)
struct ex_double { uint hi; uint lo; };
struct ff_double { float hi; float lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_split (bit-casts): a == hi + lo exactly, hi and lo each fit in 12 significant bits, as
// Veltkamp's split gives them, from a's bit pattern instead of the constant 4097 (3 flops fewer,
// no range limit, nothing an algebraic optimizer can fold: hi is not a float expression of a).
// Algorithm: binary32 pattern rounded to 12 significant bits, (bits + 2^11) & ~(2^12 - 1) (ties
// away from zero; a carry into the exponent field is the rounding up to the next binade), except
// where that would carry past FLT_MAX: there the pattern is truncated; lo = a - hi
// Source: Dekker 1971, section 5 (mul12 is exact for halves of at most 12 bits); IEEE 754-2008
// binary32 encoding; HFPA (2018) section 4.4.2 (splitting)
// Bound: exact
// Flops: 1 (plus 4 integer operations)
// Steps: hi = uintBitsToFloat(min(bits + 0x800u, bits | 0x7F7FF800u) & 0xFFFFF000u), bits the
//        pattern of a; lo = RN(a - hi), exact (hi is a on a coarser grid: |lo| <= 2^11 ulp(a)).
//        The min: with a's magnitude m, bits | 0x7F7FF800 exceeds bits + 0x800 while m <
//        0x7F7FF000, equals it up to 0x7F7FF7FF, and is the pattern itself from 0x7F7FF800 (all of
//        0x7F7FF800's bits are set there), so only those magnitudes are truncated; the sign bit is
//        the same on both sides. One unsigned min: float min/max or clamp cost about 20% of a loop
//        on SwiftShader (docs/performance.md).
// Range: no limit. From |a| = 0x7F7FF800 (3.4024e38) hi is a truncated to 12 bits and lo has 12
// bits (0 <= |lo| < 2^12 ulp(a)); mul12 stays exact there (df_two_prod below). +-Inf: hi = +-Inf,
// lo = NaN; NaN: lo is NaN (the callers' df_finish then returns the plain product).
df_double df_split(float a) {
  uint bits = floatBitsToUint(a);
  float hi = (uintBitsToFloat(min(bits + 2048u, bits | 2139092992u) & 4294963200u));
  float lo = (a - hi);
  return df_double(hi, lo);
}

// df_mul12_error: a*b - p exactly, for p = RN(a*b) and halves sa of a and sb of b of at most 12
// significant bits each (df_split): Dekker's partial products, summed in the order in which
// every partial sum is exact (the proofs are in df_two_prod's headers).
// Algorithm: the error term of Dekker's mul12 from the four products of the halves
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 8
// Steps: t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
float df_mul12_error(df_double sa, df_double sb, float p) {
  float hh = (sa.hi * sb.hi);
  float hl = (sa.hi * sb.lo);
  float lh = (sa.lo * sb.hi);
  float ll = (sa.lo * sb.lo);
  float t1 = (hh - p);
  float t2 = (t1 + hl);
  float t3 = (t2 + lh);
  float e = (t3 + ll);
  return e;
}

// df_two_prod (bit-casts): p + e == a * b exactly, with p = RN(a * b): Dekker's product on the
// halves of the split by bits, which needs no scaling of the operands (no range limit).
// Algorithm: Dekker's product (mul12, TwoProd without FMA) on halves split by their bit patterns
// Source: Dekker 1971, mul12; HFPA (2018) Algorithm 4.10
// Bound: exact
// Flops: 11 (plus 8 integer operations)
// Steps: p = RN(a*b); (ah,al) = split(a); (bh,bl) = split(b) (df_split, bit-casts);
//        t1 = RN(ah*bh - p); t2 = RN(t1 + ah*bl); t3 = RN(t2 + al*bh); e = RN(t3 + al*bl).
// Exactness, with a = A*2^i, b = B*2^j (A, B 24-bit integers), ah = AH*2^(i+12), al = AL*2^i and
// likewise for b, in units of 2^(i+j): t1 = AB - p - AL*BH*2^12 - AH*BL*2^12 - AL*BL is a multiple of
// 2^23 below 2^37; t2 = t1 + AH*BL*2^12 a multiple of 2^12 below 2^36; t3 = AB - p - AL*BL an integer
// of at most 2^24; e = AB - p. Each fits in 24 bits when |AL|, |BL| <= 2^11 (rounded halves), and
// still when one of them is below 2^12 (the truncated split of |a| >= 0x7F7FF800: a finite product
// then has |b| < 2, whose split is rounded). So the pairs are those of the Veltkamp version.
// Range: exact when |a*b| <= FLT_MAX; e underflows below ~2^-102. When a*b overflows, or an
// operand is Inf or NaN, p is the IEEE result and the callers' df_finish returns (p, 0).
df_double df_two_prod(float a, float b) {
  float p = ((a * b) - df_guard[int(df_guard[1])]);
  df_double sa = df_split(a);
  df_double sb = df_split(b);
  float e = (df_mul12_error(sa, sb, p));
  return df_double(p, e);
}

// df_fast_two_sum: s + e == a + b exactly, with s = RN(a + b), PROVIDED a == 0 or
// exponent(a) >= exponent(b) (true whenever |a| >= |b|). Callers guarantee it.
// Algorithm: Fast2Sum
// Source: Dekker 1971, Theorem 4.3; HFPA (2018) Algorithm 4.3
// Bound: exact
// Flops: 3
// Steps: s = RN(a+b); z = RN(s-a); e = RN(b-z).
df_double df_fast_two_sum(float a, float b) {
  float s = ((a + b) - df_guard[int(df_guard[1])]);
  float z = ((s - a) - df_guard[int(df_guard[1])]);
  float e = (b - z);
  return df_double(s, e);
}

// df_finish: z where 0 < |z.hi| <= FLT_MAX (a regular result); elsewhere (f, 0), where f is
// the caller's plain float result on the high words. One select per component, so the common
// path pays one abs and two comparisons. The comparisons use the guarded |z.hi| (not isinf/isnan,
// which a fast-math optimizer may fold): false for NaN, so NaN takes the (f, 0) branch too.
// Algorithm: finiteness and zero test of hi, then selection
// Source: IEEE 754-2008 sections 6.1-6.3 (infinity, NaN, signed zero); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 1 (plus 2 comparisons)
df_double df_finish(df_double z, float f) {
  float az = (abs(z.hi));
  bool regular = all(bvec2(az > 0.0, az <= 3.40282347e38));
  float h = (mix(f, z.hi, regular));
  float l = (mix(0.0, z.lo, regular));
  return df_double(h, l);
}

// df_mul: a * b.
// Algorithm: DWTimesDW1 (JMP Algorithm 10) with Dekker's TwoProd (Veltkamp split of scaled operands, C = 4097), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017 (bound 7u^2); Muller, Rideau, ACM TOMS 48(1), 2022 (5u^2)
// Bound: 7u^2
// Flops: 29
// Steps: (ch,cl1) = TwoProd(ah,bh); tl = RN(ah*bl); th = RN(al*bh); cl2 = RN(th+tl);
//        cl3 = RN(cl1+cl2); (zh,zl) = Fast2Sum(ch,cl3); df_finish(z, ch).
// The 7u^2 of JMP 2017 was later proved to be 5u^2/(1+u)^2 < 5u^2 (MR 2022, Theorem 2.6).
// Range: any finite operands whose product is within float range (TwoProd scales them).
// Special values: ch = RN(ah*bh) gives overflow to +-Inf, 0 * Inf = NaN and the sign of a zero.
df_double df_mul(df_double a, df_double b) {
  df_double c = df_two_prod(a.hi, b.hi);
  float tl = (a.hi * b.lo);
  float th = (a.lo * b.hi);
  float cl2 = (th + tl);
  float cl3 = (c.lo + cl2);
  df_double z = df_fast_two_sum(c.hi, cl3);
  df_double r = df_finish(z, c.hi);
  return r;
}

// df_two_sum: s + e == a + b exactly, with s = RN(a + b); no precondition on a, b.
// Algorithm: TwoSum (branch-free, 6 operations)
// Source: Knuth, TAOCP vol. 2, 3rd ed., 1998, 4.2.2 Theorem B; HFPA (2018) Algorithm 4.4
// Bound: exact
// Flops: 6
// Steps: s = RN(a+b); bb = RN(s-a); ab = RN(s-bb); da = RN(a-ab); db = RN(b-bb); e = RN(da+db).
df_double df_two_sum(float a, float b) {
  float s = ((a + b) - df_guard[int(df_guard[1])]);
  float bb = ((s - a) - df_guard[int(df_guard[1])]);
  float ab = (s - bb);
  float da = (a - ab);
  float db = (b - bb);
  float e = (da + db);
  return df_double(s, e);
}

// df_add: a + b.
// Algorithm: AccurateDWPlusDW (JMP Algorithm 6), then df_finish
// Source: Joldes, Muller, Popescu, ACM TOMS 44(2), 2017, Theorem 3.1
// Bound: 3u^2 + 13u^3
// Flops: 21
// Steps: (sh,sl) = TwoSum(ah,bh); (th,tl) = TwoSum(al,bl); c = RN(sl+th);
//        (vh,vl) = Fast2Sum(sh,c); w = RN(tl+vl); (zh,zl) = Fast2Sum(vh,w); df_finish(z, sh).
// The bound holds for all signs (the "sloppy" 11-flop variant is unbounded under cancellation).
// Special values: sh = RN(ah+bh) is +-Inf, NaN or the signed zero IEEE gives (x + Inf = Inf,
// Inf - Inf = NaN, -0 + -0 = -0, x - x = +0). A finite sum above FLT_MAX is Inf (float's range).
df_double df_add(df_double a, df_double b) {
  df_double s = df_two_sum(a.hi, b.hi);
  df_double t = df_two_sum(a.lo, b.lo);
  float c = (s.lo + t.hi);
  df_double v = df_fast_two_sum(s.hi, c);
  float w = (t.lo + v.lo);
  df_double z = df_fast_two_sum(v.hi, w);
  df_double r = df_finish(z, s.hi);
  return r;
}

// df_mul_pow2: a * p where every component of p is a power of two (+-2^k), exact: scaling by a
// power of two only changes exponents, so hi*p and lo*p are exact and (hi*p, lo*p) is still a
// double-word number. Replaces df_mul (29 flops) and df_div by a power of two.
// Algorithm: exact scaling of both words by a power of two, then df_finish
// Source: HFPA (2018), section 2.2 (multiplication by a power of the radix is exact); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 3
// Range: exact while lo*p stays normal (|lo*p| >= 2^-126) and hi*p does not overflow; an
// overflowing, zero or NaN hi*p gives (hi*p, 0) as df_mul does (df_finish).
df_double df_mul_pow2(df_double a, float p) {
  float h = (a.hi * p);
  float l = (a.lo * p);
  df_double r = df_finish(df_double(h, l), h);
  return r;
}

df_dvec2 df_make_dvec2_1_1(df_double a0, df_double a1) {
  return df_dvec2(vec2(a0.hi, a1.hi), vec2(a0.lo, a1.lo));
}

// ex_from_bits: the mode-exact double of a binary64 pattern uvec2(low word, high word).
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (packDouble2x32 word order)
// Bound: exact
// Flops: 0
ex_double ex_from_bits(uvec2 w) {
  return ex_double(w.y, w.x);
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

// ex_add64: 64-bit sum of two (lo, hi) words, modulo 2^64.
// Algorithm: word sums with the carry of the low word (a.x + b.x < a.x)
// Source: two's-complement multiword addition (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm A)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_add64(uvec2 a, uvec2 b) {
  uint lo = a.x + b.x;
  return uvec2(lo, a.y + b.y + (lo < a.x ? 1u : 0u));
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
ex_double ex_from_int(int i) {
  return ex_from_bits(ex_from_uint_bits(i < 0, i < 0 ? 0u - uint(i) : uint(i)));
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

// ex_u64_to_float: a 64-bit (lo, hi) integer as a float, rounded (an estimate for ex_sqrt_bits).
// Algorithm: float(hi) * 2^32 + float(lo)
// Source: IEEE 754-2019, 5.4.1 (convertFromInt)
// Bound: 0.5 ulp of float, twice (an estimate: relative error below 2^-23)
// Flops: 2
float ex_u64_to_float(uvec2 a) {
  return float(a.y) * 4294967296.0 + float(a.x);
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

// ex_sub64: 64-bit difference, modulo 2^64.
// Algorithm: word differences with the borrow of the low word (a.x < b.x)
// Source: two's-complement multiword subtraction (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm S)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_sub64(uvec2 a, uvec2 b) {
  return uvec2(a.x - b.x, a.y - b.y - (a.x < b.x ? 1u : 0u));
}

// ex_div_step: k more quotient bits of a long division by mb: (q, r) as (q.x, q.y, r.x, r.y), 0 <= r < 2mb, becomes (q * 2^k + d, r * 2^k - d * mb) with the digit d that leaves 0 <= r' < mb (k <= 18, mb < 2^53).
// Algorithm: d = r * 2^k / mb estimated by one float division: r and mb reach float with relative errors below 2^-23 each and the quotient is below 2^19, so the estimate is within 0.25 of r * 2^k / mb (also with the 2.5-ulp float division GLSL allows) and d within one of the true digit; r' in 64-bit words modulo 2^64 (the true r' is small and signed); one unit correction each way, by selects (no loop)
// Source: Ercegovac, Lang, Digital Arithmetic, 2004, ch. 5 (division by digit recurrence: high radix, digit selection by an estimate, correction); Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm D
// Bound: exact
// Flops: 8 (the digit estimate)
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

// ex_bits: the binary64 pattern of a mode-exact double as uvec2(low word, high word), the order of unpackDouble2x32.
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32 word order)
// Bound: exact
// Flops: 0
uvec2 ex_bits(ex_double a) {
  return uvec2(a.lo, a.hi);
}

// ex_div: a / b (mode exact), correctly rounded.
// Algorithm: ex_div_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
ex_double ex_div(ex_double a, ex_double b) {
  return ex_from_bits(ex_div_bits(ex_bits(a), ex_bits(b)));
}

// ex_exponent: the exponent of the integer significand, max(field, 1) (so value = ex_sig * 2^(ex_exponent - 1075)).
// Algorithm: exponent field, subnormals and zero counted as field 1
// Source: IEEE 754-2019, 3.4
// Bound: exact
// Flops: 0
int ex_exponent(uvec2 a) {
  return max(int((a.y >> 20) & 0x7FFu), 1);
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

// ex_add: a + b (mode exact), correctly rounded.
// Algorithm: ex_add_bits on the patterns
// Source: IEEE 754-2019, 5.4.1
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
ex_double ex_add(ex_double a, ex_double b) {
  return ex_from_bits(ex_add_bits(ex_bits(a), ex_bits(b)));
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
ex_double ex_mul(ex_double a, ex_double b) {
  return ex_from_bits(ex_mul_bits(ex_bits(a), ex_bits(b)));
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

// ex_from_ff: the binary64 nearest f.hi + f.lo (one rounding); a non-finite hi, or lo = 0 (which keeps the sign of a zero hi), gives float(hi) exactly.
// Algorithm: both words widened exactly (ex_from_float_bits), then ex_add_bits
// Source: IEEE 754-2019, 5.4.1, 5.4.2
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
uvec2 ex_from_ff(ff_double f) {
  uvec2 h = ex_from_float_bits(f.hi);
  if ((floatBitsToUint(f.hi) & 0x7F800000u) == 0x7F800000u || f.lo == 0.0) return h;
  return ex_add_bits(h, ex_from_float_bits(f.lo));
}

// ex_to_float_bits: the float nearest (ties to even) to a binary64 pattern, as float bits; overflow gives Inf, tiny values float subnormals or zero.
// Algorithm: significand cut to 31 bits with a sticky bit, exponent re-biased (1023 -> 127); round-and-pack with 7 round bits (jamming shift into the float subnormal range)
// Source: IEEE 754-2019, 5.4.2, 4.3.1; Hauser, Berkeley SoftFloat 3e, 2018 (roundPackToF32 scheme)
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0
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

// ex_to_ff: the float-float pair nearest a binary64 pattern: hi = float(a), lo = float(a - hi); (float(a), 0) when hi is not finite (|a| > FLT_MAX, Inf, NaN).
// Algorithm: two roundings to float (ex_to_float_bits); a - hi is exact in binary64. hi + lo keeps 48 of a's 53 bits; ex_ff_residual gives the rest
// Source: Dekker, Numer. Math. 18, 1971 (double-word representation); IEEE 754-2019, 5.4.2
// Bound: exact
// Flops: 0 (integer arithmetic)
ff_double ex_to_ff(uvec2 a) {
  uint h = ex_to_float_bits(a);
  if ((h & 0x7F800000u) == 0x7F800000u) return ff_double(uintBitsToFloat(h), 0.0);
  uvec2 rest = ex_sub_bits(a, ex_from_float_bits(uintBitsToFloat(h)));
  return ff_double(uintBitsToFloat(h), uintBitsToFloat(ex_to_float_bits(rest)));
}

ex_dvec2 ff_make_dvec2_1_1(ex_double a0, ex_double a1) {
  return ex_dvec2(uvec2(a0.hi, a1.hi), uvec2(a0.lo, a1.lo));
}

// The calls of exact functions (docs/modes.md, "Exact functions"): a float-float pair to the binary64
// nearest hi + lo, and a binary64 value to its nearest pair.
ex_double df_to_exact(df_double a) {
  return ex_from_bits(ex_from_ff(ff_double(a.hi, a.lo)));
}
df_double df_from_exact(ex_double a) {
  ff_double f = ex_to_ff(ex_bits(a));
  return df_double(f.hi, f.lo);
}
ex_dvec2 df_to_exact(df_dvec2 a) {
  ex_double x0 = df_to_exact(df_double(a.hi.x, a.lo.x));
  ex_double x1 = df_to_exact(df_double(a.hi.y, a.lo.y));
  return ex_dvec2(uvec2(x0.hi, x1.hi), uvec2(x0.lo, x1.lo));
}
df_dvec2 df_from_exact(ex_dvec2 a) {
  df_double x0 = df_from_exact(ex_double(a.hi.x, a.lo.x));
  df_double x1 = df_from_exact(ex_double(a.hi.y, a.lo.y));
  return df_dvec2(vec2(x0.hi, x1.hi), vec2(x0.lo, x1.lo));
}

layout(std430, binding = 0) readonly buffer In {
  df_double x[];
};
layout(std430, binding = 1) writeonly buffer Out {
  df_double sums[];
};

ex_double harmonic(ex_double scale, int terms);
ex_dvec2 both_ends(ex_dvec2 v);

ex_double harmonic(ex_double scale, int terms)
{
  ex_double s = ex_double(0u, 0u);
  for (int k = 1; k <= terms; ++k)
  {
    s = ex_add(s, ex_div(scale, ex_from_int(k)));
  }
  return s;
}

ex_dvec2 both_ends(ex_dvec2 v)
{
  return ff_make_dvec2_1_1(harmonic(ex_double(v.hi.x, v.lo.x), 2), ex_mul(ex_double(v.hi.y, v.lo.y), ex_double(v.hi.y, v.lo.y)));
}

void main()
{
  uint i = gl_GlobalInvocationID.x;
  df_dvec2 e = df_from_exact(both_ends(df_to_exact(df_make_dvec2_1_1(x[i], df_double(0.5 - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])])))));
  sums[i] = df_add(df_mul_pow2(df_from_exact(harmonic(df_to_exact(x[i]), 3000)), 2.0), df_mul(df_double(e.hi.y, e.lo.y), df_double(e.hi.x, e.lo.x)));
}
