// GCC spells the depfile options with one dash and several letters (-MD, -MF FILE,
// -MT TARGET, also -MFFILE). CLI11 only knows one-letter short options, so these are
// rewritten to --MD, --MF, --MT before parsing.
#pragma once

#include <string>
#include <vector>

namespace doublet::cli {

std::vector<std::string> rewrite_gcc_style_args(int argc, char** argv);

}  // namespace doublet::cli
