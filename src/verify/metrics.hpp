// Error statistics of one output component: lowered result `got` against native fp64 `want`.
#pragma once

#include <cmath>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace doublet::verify {

// Correct bits are capped here: the comparison cannot resolve more than fp64 gives.
inline constexpr double kMaxBits = 60.0;

// NaN, +-Inf, +-0 or an ordinary finite value.
enum class ValueClass { Nan, PosInf, NegInf, PosZero, NegZero, Finite };
ValueClass classify(double x);

struct OutputStats {
  std::string name;      // "r[].x", "result.y", "values[].xy (hi+lo)"
  std::string type;      // "double", "float", "float hi+lo"
  uint64_t samples = 0;
  double max_rel_err = 0, p99_rel_err = 0, median_rel_err = 0, max_abs_err = 0;
  double min_bits = kMaxBits, p1_bits = kMaxBits;
  uint64_t class_mismatches = 0;  // samples whose got/want differ in class (a ±0 sign counts too)
  // Samples whose bits differ (a NaN with another NaN's payload or sign counted apart, in
  // nan_payloads: GLSL leaves NaN results undefined). Modes exact and rte-exact require 0.
  uint64_t differing = 0, nan_payloads = 0;
  bool require_identical = false;
  uint64_t worst_sample = 0;      // sample index of min_bits
  double worst_got = 0, worst_want = 0;
  std::string worst_input;        // filled by the caller from worst_sample
  double abs_floor = 0;
  // Every sample's lowered and native value, in sample order: the differential tester compares two
  // lowerings of one program bit for bit (docs/robustness.md, "Differential testing").
  std::vector<double> got_values, want_values;
  double min_bits_required = -1;  // < 0: no requirement
  double max_abs_err_allowed = -1;  // < 0: no requirement (a scene's abs_error)
  // Without a threshold a float-float mode is judged against the same shader demoted to float
  // (VerifyOptions::judge_against_float): its median bits, < 0 where not judged. The output must
  // keep kBeyondFloatBits more, unless float alone keeps kFloatIsEnoughBits (nothing to tell apart).
  double float_median_bits = -1;
  static constexpr double kBeyondFloatBits = 8, kFloatIsEnoughBits = 40;
  // In [0, kMaxBits]: a relative error of 1 or more (an Inf or a NaN where native is finite) keeps
  // no bits. (Unclamped, a float median of -inf bits read as "not judged" above, and an output that
  // was Inf in every sample in both float and float-float passed.)
  double median_bits() const {
    return median_rel_err > 0 ? std::fmax(0.0, std::fmin(kMaxBits, -std::log2(median_rel_err))) : kMaxBits;
  }
  bool beyond_float_passed() const {
    return float_median_bits < 0 || float_median_bits >= kFloatIsEnoughBits ||
           median_bits() >= float_median_bits + kBeyondFloatBits;
  }
  bool abs_passed() const {
    return max_abs_err_allowed < 0 || (class_mismatches == 0 && max_abs_err <= max_abs_err_allowed);
  }
  bool identical_passed() const { return !require_identical || differing == 0; }
  bool passed() const {
    return (min_bits_required < 0 || min_bits >= min_bits_required) && abs_passed() && identical_passed() &&
           beyond_float_passed();
  }
};

// Accumulates samples, then computes the order statistics once.
class StatsBuilder {
 public:
  StatsBuilder(std::string name, std::string type, double abs_floor);
  void add(double got, double want, uint64_t sample);
  OutputStats finish();

 private:
  OutputStats stats_;
  std::vector<double> rel_;   // per sample
  std::vector<double> bits_;  // per sample
};

// -log2(relative error), with |want| below abs_floor measured as |got - want| / abs_floor; a NaN/Inf
// class mismatch scores 0, an exact match kMaxBits.
double correct_bits(double got, double want, double abs_floor, double* rel_err);

std::string hex(double x);  // "%a" spelling, what the report prints for worst inputs

}  // namespace doublet::verify
