// Target wgsl: doublet's pipeline for GLSL ES 3.10 with the uniform guard, whose output (runtime
// included) is re-imported by the front end and printed as WGSL (src/emit/wgsl_printer.hpp).
#pragma once

#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet {

Result lower_wgsl(std::string_view source, const Options& options);

}  // namespace doublet
