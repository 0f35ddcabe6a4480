#include "verify/inputs.hpp"

#include <algorithm>
#include <cmath>

#include "doublet/split.hpp"

namespace doublet::verify {

double representable(double x, bool is_double) {
  return is_double ? join(split(x)) : static_cast<double>(static_cast<float>(x));
}

double integer_value(double x, char scalar) {
  if (scalar == 'b') return x != 0 ? 1 : 0;
  const double r = std::nearbyint(x);
  return scalar == 'u' ? std::max(r, 0.0) : r;
}

double InputGenerator::draw(const InputSpec& spec) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double lo = spec.lo.value_or(0x1p-20), hi = spec.hi.value_or(0x1p20);
  if (!spec.lo) {  // default: magnitude log-uniform in [lo, hi], random sign
    const double m = std::exp2(std::log2(lo) + unit(rng_) * (std::log2(hi) - std::log2(lo)));
    return unit(rng_) < 0.5 ? -m : m;
  }
  if (lo > 0 || hi < 0) {
    const double a = std::fabs(lo), b = std::fabs(hi);
    const double m = std::exp2(std::log2(a) + unit(rng_) * (std::log2(b) - std::log2(a)));
    return hi < 0 ? -m : m;
  }
  return lo + unit(rng_) * (hi - lo);
}

double InputGenerator::next(const InputSpec& spec, bool is_double, uint64_t index) {
  const double x = spec.values.empty() ? draw(spec) : spec.values[index % spec.values.size()];
  const double kept = binary64_ && is_double ? x : representable(x, is_double);
  if (std::isfinite(x) && std::isinf(kept)) ++beyond_float_range_;
  return kept;
}

std::string beyond_float_range_note(uint64_t count) {
  if (count == 0) return {};
  return std::to_string(count) +
         " input value(s) beyond float range (|x| > 3.4028235e38) were given to both shaders as +-Inf: "
         "a float-float or float input cannot hold them (keep ranges within +-3.4e38 to compare finite values)";
}

}  // namespace doublet::verify
