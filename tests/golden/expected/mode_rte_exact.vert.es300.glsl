#version 300 es
precision highp float;
precision highp int;

// doublet exact binary64 runtime (mode exact): 14 functions from rules/exact.glsl and rules/rte_exact.glsl, integer arithmetic (no optimizer guard needed)
struct df_double { uint hi; uint lo; };
struct df_dvec3 { uvec3 hi; uvec3 lo; };

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

// ex_sub64: 64-bit difference, modulo 2^64.
// Algorithm: word differences with the borrow of the low word (a.x < b.x)
// Source: two's-complement multiword subtraction (Knuth TAOCP vol. 2, 1997, 4.3.1, Algorithm S)
// Bound: exact
// Flops: 0 (4 integer operations)
uvec2 ex_sub64(uvec2 a, uvec2 b) {
  return uvec2(a.x - b.x, a.y - b.y - (a.x < b.x ? 1u : 0u));
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

// ex_clz32: count of leading zero bits of a 32-bit word (32 for 0); ES 3.00 has no findMSB.
// Algorithm: binary search over 16, 8, 4, 2, 1 bit halves, each step by selects (no branch)
// Source: H. S. Warren, Hacker's Delight, 2nd ed., 2012, section 5-3 (nlz, binary search)
// Bound: exact
// Flops: 0 (about 16 integer operations)
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

// ex_sub_to_float_bits: the float bits of RN_float(a - b) for binary64 patterns a, b (uvec2(low, high)), rounded once.
// Algorithm: NaN and infinities first; b's sign flipped; the larger magnitude x, the other y; the 53-bit significands shifted left 10 (bit 62 the top), y's jam-shifted right by the exponent difference; added or subtracted exactly in 64 bits; normalised to bit 63; 24 bits kept (fewer below float's normal range), one round bit and a jammed sticky bit; ties to even; a carry runs into the exponent up to infinity
// Source: IEEE 754-2019, 4.3.1 and 5.4.1; Hauser, SoftFloat 3e, 2018 (jamming alignment); Muller et al., Handbook of Floating-Point Arithmetic, 2018, 7.2
// Bound: 0.5 ulp of float (correctly rounded from the exact difference)
// Flops: 0 (about 80 integer operations)
// Range: every pair of doubles; a NaN operand gives a quiet NaN with its sign, Inf - Inf the default NaN 0xFFC00000
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

// ex_bits: the binary64 pattern of a mode-exact double as uvec2(low word, high word), the order of unpackDouble2x32.
// Algorithm: member reorder
// Source: GLSL 4.60 specification, 2017, 8.4 (unpackDouble2x32 word order)
// Bound: exact
// Flops: 0
uvec2 ex_bits(df_double a) {
  return uvec2(a.lo, a.hi);
}

// ex_sub_to_float: float(a - b) of two mode rte-exact doubles: the exact difference rounded once to float.
// Algorithm: ex_sub_to_float_bits on the patterns
// Source: IEEE 754-2019, 4.3.1 and 5.4.1 (one rounding of the exact result)
// Bound: 0.5 ulp of float (correctly rounded from the exact difference)
// Flops: 0 (integer arithmetic)
float ex_sub_to_float(df_double a, df_double b) {
  return uintBitsToFloat(ex_sub_to_float_bits(ex_bits(a), ex_bits(b)));
}

// ex_sub_to_float: float(a - b) of two mode rte-exact doubles: the exact difference rounded once to float.
// Algorithm: ex_sub_to_float_bits on the patterns
// Source: IEEE 754-2019, 4.3.1 and 5.4.1 (one rounding of the exact result)
// Bound: 0.5 ulp of float (correctly rounded from the exact difference)
// Flops: 0 (integer arithmetic)
// (width 3: the width-1 ex_sub_to_float applied to each component, in a loop)
vec3 ex_sub_to_float(df_dvec3 a, df_dvec3 b) {
  vec3 per_r;
  for (int per_k = 0; per_k < 3; ++per_k) {
    int per_i = 2 - per_k;
    float per_c = ex_sub_to_float(df_double(a.hi[per_i], a.lo[per_i]), df_double(b.hi[per_i], b.lo[per_i]));
    per_r[per_i] = per_c;
  }
  return per_r;
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

// ex_to_float: float(a) (mode exact), rounded to nearest even.
// Algorithm: ex_to_float_bits
// Source: IEEE 754-2019, 5.4.2
// Bound: 0.5 ulp (correctly rounded)
// Flops: 0 (integer arithmetic)
float ex_to_float(df_double a) {
  return uintBitsToFloat(ex_to_float_bits(ex_bits(a)));
}

layout(location = 0) in uvec4 position_xy;
layout(location = 1) in uvec2 position_z;
df_dvec3 position;
uniform uvec4 eye_xy;
uniform uvec2 eye_z;
df_dvec3 eye;
uniform mat4 viewProj;
uniform uvec2 scale;
df_double scale_value;


void main()
{
  position = df_dvec3(uvec3(position_xy.yw, position_z.y), uvec3(position_xy.xz, position_z.x));
  eye = df_dvec3(uvec3(eye_xy.yw, eye_z.y), uvec3(eye_xy.xz, eye_z.x));
  scale_value = df_double(scale.y, scale.x);
  vec3 p = ex_sub_to_float(position, eye);
  float s = ex_sub_to_float(df_double(position.hi.x, position.lo.x), df_double(eye.hi.x, eye.lo.x));
  gl_Position = viewProj * vec4(p * ex_to_float(scale_value) + s, 1.0);
}
