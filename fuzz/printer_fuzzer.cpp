// libFuzzer target for the printer (docs/robustness.md, "Printer round trip"): the input bytes
// drive the expression generator of tests/printer/round_trip.hpp (every choice is one byte; the
// first picks the target, the next the size); the generated module is printed, parsed back by
// glslang and imported, and main must keep its structure. A difference is a finding (trap), and so
// are a crash, a hang and a sanitizer report.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzedDataProvider bytes(data, size);
  static constexpr doublet::Target kTargets[] = {doublet::Target::Es100,  doublet::Target::Es300,
                                                 doublet::Target::Es310,  doublet::Target::Es320,
                                                 doublet::Target::Glsl330, doublet::Target::Glsl450,
                                                 doublet::Target::Webgl2};
  // ES 1.00 lacks % and the bitwise operators the generator uses: ES 3.00 and later, desktop.
  const doublet::Target target = kTargets[1 + bytes.ConsumeIntegralInRange<int>(0, 5)];
  const int statements = bytes.ConsumeIntegralInRange<int>(1, 8);
  const int depth = bytes.ConsumeIntegralInRange<int>(1, 6);
  doublet::roundtrip::Chooser choose = [&](uint32_t bound) { return bytes.ConsumeIntegralInRange<uint32_t>(0, bound - 1); };
  doublet::ir::Module module = doublet::roundtrip::random_module(choose, statements, depth);
  const std::string difference = doublet::roundtrip::round_trip_difference(module, target);
  if (!difference.empty()) {
    std::fprintf(stderr, "printer round trip differs:\n%s\n", difference.c_str());
    __builtin_trap();
  }
  return 0;
}
