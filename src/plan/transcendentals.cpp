// Interval images, slopes and error bounds of the transcendental built-ins (transcendentals.hpp).
// Arguments: a = the first argument, b = the second (pow's exponent; for atan(y, x), a = y, b = x).
#include "plan/transcendentals.hpp"

#include <cmath>
#include <map>

namespace doublet::plan {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kU2 = 0x1p-48;       // u^2, u = 2^-24
constexpr double kTrigLimit = 0x1p20;  // docs/transcendentals.md: bounds hold with either guard

bool atan2(const std::string& f, int arity) { return f == "atan" && arity == 2; }

// Half an ulp and one ulp of a float of magnitude m.
double ulp(double m) { return 2 * float_half_ulp(m); }

Interval increasing(double (*g)(double), Interval a) { return sane(g(a.lo), g(a.hi)); }

// sin over [lo, hi]: endpoints, plus +-1 where a crest or trough lies inside.
Interval sin_range(Interval a) {
  if (!a.bounded()) return {-1, 1};
  if (a.hi - a.lo >= 2 * kPi) return {-1, 1};
  double lo = std::min(std::sin(a.lo), std::sin(a.hi)), hi = std::max(std::sin(a.lo), std::sin(a.hi));
  const double crest = std::ceil((a.lo - kPi / 2) / (2 * kPi)) * 2 * kPi + kPi / 2;
  const double trough = std::ceil((a.lo + kPi / 2) / (2 * kPi)) * 2 * kPi - kPi / 2;
  if (crest <= a.hi) hi = 1;
  if (trough <= a.hi) lo = -1;
  return {lo, hi};
}
Interval cos_range(Interval a) { return sin_range({a.lo + kPi / 2, a.hi + kPi / 2}); }

Interval tan_range(Interval a) {
  if (!a.bounded()) return Interval::top();
  // A pole (k + 1/2) pi inside: unbounded.
  const double pole = std::ceil(a.lo / kPi - 0.5) * kPi + kPi / 2;
  if (pole <= a.hi) return Interval::top();
  return {std::tan(a.lo), std::tan(a.hi)};
}

// The angle of the points of the box (x, y): continuous, so extremes at corners, unless the box
// touches the branch cut (x <= 0, y = 0) or the origin.
Interval atan2_range(Interval y, Interval x) {
  const bool cut = x.lo <= 0 && y.contains_zero();
  if (cut || !x.bounded() || !y.bounded()) {
    if (x.lo > 0) return {-kPi / 2, kPi / 2};
    return {-kPi, kPi};
  }
  double lo = kInf, hi = -kInf;
  for (double yy : {y.lo, y.hi})
    for (double xx : {x.lo, x.hi}) {
      lo = std::min(lo, std::atan2(yy, xx));
      hi = std::max(hi, std::atan2(yy, xx));
    }
  return {lo, hi};
}

Interval log_range(Interval a, double (*g)(double)) {
  if (a.hi <= 0) return Interval::top();  // NaN or -inf only
  return sane(a.lo > 0 ? g(a.lo) : -kInf, g(a.hi));
}

Interval pow_range(Interval a, Interval b) {
  if (a.lo <= 0) return Interval::top();
  const Interval e = b * log_range(a, std::log);
  return sane(std::exp(e.lo), std::exp(e.hi));
}

Interval cosh_range(Interval a) { return sane(std::cosh(abs(a).lo), std::cosh(a.mag())); }

}  // namespace

bool is_transcendental(const std::string& f) {
  static const char* names[] = {"exp", "exp2", "log", "log2", "pow", "sin", "cos", "tan",
                                "asin", "acos", "atan", "sinh", "cosh", "tanh"};
  for (const char* n : names)
    if (f == n) return true;
  return false;
}

