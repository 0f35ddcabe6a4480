// Closed intervals of reals for doublet's range analysis (docs/plan.md). Endpoints may be ±inf;
// an operation whose endpoint products are undefined (0 × inf) returns the whole line. Endpoints
// are computed in double without outward rounding: the analysis needs magnitudes to a few bits,
// not enclosures to the last ulp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace doublet::plan {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double lo = -kInf, hi = kInf;

  static Interval point(double x) { return {x, x}; }
  static Interval top() { return {}; }
  double mag() const { return std::max(std::fabs(lo), std::fabs(hi)); }  // max |x|
  double mig() const { return lo > 0 ? lo : hi < 0 ? -hi : 0; }        // min |x|
  bool bounded() const { return std::isfinite(lo) && std::isfinite(hi); }
  bool contains_zero() const { return lo <= 0 && hi >= 0; }
  bool operator==(const Interval&) const = default;
};

inline Interval join(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }
inline Interval meet(Interval a, Interval b) {  // empty meets keep `a` (a relation cannot empty a range)
  Interval m{std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
  return m.lo <= m.hi ? m : a;
}

inline Interval sane(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return Interval::top();
  return {lo, hi};
}
inline Interval operator+(Interval a, Interval b) { return sane(a.lo + b.lo, a.hi + b.hi); }
inline Interval operator-(Interval a) { return {-a.hi, -a.lo}; }
inline Interval operator-(Interval a, Interval b) { return a + (-b); }
inline Interval operator*(Interval a, Interval b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  for (double x : p)
    if (std::isnan(x)) return Interval::top();
  return {*std::min_element(p, p + 4), *std::max_element(p, p + 4)};
}
inline Interval reciprocal(Interval b) {
  if (b.contains_zero()) return Interval::top();
  return {1 / b.hi, 1 / b.lo};
}
inline Interval operator/(Interval a, Interval b) { return a * reciprocal(b); }
inline Interval abs(Interval a) { return a.lo >= 0 ? a : a.hi <= 0 ? -a : Interval{0, a.mag()}; }
inline Interval square(Interval a) { Interval m = abs(a); return {m.lo * m.lo, m.hi * m.hi}; }
inline Interval sqrt(Interval a) { return {std::sqrt(std::max(a.lo, 0.0)), std::sqrt(std::max(a.hi, 0.0))}; }

// Float's largest finite value, and its smallest normal: below it a vertex/fragment stage may
// flush to zero (so a value under 2^-126 may lose all of itself).
inline constexpr double kFloatMax = 0x1.fffffep127;
inline constexpr double kFloatMinNormal = 0x1p-126;

// Half the spacing of floats at magnitude m, 2^(floor(log2 m) - 24): the largest error of
// rounding any |x| <= m to float (round to nearest); infinite beyond float's range (the value
// overflows), at least min(m, 2^-126) (flushed subnormals).
inline double float_half_ulp(double m) {
  if (!(m > 0)) return 0;
  if (!std::isfinite(m) || m > kFloatMax) return kInf;
  return std::max(std::ldexp(1.0, std::ilogb(m) - 24), std::min(m, kFloatMinNormal));
}

// Float-float's absolute error at magnitude m for a relative bound `rel`: float's exponent range
// (beyond FLT_MAX hi overflows), and below 2^-102 lo turns subnormal and may flush.
inline double float_float_error(double m, double rel) {
  if (!(m > 0)) return 0;
  if (!std::isfinite(m) || m > kFloatMax) return kInf;
  return std::max(rel * m, std::min(m, kFloatMinNormal));
}

// Half an ulp of binary64 at magnitude m (mode exact: every operation correctly rounded);
// subnormals are kept, so the floor is the smallest subnormal (its half is not a double).
inline double double_half_ulp(double m) {
  if (!(m > 0)) return 0;
  if (!std::isfinite(m)) return kInf;
  return std::max(std::ldexp(1.0, std::ilogb(m) - 53), 0x1p-1074);
}

}  // namespace doublet::plan
