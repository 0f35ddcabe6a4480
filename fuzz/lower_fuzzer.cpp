// libFuzzer target: any bytes → doublet::lower for a target and stage chosen
// by the first byte. A crash, hang, sanitizer report or exception escaping is a
// finding; every finding becomes a file in tests/hostile/cases.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "doublet/doublet.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static constexpr doublet::Target kTargets[] = {doublet::Target::Es100,  doublet::Target::Es300,
                                                 doublet::Target::Es310,  doublet::Target::Es320,
                                                 doublet::Target::Glsl330, doublet::Target::Glsl450,
                                                 doublet::Target::Webgl2};
  static constexpr doublet::Stage kStages[] = {doublet::Stage::Vertex, doublet::Stage::Fragment,
                                               doublet::Stage::Compute};
  doublet::Options options;
  options.target = kTargets[data[0] % 7];
  options.stage = kStages[(data[0] / 6) % 3];
  options.file_name = "fuzz.glsl";
  std::string_view source(reinterpret_cast<const char*>(data + 1), size - 1);
  doublet::Result result = doublet::lower(source, options);
  // Invariants every input must keep.
  if (result.ok == result.output.empty()) __builtin_trap();  // ok ⇔ output
  for (const auto& d : result.diagnostics)
    if (d.message.empty()) __builtin_trap();
  return 0;
}