Interval transcendental_range(const std::string& f, int arity, Interval a, Interval b) {
  if (f == "sin") return sin_range(a);
  if (f == "cos") return cos_range(a);
  if (f == "tan") return tan_range(a);
  if (f == "asin" || f == "acos") {
    const Interval c{std::max(a.lo, -1.0), std::min(a.hi, 1.0)};
    if (c.lo > c.hi) return Interval::top();
    return f == "asin" ? Interval{std::asin(c.lo), std::asin(c.hi)} : Interval{std::acos(c.hi), std::acos(c.lo)};
  }
  if (atan2(f, arity)) return atan2_range(a, b);
  if (f == "atan") return increasing(std::atan, a);
  if (f == "exp") return increasing(std::exp, a);
  if (f == "exp2") return increasing(std::exp2, a);
  if (f == "log") return log_range(a, std::log);
  if (f == "log2") return log_range(a, std::log2);
  if (f == "pow") return pow_range(a, b);
  if (f == "sinh") return increasing(std::sinh, a);
  if (f == "cosh") return cosh_range(a);
  if (f == "tanh") return increasing(std::tanh, a);
  return Interval::top();
}

double transcendental_slope(const std::string& f, int arity, size_t i, Interval a, Interval b) {
  const Interval r = transcendental_range(f, arity, a, b);
  if (f == "sin") return cos_range(a).mag();
  if (f == "cos") return sin_range(a).mag();
  if (f == "tan") return 1 + r.mag() * r.mag();
  if (f == "asin" || f == "acos") return a.mag() < 1 ? 1 / std::sqrt(1 - a.mag() * a.mag()) : kInf;
  if (atan2(f, arity)) {  // |d/dy| = |x| / r^2 and |d/dx| = |y| / r^2, both <= 1 / r
    const double r_min = std::hypot(a.mig(), b.mig());
    return r_min > 0 ? 1 / r_min : kInf;
  }
  if (f == "atan") return 1 / (1 + a.mig() * a.mig());
  if (f == "exp") return r.hi;                    // e^x, largest at the top
  if (f == "exp2") return std::log(2.0) * r.hi;
  if (f == "sinh") return cosh_range(a).hi;       // cosh
  if (f == "cosh") return std::sinh(a.mag());     // |sinh|
  if (f == "log") return a.mig() > 0 ? 1 / a.mig() : kInf;
  if (f == "log2") return a.mig() > 0 ? 1 / (a.mig() * std::log(2.0)) : kInf;
  if (f == "tanh") return 1 / (std::cosh(a.mig()) * std::cosh(a.mig()));
  if (f == "pow") {  // d/dx = y x^y / x, d/dy = log(x) x^y
    if (a.lo <= 0) return kInf;
    return i == 0 ? b.mag() * r.mag() / a.mig() : log_range(a, std::log).mag() * r.mag();
  }
  return kInf;
}

double transcendental_error_df64(const std::string& f, int arity, Interval a, Interval b, Interval result) {
  const double m = result.mag();
  if (!result.bounded() || !a.bounded() || (arity == 2 && !b.bounded())) return kInf;
  // Float-float holds float's exponent range only: arguments or results beyond it overflow,
  // positive arguments below float's smallest normal may flush to zero (log(0) = -inf).
  if (a.mag() > kFloatMax || (arity == 2 && b.mag() > kFloatMax) || m > kFloatMax) return kInf;
  if ((f == "log" || f == "log2" || f == "pow") && a.lo < kFloatMinNormal) return kInf;
  auto relative = [&](double c) { return c * kU2 * m; };
  if (f == "exp") return a.lo >= -70.7 && a.hi <= 88.72 ? relative(10) : kInf;
  if (f == "exp2") return a.lo >= -102 && a.hi < 128 ? relative(12) : kInf;
  if (f == "log" || f == "log2") return a.lo > 0 ? relative(f == "log" ? 28 : 37) : kInf;
  if (f == "pow") {
    if (a.lo <= 0 || result.lo < 0x1p-126) return kInf;
    const double t = (b * log_range(a, std::log)).mag();  // |y log x|
    return relative(40 + 31 * t);
  }
  if (f == "sin" || f == "cos" || f == "tan") {
    const double x = a.mag();
    if (x > kTrigLimit) return kInf;
    return f == "tan" ? relative(40) + x * 0x1p-96 * (1 + m * m) : relative(20) + x * 0x1p-96;
  }
  if (f == "atan") return relative(70);
  if (f == "asin" || f == "acos") return a.lo >= -1 && a.hi <= 1 ? relative(75) : kInf;
  if (f == "sinh" || f == "cosh") return a.mag() <= 88.72 ? relative(f == "sinh" ? 50 : 20) : kInf;
  if (f == "tanh") return relative(50);
  return kInf;
}

