#include "bench/transcendental_kernels.hpp"

#include <cmath>
#include <random>

#include "bench/kernels.hpp"

namespace doublet::bench {

const char* variant_name(TranscendentalVariant v) {
  switch (v) {
    case TranscendentalVariant::Fp32: return "fp32";
    case TranscendentalVariant::Df64: return "df64";
    case TranscendentalVariant::Native: return "native";
    case TranscendentalVariant::Luma: return "luma.gl";
  }
  return "?";
}

const std::vector<std::string>& transcendental_functions() {
  static const std::vector<std::string> f{"exp", "log", "sin", "cos", "tan"};
  return f;
}

bool is_trig(const std::string& f) { return f == "sin" || f == "cos" || f == "tan"; }

// Written here, for the benchmark, from the algorithms of rules/transcendental.glsl (same
// reductions, same polynomial degrees) in native fp64; the split constants ln 2 = LN2_HI + LN2_LO
// and pi/2 = P1 + P2 + P3 (33-bit words, so k * word is exact for |k| < 2^20) are those of
// fdlibm (Sun Microsystems, 1993; e_exp.c, e_rem_pio2.c). Coefficients are 1/n! and 1/(2n+1)
// rounded to double.
const char* const kNativeLibrary = R"(
// e^x: k = round(x / ln 2), r = x - k ln 2 (two words), Taylor to r^14, times 2^k.
double nat_exp(double x) {
  double k = floor(x * 1.4426950408889634lf + 0.5lf);
  double r = (x - k * 6.93147180369123816490e-01lf) - k * 1.90821492927058770002e-10lf;
  double p = 1.1470745597729725e-11lf;
  p = p * r + 1.6059043836821613e-10lf;
  p = p * r + 2.08767569878681e-09lf;
  p = p * r + 2.505210838544172e-08lf;
  p = p * r + 2.755731922398589e-07lf;
  p = p * r + 2.7557319223985893e-06lf;
  p = p * r + 2.48015873015873e-05lf;
  p = p * r + 0.0001984126984126984lf;
  p = p * r + 0.001388888888888889lf;
  p = p * r + 0.008333333333333333lf;
  p = p * r + 0.041666666666666664lf;
  p = p * r + 0.16666666666666666lf;
  p = p * r + 0.5lf;
  p = p * r + 1.0lf;
  p = p * r + 1.0lf;
  return ldexp(p, int(k));
}

// log x = e ln 2 + 2 atanh(s), x = m 2^e with m in [sqrt(1/2), sqrt(2)), s = (m - 1)/(m + 1),
// the atanh series to s^21.
double nat_log(double x) {
  int e;
  double m = frexp(x, e);
  if (m < 0.70710678118654752lf) {
    m = m * 2.0lf;
    e = e - 1;
  }
  double s = (m - 1.0lf) / (m + 1.0lf);
  double w = s * s;
  double p = 0.047619047619047616lf;
  p = p * w + 0.05263157894736842lf;
  p = p * w + 0.058823529411764705lf;
  p = p * w + 0.06666666666666667lf;
  p = p * w + 0.07692307692307693lf;
  p = p * w + 0.09090909090909091lf;
  p = p * w + 0.1111111111111111lf;
  p = p * w + 0.14285714285714285lf;
  p = p * w + 0.2lf;
  p = p * w + 0.3333333333333333lf;
  p = p * w + 1.0lf;
  double fe = double(e);
  return fe * 6.93147180369123816490e-01lf + (fe * 1.90821492927058770002e-10lf + 2.0lf * s * p);
}

// r = x - k pi/2 (three 33-bit words), q = k mod 4.
double nat_reduce(double x, out int q) {
  double k = floor(x * 0.6366197723675814lf + 0.5lf);
  double r = ((x - k * 1.57079632673412561417e+00lf) - k * 6.07710050630396597660e-11lf) - k * 2.02226624871116645580e-21lf;
  q = int(k - 4.0lf * floor(k * 0.25lf));
  return r;
}

// sin r, Taylor to r^17.
double nat_sin_kernel(double r) {
  double w = r * r;
  double p = 2.8114572543455206e-15lf;
  p = p * w - 7.647163731819816e-13lf;
  p = p * w + 1.6059043836821613e-10lf;
  p = p * w - 2.505210838544172e-08lf;
  p = p * w + 2.7557319223985893e-06lf;
  p = p * w - 0.0001984126984126984lf;
  p = p * w + 0.008333333333333333lf;
  p = p * w - 0.16666666666666666lf;
  return r + r * w * p;
}

// cos r, Taylor to r^18.
double nat_cos_kernel(double r) {
  double w = r * r;
  double p = -1.5619206968586225e-16lf;
  p = p * w + 4.779477332387385e-14lf;
  p = p * w - 1.1470745597729725e-11lf;
  p = p * w + 2.08767569878681e-09lf;
  p = p * w - 2.755731922398589e-07lf;
  p = p * w + 2.48015873015873e-05lf;
  p = p * w - 0.001388888888888889lf;
  p = p * w + 0.041666666666666664lf;
  p = p * w - 0.5lf;
  return 1.0lf + w * p;
}

double nat_sin_quadrant(double r, int q) {
  double v = (q & 1) == 0 ? nat_sin_kernel(r) : nat_cos_kernel(r);
  return (q & 2) != 0 ? -v : v;
}

double nat_sin(double x) {
  int q;
  double r = nat_reduce(x, q);
  return nat_sin_quadrant(r, q);
}

double nat_cos(double x) {
  int q;
  double r = nat_reduce(x, q);
  return nat_sin_quadrant(r, (q + 1) & 3);
}

double nat_tan(double x) {
  int q;
  double r = nat_reduce(x, q);
  double s = nat_sin_kernel(r);
  double c = nat_cos_kernel(r);
  return (q & 1) == 0 ? s / c : -c / s;
}
)";

