// Test-case reduction for the differential tester: delta debugging (Zeller and Hildebrandt,
// "Simplifying and isolating failure-inducing input", TSE 2002) over the program's lines, after a
// first pass that drops whole braced blocks. A candidate counts when it still compiles natively and
// the same oracle still reports a finding; every program the generator writes has one statement
// per line, so removing lines keeps most candidates well-formed.
#pragma once

#include <functional>
#include <string>

#include "difftest/oracles.hpp"

namespace doublet::difftest {

struct Reduction {
  std::string program;  // the smallest program that kept the finding
  int checks = 0;       // candidate programs run through the oracle
  Finding finding;      // the finding on the reduced program
};

// `oracle` is the finding's oracle; options.oracles is narrowed to what reproduces it. After
// `seconds` no candidate counts any more, so the reduction ends with what it has.
Reduction reduce(const std::string& glsl, const std::string& spec_json, const std::string& stage, const std::string& oracle,
                 CheckOptions options, double seconds, const std::function<void(const std::string&)>& progress);

// Whether every counter of the generator's while and do-while loops (`while (w < N)`) is still
// incremented (`w++`): the reducer keeps only candidates that do, since a loop that never ends lets
// a driver return anything (seed 70349's reduction, docs/robustness.md).
bool keeps_loop_steps(const std::string& glsl);

}  // namespace doublet::difftest
