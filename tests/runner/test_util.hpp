// Shared helpers for the driver tests.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

#include "runner/runner.hpp"

namespace doublet::runner {
// Lets gtest name parameterised cases "Vulkan"/"GLES" instead of dumping bytes.
inline void PrintTo(Backend b, std::ostream* os) { *os << backend_name(b); }
}  // namespace doublet::runner

namespace doublet::runner::test {

template <typename T>
std::vector<uint8_t> to_bytes(const std::vector<T>& v) {
  std::vector<uint8_t> out(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(out.data(), v.data(), out.size());
  return out;
}

template <typename T>
std::vector<T> from_bytes(const std::vector<uint8_t>& bytes) {
  std::vector<T> out(bytes.size() / sizeof(T));
  if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

template <typename T, typename U>
T bits(U x) {
  static_assert(sizeof(T) == sizeof(U));
  T t;
  std::memcpy(&t, &x, sizeof t);
  return t;
}

// Fails the test (never skips) when the backend cannot run here.
#define REQUIRE_BACKEND(b)                                                                         \
  ASSERT_EQ(::doublet::runner::backend_unavailable_reason(b), "")                                   \
      << ::doublet::runner::backend_name(b) << " backend unavailable on this machine"

// Runs the job and asserts success, printing the driver's message otherwise.
#define RUN_OK(result, backend, job)                                                               \
  ::doublet::runner::ComputeResult result = ::doublet::runner::run_compute(backend, job);           \
  ASSERT_TRUE(result.ok) << ::doublet::runner::backend_name(backend) << ": " << result.error;       \
  ASSERT_EQ(result.buffers.size(), (job).buffers.size())

// Bytes that differ between two runs' buffers, every buffer (SIZE_MAX when their shapes differ).
inline size_t differing_bytes(const std::vector<std::vector<uint8_t>>& a, const std::vector<std::vector<uint8_t>>& b) {
  if (a.size() != b.size()) return SIZE_MAX;
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return SIZE_MAX;
    for (size_t k = 0; k < a[i].size(); ++k) n += a[i][k] != b[i][k];
  }
  return n;
}

inline std::string backend_param_name(const ::testing::TestParamInfo<Backend>& info) {
  return backend_name(info.param);
}

}  // namespace doublet::runner::test
