// Input values for verify runs. Default: log-uniform magnitudes in [2^-20, 2^20] with random signs.
// A range [LO, HI] with 0 < LO is log-uniform and positive, with HI < 0 log-uniform and negative;
// one that contains 0 is uniform (linear). Exact values (spec "values") are cycled.
// Every value is rounded to what both shaders can receive: a float-float pair (hi + lo) for a
// double input, a float for a float input, so the native and the lowered shader see the same
// numbers and the measured error is the arithmetic's (docs/numerics.md#representation-loss).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "verify/spec.hpp"

namespace doublet::verify {

class InputGenerator {
 public:
  // binary64: double inputs are kept as drawn (modes exact, rte-exact carry every double), not
  // rounded to a float-float pair.
  explicit InputGenerator(uint64_t seed, bool binary64 = false) : rng_(seed), binary64_(binary64) {}
  // Value number `index` of a variable (index counts samples × components, for cycling "values").
  double next(const InputSpec& spec, bool is_double, uint64_t index);
  // How many finite values next() drew beyond float range (|x| > FLT_MAX, after the split's
  // rounding) and so returned as +-Inf: neither a float-float pair nor a float holds them.
  uint64_t beyond_float_range() const { return beyond_float_range_; }

 private:
  double draw(const InputSpec& spec);
  std::mt19937_64 rng_;
  bool binary64_ = false;
  uint64_t beyond_float_range_ = 0;
};

// An input named as a whole, `name`, when the harness lists it by parts: every input named
// `name[...` (the elements of a per-vertex input array) or `name.MEMBER` (the members of a struct
// in a buffer; `doublet plan` gives a struct one range) takes `in`. False when none is named so.
template <typename Variable>
bool apply_to_parts(std::vector<Variable>& inputs, const std::string& name, const InputSpec& in) {
  bool any = false;
  for (Variable& v : inputs)
    if (v.name.size() > name.size() && v.name.compare(0, name.size(), name) == 0 &&
        (v.name[name.size()] == '[' || v.name[name.size()] == '.')) {
      v.input = in;
      any = true;
    }
  return any;
}

// The note verify prints (and writes in the JSON report's "notes") when `count` input values
// were beyond float range; empty when there were none.
std::string beyond_float_range_note(uint64_t count);

// An int/uint/bool input's value (scalar 'i', 'u', 'b') from a drawn or given number: rounded to
// the nearest integer (uint: at least 0); bool: 1 unless 0.
double integer_value(double x, char scalar);

// The value a double input keeps after the hi/lo split (or a float input after rounding).
double representable(double x, bool is_double);

}  // namespace doublet::verify
