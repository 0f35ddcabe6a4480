// Mode exact and rte-exact (docs/modes.md): the lowered shader's double inputs and outputs are the
// binary64 words of the values, low word first (`double X` -> uvec2 X, dvec3 -> X_xy + X_z), and its
// blocks hold the doubles' bytes at their original offsets. The harnesses feed and read them here.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "doublet/doublet.hpp"
#include "doublet/split.hpp"

namespace doublet::verify {

// True when the lowering carries doubles as binary64 words (manifest "encoding").
inline bool carries_words(const Manifest& m) { return m.mode == "exact" || m.mode == "rte-exact"; }

// The words of `values` (elements × doubles_per_element, element after element) for the lowered
// variables whose uint components per element are `part_components` (2 or 4 each, in order):
// part k holds the next part_components[k] / 2 doubles of every element. Words as doubles (exact).
inline std::vector<std::vector<double>> word_parts(const std::vector<double>& values, int doubles_per_element,
                                                   const std::vector<int>& part_components) {
  std::vector<std::vector<double>> parts(part_components.size());
  const size_t elements = doubles_per_element > 0 ? values.size() / size_t(doubles_per_element) : 0;
  for (size_t e = 0; e < elements; ++e) {
    int first = 0;
    for (size_t k = 0; k < parts.size(); ++k) {
      for (int c = first; c < first + part_components[k] / 2 && c < doubles_per_element; ++c) {
        const ExactWords w = exact_words(values[e * size_t(doubles_per_element) + size_t(c)]);
        parts[k].push_back(w.lo);
        parts[k].push_back(w.hi);
      }
      first += part_components[k] / 2;
    }
  }
  return parts;
}

// Double number `c` of element `e` from word outputs (uint values read back as doubles), laid out
// as word_parts() lays inputs.
inline double joined_word(const std::vector<const std::vector<double>*>& parts, const std::vector<int>& part_components,
                          size_t e, int c) {
  int first = 0;
  for (size_t k = 0; k < parts.size(); ++k) {
    const int doubles = part_components[k] / 2;
    if (c < first + doubles) {
      const size_t at = e * size_t(part_components[k]) + 2 * size_t(c - first);
      return exact_join({static_cast<uint32_t>((*parts[k])[at]), static_cast<uint32_t>((*parts[k])[at + 1])});
    }
    first += doubles;
  }
  return 0;
}

}  // namespace doublet::verify
