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
  std::vector<std::pair<double, double>> component_ranges;  // per component (scene files); wins over lo/hi
  // A uniform's initializer, not the user's entry: nothing to feed when the compiler removed the
  // uniform (unused), where a name the user gives must exist.
  bool from_initializer = false;
  InputSpec component(size_t c) const;  // this spec with component c's range as lo/hi
};

struct OutputSpec {
  std::optional<double> min_bits;  // per-output threshold (overrides --min-bits)
  std::optional<double> abs_floor; // |want| below this is measured as absolute error / floor
  std::optional<double> max_abs_error;  // scene abs_error: fail when |got - want| exceeds it
  bool join_hi_lo = false;         // float vec2/vec4 holding (hi, lo) pairs: compare hi + lo as one value
  unsigned elements_per_invocation = 1;  // runtime-sized arrays: elements each invocation writes
};

// Scene relation (docs/plan.md): a - b lies in [-abs_max, abs_max] per component. The harness
// draws b, then a = b + offset (or b from a when only b is per sample), clamped to a's range.
struct InputRelation {
  std::string a, b;
  double abs_max = 0;
};

struct Spec {
  std::map<std::string, InputSpec> inputs;
  std::vector<InputRelation> relations;
  std::map<std::string, OutputSpec> outputs;
  std::optional<unsigned> array_length;  // elements of runtime-sized arrays per dispatch
  unsigned groups[3] = {1, 1, 1};         // workgroups per dispatch (per-dispatch mode)
};

// "NAME=LO:HI" (numbers in any strtod form, hex floats included). Empty on success, else why.
std::string parse_range(const std::string& text, std::string* name, InputSpec* out);

// Parses a --spec JSON document into *out (adding to what is there). Empty on success, else why.
std::string parse_spec(const std::string& json_text, Spec* out);

}  // namespace doublet::verify