namespace {

constexpr const char* kBuffers =
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer Inputs { vec4 inp[]; };\n";

// One chain step per syntax: doubles (GLSL built-in names, lowered by doublet), native (nat_*),
// luma.gl (vec2 functions).
std::string chain_step(const std::string& f, TranscendentalVariant v) {
  if (v == TranscendentalVariant::Luma) {
    if (f == "exp") return "x = exp_fp64(-x);";
    if (f == "log") return "x = log_fp64(sum_fp64(x, vec2(2.0, 0.0)));";
    if (f == "sin") return "x = sum_fp64(sin_fp64(x), vec2(1.0, 0.0));";
    if (f == "cos") return "x = cos_fp64(x);";
    return "x = sub_fp64(vec2(1.0, 0.0), tan_fp64(x * 0.5));";
  }
  const std::string p = v == TranscendentalVariant::Native ? "nat_" : "";
  if (f == "exp") return "x = " + p + "exp(-x);";
  if (f == "log") return "x = " + p + "log(x + 2.0lf);";
  if (f == "sin") return "x = " + p + "sin(x) + 1.0lf;";
  if (f == "cos") return "x = " + p + "cos(x);";
  return "x = 1.0lf - " + p + "tan(x * 0.5lf);";
}

std::string header(TranscendentalVariant v, const std::string& luma_glsl) {
  if (v == TranscendentalVariant::Luma)
    return "#version 310 es\nprecision highp float;\nprecision highp int;\n" + luma_glsl + "\n";
  return std::string("#version 450\n") + (v == TranscendentalVariant::Native ? kNativeLibrary : "");
}

}  // namespace

std::string chain_source(const std::string& f, TranscendentalVariant v, int steps, const std::string& luma_glsl) {
  const bool luma = v == TranscendentalVariant::Luma;
  std::string unrolled;
  for (int u = 0; u < kUnroll; ++u) unrolled += "    " + chain_step(f, v) + "\n";
  return header(v, luma_glsl) + kBuffers +
         "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n" +
         (luma ? "  vec2 x = vec2(inp[i].x, 0.0);\n" : "  double x = double(inp[i].x);\n") +
         "  for (int k = 0; k < " + std::to_string(rounded_steps(steps) / kUnroll) + "; ++k) {\n" + unrolled +
         "  }\n" + (luma ? "  outp[i] = vec4(x, 0.0, 0.0);\n" : "  outp[i] = vec4(float(x));\n") + "}\n";
}

std::string accuracy_source(const std::string& f, TranscendentalVariant v, const std::string& luma_glsl) {
  std::string s = header(v, luma_glsl) + kBuffers;
  if (v == TranscendentalVariant::Luma)
    return s + "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n"
               "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  vec2 z = " + f + "_fp64(inp[i].xy);\n"
               "  outp[i] = vec4(z, 0.0, 0.0);\n}\n";
  if (v == TranscendentalVariant::Native)
    return s + "layout(std430, binding = 1) writeonly buffer Outputs { uvec4 outp[]; };\n"
               "void main() {\n  uint i = gl_GlobalInvocationID.x;\n"
               "  double z = nat_" + f + "(double(inp[i].x) + double(inp[i].y));\n"
               "  outp[i] = uvec4(unpackDouble2x32(z), 0u, 0u);\n}\n";
  return s + "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n"
             "void main() {\n  uint i = gl_GlobalInvocationID.x;\n"
             "  double z = " + f + "(double(inp[i].x) + double(inp[i].y));\n"
             "  float h = float(z);\n  outp[i] = vec4(h, float(z - double(h)), 0.0, 0.0);\n}\n";
}

const char* domain_name(const std::string& f, Domain d) {
  if (d == Domain::Wide) return "|x| in [2^-10, 2^20]";
  if (f == "exp") return "[-70, 88]";
  if (f == "log") return "[2^-60, 2^60]";
  return "[-pi, pi]";
}

std::vector<float> accuracy_inputs(const std::string& f, Domain d, int count) {
  std::mt19937_64 rng(20261125);
  auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1p-53; };
  std::vector<float> v;
  v.reserve(static_cast<size_t>(count) * 2);
  for (int i = 0; i < count; ++i) {
    double x;
    if (d == Domain::Wide) x = std::exp2(-10 + 30 * unit()) * ((rng() & 1) ? -1 : 1);
    else if (f == "exp") x = -70 + 158 * unit();
    else if (f == "log") x = std::exp2(-60 + 120 * unit());
    else x = (2 * unit() - 1) * 3.141592653589793;
    const float hi = static_cast<float>(x);
    v.push_back(hi);
    v.push_back(static_cast<float>(x - hi));
  }
  return v;
}

long double reference(const std::string& f, long double x) {
  if (f == "exp") return std::exp(x);
  if (f == "log") return std::log(x);
  if (f == "sin") return std::sin(x);
  if (f == "cos") return std::cos(x);
  return std::tan(x);
}

}  // namespace doublet::bench
