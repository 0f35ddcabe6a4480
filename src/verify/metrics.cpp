#include "verify/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace doublet::verify {

ValueClass classify(double x) {
  if (std::isnan(x)) return ValueClass::Nan;
  if (std::isinf(x)) return x > 0 ? ValueClass::PosInf : ValueClass::NegInf;
  if (x == 0) return std::signbit(x) ? ValueClass::NegZero : ValueClass::PosZero;
  return ValueClass::Finite;
}

double correct_bits(double got, double want, double abs_floor, double* rel_err) {
  *rel_err = 0;
  const bool got_finite = std::isfinite(got), want_finite = std::isfinite(want);
  if (!got_finite || !want_finite) {
    const bool same = (std::isnan(got) && std::isnan(want)) || got == want;
    *rel_err = same ? 0 : std::numeric_limits<double>::infinity();
    return same ? kMaxBits : 0;
  }
  if (got == want) return kMaxBits;
  const double rel = std::fabs(got - want) / std::max(std::fabs(want), abs_floor);
  *rel_err = rel;
  return std::clamp(-std::log2(rel), 0.0, kMaxBits);
}

std::string hex(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

StatsBuilder::StatsBuilder(std::string name, std::string type, double abs_floor) {
  stats_.name = std::move(name);
  stats_.type = std::move(type);
  stats_.abs_floor = abs_floor;
}

void StatsBuilder::add(double got, double want, uint64_t sample) {
  double rel = 0;
  const double bits = correct_bits(got, want, stats_.abs_floor, &rel);
  if (classify(got) != classify(want)) ++stats_.class_mismatches;
  uint64_t got_bits, want_bits;
  std::memcpy(&got_bits, &got, 8);
  std::memcpy(&want_bits, &want, 8);
  if (got_bits != want_bits) ++(std::isnan(got) && std::isnan(want) ? stats_.nan_payloads : stats_.differing);
  // Absolute error: |got - want| between finite values; infinite where only one side is finite
  // or the infinities differ (an overflow where native is finite); NaN against NaN is no error.
  if (std::isfinite(got) && std::isfinite(want))
    stats_.max_abs_err = std::max(stats_.max_abs_err, std::fabs(got - want));
  else if (got != want && !(std::isnan(got) && std::isnan(want)))
    stats_.max_abs_err = std::numeric_limits<double>::infinity();
  if (stats_.samples == 0 || bits < stats_.min_bits) {
    stats_.min_bits = bits;
    stats_.worst_sample = sample;
    stats_.worst_got = got;
    stats_.worst_want = want;
  }
  ++stats_.samples;
  stats_.got_values.push_back(got);
  stats_.want_values.push_back(want);
  rel_.push_back(rel);
  bits_.push_back(bits);
}

namespace {
// The q-quantile (0..1) by nearest rank; the vector is partially reordered.
double quantile(std::vector<double>& v, double q) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}
}  // namespace

OutputStats StatsBuilder::finish() {
  if (!rel_.empty()) {
    stats_.max_rel_err = *std::max_element(rel_.begin(), rel_.end());
    stats_.p99_rel_err = quantile(rel_, 0.99);
    stats_.median_rel_err = quantile(rel_, 0.5);
    stats_.p1_bits = quantile(bits_, 0.01);
  }
  return stats_;
}

}  // namespace doublet::verify
