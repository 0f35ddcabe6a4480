// targets: es310 es320 glsl450
#version 450
// Mode exact for one function of a df64 shader (src/lower/exact_functions.cpp): harmonic() runs
// in binary64 words (ex_double, rules/exact.glsl's ex_* rules), the rest in float-float; the call
// converts its argument (df_to_exact) and its result (df_from_exact). A long sum keeps binary64's
// accuracy inside the exact function; in df64 it loses about 6 bits over 3000 terms.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { double x[]; };
layout(std430, binding = 1) writeonly buffer Out { double sums[]; };

#pragma doublet mode(exact)
double harmonic(double scale, int terms) {
  double s = 0.0lf;
  for (int k = 1; k <= terms; ++k) s += scale / double(k);
  return s;
}

#pragma doublet mode(exact)
dvec2 both_ends(dvec2 v) { return dvec2(harmonic(v.x, 2), v.y * v.y); }

void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec2 e = both_ends(dvec2(x[i], 0.5lf));
  sums[i] = harmonic(x[i], 3000) * 2.0lf + e.y * e.x;
}
