// Make-style dependency files (`-MD -MF FILE`), the format GCC writes and that Make,
// Ninja and CMake's add_custom_command(DEPFILE) read:
//   out/globe.vert: shaders/globe.vert shaders/common/geodesy.glsl
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace doublet::cli {

// One rule, `target: prerequisites...`, one prerequisite per continued line. Spaces, '#'
// and '$' in paths are escaped the way Make (and Ninja) unescape them.
std::string make_depfile(std::string_view target, const std::vector<std::string>& prerequisites);

}  // namespace doublet::cli
