// The per-operation benchmark kernels: one double-precision compute shader per operation that
// applies the operation in a dependent chain (each step consumes the previous result, so the
// driver can neither skip nor overlap steps) and stores the result so nothing is dead code.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace doublet::bench {

// The bytes of v, as a storage buffer holds them (a job's runner::ComputeJob::buffers entry).
template <class T>
std::vector<uint8_t> bytes_of(const std::vector<T>& v) {
  std::vector<uint8_t> b(v.size() * sizeof(T));
  std::memcpy(b.data(), v.data(), b.size());
  return b;
}

struct Kernel {
  std::string op;        // "add", "sub", ..., "mat4"
  std::string rule;      // the docs/rules.md row whose flop count one step costs in df64
  int rule_flops = 0;    // that row's "flops" (docs/rules.md); mat4 = 4 dot4
  int fp32_flops = 0;    // float operations of one step in fp32 (and fp64 operations natively)
  int default_steps = 0; // chain length when --steps is not given: fp32 dispatches of ~5 ms on
                         // llvmpipe, long enough that thread wake-ups do not dominate
};

const std::vector<Kernel>& kernels();  // in report order
const Kernel* find_kernel(const std::string& op);

inline constexpr int kLocalSize = 64;  // invocations per work group
inline constexpr int kUnroll = 8;      // steps written out per loop trip (keeps loop overhead out of fp32)

// `#version 450` source with doubles. Buffers: binding 0 `vec4 inp[]` (one vec4 per element),
// binding 1 `vec4 outp[]`, binding 2 (mat4 only) `vec4 mcol[4]`. `steps` is rounded up to a
// multiple of kUnroll.
std::string kernel_source(const Kernel& k, int steps);
// The same chain of kUnroll steps on inputs that have lo words (inp[i] + inp[i].wzyx * 2^-24),
// storing the result's hi and lo words (`x` or `v.x`, then x - double(float(x)), exact) in
// outp[i].xy: what the bench's accuracy run compares with native fp64.
std::string kernel_accuracy_source(const Kernel& k);
// hi + lo of element i of an accuracy run's `vec4 outp[]` (hi in .x, lo in .y).
long double stored_hi_lo(const std::vector<uint8_t>& outp, size_t i);

// The worst relative error of an accuracy run, as bits: a NaN error counts as infinitely bad.
struct WorstRelativeError {
  long double worst = 0;
  void add(long double rel) {
    if (!(rel <= worst)) worst = std::isnan(static_cast<double>(rel)) ? INFINITY : rel;
  }
  double bits(double if_exact) const { return worst == 0 ? if_exact : -std::log2(static_cast<double>(worst)); }
};

// The one-step line kernel_source writes kUnroll times in its loop (e.g. "x = x + y;").
std::string kernel_step(const Kernel& k);
int rounded_steps(int steps);

// Input buffers for `elements` invocations: values in [0.5, 1) so every chain stays finite.
std::vector<std::vector<uint8_t>> kernel_buffers(const Kernel& k, int elements);

}  // namespace doublet::bench
