// Random, well-typed, terminating GLSL 4.50 programs over doubles (compute, vertex, fragment), for differential testing
// of the lowering (docs/robustness.md, "Differential testing"). In the spirit of Csmith (Yang et al.,
// "Finding and understanding bugs in C compilers", PLDI 2011): programs are built top-down from a
// grammar with a scope of typed variables, so each one compiles, and every loop has a constant trip
// count, so each one ends. Magnitudes are tracked roughly per expression and wrapped in clamp()
// where a product could grow past 1e8, so that native results stay finite in most programs; the
// oracles do not rely on it (they skip samples where native is not finite).
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace doublet::difftest {

struct Program {
  uint64_t seed = 0;
  std::string stage = "comp";  // "comp", "vert" or "frag" (the file extension it is saved with)
  std::string glsl;       // "#version 450" shader, one statement per line
  std::string spec_json;  // `doublet verify --spec`: the range of every input
  // Features used: operators ("op:+"), built-ins ("fn:fma"), statements ("stmt:for"), types.
  std::set<std::string> features;
};

Program generate(uint64_t seed);

// Every feature the generator can emit: the denominator of the coverage share it prints.
const std::vector<std::string>& all_features();

// Built-ins whose native lavapipe results are not IEEE (docs/extremes.md, "Native fp64 is not the
// oracle for rounding to an integer"; smoothstep, reflect: docs/robustness.md, findings): the
// exact-equals-native oracle skips a program that uses one of them.
bool uses_native_non_ieee(const Program&);

// Whether a generated expression's text reads a variable (an identifier that is not a function or
// constructor, a swizzle or a literal's suffix): mix's ends must not both be constants, which NIR
// folds into another formula (docs/robustness.md, findings).
bool reads_a_variable(const std::string& expression);

}  // namespace doublet::difftest
