#version 310 es
precision highp float;
precision highp int;
layout(local_size_x = 1, local_size_y = 1, local_size_z = 1) in;

// doublet float-float runtime: 4 functions from rules/*.glsl, guard: uniform df_guard
struct df_double { float hi; float lo; };
uniform highp float df_guard[2];  // never set: GL zero-fills it at link

// df_neg: -a, exact, signed zeros included (the Uniform guard subtracts its +0: -0 - 0 = -0).
// Algorithm: sign flip of both words
// Source: Dekker 1971 (trivial); JMP section 1
// Bound: exact
// Flops: 2
df_double df_neg(df_double a) {
  float h = (-a.hi);
  float l = (-a.lo);
  return df_double(h, l);
}

// df_lt: a < b.
// Algorithm: lexicographic comparison of (hi, lo)
// Source: JMP 2017, Definition 1.4 (double-word uniqueness); Knuth TAOCP vol. 2, 4.2.2
// Bound: exact
// Flops: 0 (3 comparisons)
bool df_lt(df_double a, df_double b) {
  return any(bvec2(a.hi < b.hi, all(bvec2(a.hi == b.hi, a.lo < b.lo))));
}

// df_select: c ? a : b per component, without a branch (mix on a boolean selector, a
// ternary on ES 1.00). Every rule with a data-dependent choice between pairs goes through it: an
// early return or a short-circuit inside a rule that is inlined into a loop body multiplies the
// control flow the browser's shader compilers have to handle (docs/performance.md, "Compile time in
// the browser").
// Algorithm: selection
// Source: GLSL 4.60 (2019) section 8.3 (mix with genBType)
// Bound: exact
// Flops: 0
df_double df_select(bool c, df_double a, df_double b) {
  float h = (mix(b.hi, a.hi, c));
  float l = (mix(b.lo, a.lo, c));
  return df_double(h, l);
}

// df_min: component-wise min(a, b) = b < a ? b : a (GLSL definition).
// Algorithm: lexicographic compare (df_lt) and select; widths 2-4 per component
// Source: GLSL ES 3.20 section 8.3 (min); JMP 2017, Definition 1.4
// Bound: exact
// Flops: 0 (3 comparisons per component)
df_double df_min(df_double a, df_double b) {
  bool take = df_lt(b, a);
  df_double r = df_select(take, b, a);
  return r;
}

layout(std430, binding = 0) buffer B {
  df_double lowest;
  df_double highest;
  df_double x;
};

df_double positive_infinity();

df_double positive_infinity()
{
  return df_double(uintBitsToFloat(0x7F800000u) - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]);
}

void main()
{
  lowest = df_neg(positive_infinity());
  highest = df_min(x, df_double(uintBitsToFloat(0x7F800000u) - df_guard[int(df_guard[1])], 0.0 + df_guard[int(df_guard[1])]));
}
