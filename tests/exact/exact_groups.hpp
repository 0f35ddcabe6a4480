// Shared by the mode-exact tests that compare a whole fp64 shader with its --mode exact lowering:
// a group of results computed from the same inputs (doubles and ints), its shader, its inputs, the
// lowering, and the count of differing results per output.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "exact_harness.hpp"

namespace doublet::runner::test::exact {

constexpr uint32_t kInvocations = 1u << 20;

// One shader: `doubles` inputs d[k], `ints` inputs n[k], and one output per entry of `results`
// (a double expression, or an int one when it starts with "int:").
struct Group {
  const char* name;
  int doubles, ints;
  std::vector<std::pair<const char*, std::string>> results;  // {name, GLSL expression}
  std::string prelude = "";  // statements before the results (out arguments)
};

inline std::string source(const Group& g) {
  const int arity = g.doubles + g.ints, results = int(g.results.size());
  std::string body = "  double d[" + std::to_string(g.doubles) + "];\n  for (int k = 0; k < " +
                     std::to_string(g.doubles) + "; ++k) d[k] = packDouble2x32(w[k]);\n";
  if (g.ints) {
    body += "  int n[" + std::to_string(g.ints) + "];\n";
    for (int k = 0; k < g.ints; ++k)
      body += "  n[" + std::to_string(k) + "] = int(w[" + std::to_string(g.doubles + k) + "].x);\n";
  }
  body += g.prelude;
  for (int k = 0; k < results; ++k) {
    const std::string& e = g.results[size_t(k)].second;
    const std::string at = "r[" + std::to_string(results) + "u * i + " + std::to_string(k) + "u] = ";
    body += e.rfind("int:", 0) == 0 ? "  " + at + "uvec2(uint(" + e.substr(4) + "), 0u);\n"
                                    : "  " + at + "unpackDouble2x32(" + e + ");\n";
  }
  return words_shader("#version 450\n", arity, results, body);
}

// Per double: half moderate magnitudes (2^-10..2^10, full significands), the rest random
// patterns, the exponent grid, short significands near 1 (ties) and special values; per int: an
// exponent for ldexp (within +-2200, half of them within +-60).
inline std::vector<uint64_t> inputs(const Group& g, uint32_t invocations = kInvocations) {
  Operands op(20261127);
  auto& rng = op.rng();
  std::vector<uint64_t> v;
  v.reserve(size_t(invocations) * size_t(g.doubles + g.ints));
  for (uint32_t i = 0; i < invocations; ++i) {
    for (int k = 0; k < g.doubles; ++k) {
      switch (rng() % 10) {
        case 0: v.push_back(op.special()); break;
        case 1: v.push_back(rng()); break;
        case 2: v.push_back(op.grid()); break;
        case 3: v.push_back(op.short_sig(1020 + rng() % 6, int(rng() % 12))); break;
        default: v.push_back(op.random_sign(((1013 + rng() % 21) << 52) | (rng() >> 12))); break;
      }
    }
    for (int k = 0; k < g.ints; ++k) {
      const int32_t e = (rng() & 1) ? int32_t(rng() % 4401) - 2200 : int32_t(rng() % 121) - 60;
      v.push_back(uint64_t(uint32_t(e)));
    }
  }
  return v;
}

inline std::string lower_exact(const std::string& src) {
  Options options;
  options.stage = Stage::Compute;
  options.target = Target::Es310;
  options.mode = Mode::Exact;
  Result lowered = lower(src, options);
  std::string diagnostics;
  for (const Diagnostic& d : lowered.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  EXPECT_TRUE(lowered.ok) << diagnostics;
  EXPECT_EQ(diagnostics, "");
  return lowered.output;
}

// Differing results per output of the group (both NaN counted apart: GLSL leaves NaN undefined).
struct Count {
  uint64_t differing = 0, nan_payload = 0;
  std::string first;
};

inline std::vector<Count> compare_group(const Group& g, const std::vector<uint64_t>& in, const std::vector<uint64_t>& got,
                                 const std::vector<uint64_t>& want) {
  const size_t results = g.results.size(), arity = size_t(g.doubles + g.ints);
  std::vector<Count> c(results);
  for (size_t i = 0; i < got.size() && i < want.size(); ++i) {
    if (got[i] == want[i]) continue;
    Count& k = c[i % results];
    if (is_nan(got[i]) && is_nan(want[i])) {
      ++k.nan_payload;
      continue;
    }
    if (k.differing++ == 0) {
      char buf[64];
      k.first = "inputs";
      for (size_t a = 0; a < arity; ++a) {
        std::snprintf(buf, sizeof buf, " %016llx", (unsigned long long)in[(i / results) * arity + a]);
        k.first += buf;
      }
      std::snprintf(buf, sizeof buf, " got %016llx want %016llx", (unsigned long long)got[i], (unsigned long long)want[i]);
      k.first += buf;
    }
  }
  return c;
}

// Runs the group natively on lavapipe and, lowered with --mode exact, on lavapipe and Mesa GLES;
// expects 0 differing results per output (NaN payloads reported apart).
inline void expect_bit_identical(const Group& g) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const std::string native_src = source(g), exact_src = lower_exact(native_src);
  ASSERT_FALSE(exact_src.empty());
  const std::string code = std::regex_replace(exact_src, std::regex("//[^\n]*"), "");
  EXPECT_FALSE(std::regex_search(code, std::regex(R"(\b(double|dvec[234])\b)"))) << "a double survived";
  const std::vector<uint64_t> in = inputs(g);
  const int arity = g.doubles + g.ints, results = int(g.results.size());
  const std::vector<uint64_t> native = run_words(Backend::Vulkan, native_src, in, arity, results);
  ASSERT_EQ(native.size(), size_t(kInvocations) * size_t(results));
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const std::vector<uint64_t> got = run_words(backend, exact_src, in, arity, results);
    const std::vector<Count> c = compare_group(g, in, got, native);
    for (size_t k = 0; k < c.size(); ++k) {
      std::cout << "[ exact ] " << backend_name(backend) << " " << g.results[k].first << ": " << c[k].differing
                << " of " << kInvocations << " differ from native (" << c[k].nan_payload << " NaN payloads apart)"
                << (c[k].differing ? "; first " + c[k].first : "") << "\n";
      EXPECT_EQ(c[k].differing, 0u) << backend_name(backend) << " " << g.results[k].first << ": " << c[k].first;
    }
  }
}

