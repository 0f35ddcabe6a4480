// What the user tells `doublet verify` about inputs and outputs: --range NAME=LO:HI and the
// --spec JSON file (format in docs/verify.md). Parsing only; no shader knowledge here.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace doublet::verify {

// How one input variable's values are drawn.
struct InputSpec {
  std::optional<double> lo, hi;  // range; see inputs.hpp for how it is sampled
  std::vector<double> values;    // exact values, cycled over samples and components (wins over a range)
  unsigned elements_per_invocation = 1;  // runtime-sized arrays: elements each invocation reads
};

struct OutputSpec {
  std::optional<double> min_bits;  // per-output threshold (overrides --min-bits)
  std::optional<double> abs_floor; // |want| below this is measured as absolute error / floor
  bool join_hi_lo = false;         // float vec2/vec4 holding (hi, lo) pairs: compare hi + lo as one value
  unsigned elements_per_invocation = 1;  // runtime-sized arrays: elements each invocation writes
};

struct Spec {
  std::map<std::string, InputSpec> inputs;
  std::map<std::string, OutputSpec> outputs;
  std::optional<unsigned> array_length;  // elements of runtime-sized arrays per dispatch
  unsigned groups[3] = {1, 1, 1};         // workgroups per dispatch (per-dispatch mode)
};

// "NAME=LO:HI" (numbers in any strtod form, hex floats included). Empty on success, else why.
std::string parse_range(const std::string& text, std::string* name, InputSpec* out);

// Parses a --spec JSON document into *out (adding to what is there). Empty on success, else why.
std::string parse_spec(const std::string& json_text, Spec* out);

}  // namespace doublet::verify
