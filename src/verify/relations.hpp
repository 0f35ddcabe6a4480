// Scene relations for verify's input sampling (docs/plan.md): after every input is drawn from its
// own range, each relation a - b in [-R, R] redraws one side as the other plus a uniform offset
// in [-R, R] per component, clamped to that side's range. The side redrawn is the per-sample one
// (an attribute against a uniform), else `a`.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "verify/spec.hpp"

namespace doublet::verify {

struct RelatedInput {
  std::string name;
  bool per_sample = false;  // several samples share one value when false (a uniform)
  int components = 1;
  bool is_double = false;
  const InputSpec* spec = nullptr;
  std::vector<double>* values = nullptr;  // samples × components, or components
};

// Empty, or a note when a redrawn value had to leave the relation to stay in its range.
std::string apply_relations(const std::vector<InputRelation>& relations, std::vector<RelatedInput>& inputs,
                            std::mt19937_64& rng);

}  // namespace doublet::verify