// A test name per group for INSTANTIATE_TEST_SUITE_P: the group's name, non-alphanumerics as '_'.
inline std::string group_test_name(const std::vector<Group>& groups, int index) {
  std::string n = groups[size_t(index)].name;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

// An edit of the lowered text of group `group`: another order of operations, a rule left out.
struct Sabotage {
  const char* name;
  int group;
  std::string from, to;
  std::vector<int> only = {};  // the group's results the edit reaches (empty: all); the rest are left out, so
                               // lavapipe compiles a shader of the one formula (mode exact's code is large)
};

// The prelude's statements that declare a variable the results use (one statement per line, as
// "  TYPE NAME = ...;"); the others would only make lavapipe compile code that is thrown away.
inline std::string prelude_for(const std::string& prelude, const std::vector<std::pair<const char*, std::string>>& results) {
  static const std::regex declaration(R"(^\s*\w+\s+(\w+)\s*=)");
  std::string kept, line;
  std::istringstream lines(prelude);
  while (std::getline(lines, line)) {
    std::smatch m;
    bool used = !std::regex_search(line, m, declaration);  // a statement that declares nothing stays
    if (!used) {
      const std::regex name("\\b" + m[1].str() + "\\b");
      used = std::any_of(results.begin(), results.end(), [&](const auto& r) { return std::regex_search(r.second, name); });
    }
    if (used) kept += line + "\n";
  }
  return kept;
}

// Each edit must apply to the lowered text and make some results differ from native on lavapipe
// (2^16 inputs: a sabotage shows on far fewer than the bit-identity check's).
inline void expect_sabotages_differ(const std::vector<Group>& groups, const std::vector<Sabotage>& sabotages) {
  REQUIRE_BACKEND(Backend::Vulkan);
  for (const Sabotage& sab : sabotages) {
    const auto start = std::chrono::steady_clock::now();
    Group g = groups[size_t(sab.group)];
    if (!sab.only.empty()) {
      decltype(g.results) kept;
      for (int k : sab.only) kept.push_back(g.results.at(size_t(k)));
      g.results = kept;
      g.prelude = prelude_for(g.prelude, g.results);
    }
    const std::string native_src = source(g);
    std::string exact_src = lower_exact(native_src);
    const size_t at = exact_src.find(sab.from);
    ASSERT_NE(at, std::string::npos) << sab.name;
    exact_src.replace(at, sab.from.size(), sab.to);
    const std::vector<uint64_t> in = inputs(g, 1u << 16);
    const int arity = g.doubles + g.ints, results = int(g.results.size());
    const std::vector<Count> c = compare_group(g, in, run_words(Backend::Vulkan, exact_src, in, arity, results),
                                               run_words(Backend::Vulkan, native_src, in, arity, results));
    uint64_t total = 0;
    for (const Count& k : c) total += k.differing;
    std::cout << "[ exact ] sabotage '" << sab.name << "': " << total << " results differ ("
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)" << std::endl;
    EXPECT_GT(total, 0u) << sab.name;
  }
}

}  // namespace doublet::runner::test::exact