double transcendental_error_exact(const std::string& f, int arity, Interval a, Interval b, Interval result) {
  const double m = result.mag();
  if (!result.bounded() || !a.bounded() || (arity == 2 && !b.bounded())) return kInf;
  // The bridge adds 2u^2 (first-order residual correction) and one binary64 rounding.
  auto bridged = [&](double rule) { return rule + 2 * kU2 * m + double_half_ulp(m); };
  // log/log2 scale any positive binary64 into float's range; atan and atan(y, x) take every pair.
  if (f == "log" || f == "log2") return a.lo > 0 ? bridged((f == "log" ? 28 : 37) * kU2 * m) : kInf;
  if (f == "atan") return bridged(70 * kU2 * m);
  const double rule = transcendental_error_df64(f, arity, a, b, result);
  return std::isinf(rule) ? kInf : bridged(rule);
}

double transcendental_error_float(const std::string& f, int arity, Interval a, Interval b, Interval result) {
  const double m = result.mag();
  if (!result.bounded() || !a.bounded() || (arity == 2 && !b.bounded())) return kInf;
  constexpr double kTrig = 0x1p-11;  // sin/cos, absolute, on [-pi, pi]
  auto log_error = [](Interval x, double m_log) {  // 2^-21 absolute inside [0.5, 2], 3 ulp outside
    double e = 0;
    if (x.lo < 2 && x.hi > 0.5) e = std::max(e, 0x1p-21);
    if (x.lo < 0.5 || x.hi > 2) e = std::max(e, 3 * ulp(m_log));
    return e;
  };
  if (f == "sin" || f == "cos") return a.lo >= -kPi && a.hi <= kPi ? kTrig : kInf;
  if (f == "tan") {  // sin/cos with both errors: |ds / c| + |s dc / c^2|, c^2 >= 1 / (1 + tan^2)
    if (a.lo < -kPi || a.hi > kPi) return kInf;
    const double sec2 = 1 + m * m;
    return kTrig * (std::sqrt(sec2) + m * sec2) + 3 * ulp(m);
  }
  if (f == "atan" || f == "asin" || f == "acos") return 4096 * ulp(m);  // asin, acos: via atan(y, x)
  if (f == "exp" || f == "exp2") return (3 + 2 * a.mag()) * ulp(m);
  if (f == "log" || f == "log2") return a.lo > 0 ? log_error(a, m) : kInf;
  if (f == "pow") {  // exp2(t), t = y log2 x: the error of t becomes a relative error of the result
    if (a.lo <= 0) return kInf;
    const Interval l2 = log_range(a, std::log2);
    const double t = (b * l2).mag();
    const double dt = b.mag() * log_error(a, l2.mag()) + ulp(t) / 2;
    return m * std::log(2.0) * dt + (3 + 2 * t) * ulp(m);
  }
  if (f == "sinh" || f == "cosh") {  // (exp(x) -+ exp(-x)) / 2
    const double e = std::exp(a.mag());
    return (3 + 2 * a.mag()) * ulp(e) + ulp(m);
  }
  if (f == "tanh") {  // sinh / cosh: both errors relative to cosh >= 1
    const double e = std::exp(a.mag());
    return 2 * ((3 + 2 * a.mag()) * ulp(e) + ulp(e)) / std::cosh(a.mig()) + 3 * ulp(m);
  }
  return kInf;
}

double transcendental_flops_df64(const std::string& f, int arity) {
  static const std::map<std::string, double> flops{
      {"exp", 460},  {"exp2", 431}, {"log", 380},  {"log2", 369},  {"pow", 869},  {"sin", 524},  {"cos", 524},
      {"tan", 820},  {"asin", 674}, {"acos", 674}, {"atan", 565},  {"sinh", 548}, {"cosh", 525}, {"tanh", 528}};
  if (atan2(f, arity)) return 591;
  auto it = flops.find(f);
  return it == flops.end() ? 20 : it->second;
}

}  // namespace doublet::plan
