// Preparing a user's compute shader for `doublet bench SHADER`: the runner takes one
// self-contained text, so #include "..." is expanded here (the lowering resolves includes itself,
// from the same directories), and native fp64 needs desktop GLSL ("#version 450"): glslang does
// not allow doubles in ES text, which doublet accepts as input.
#pragma once

#include <string>
#include <vector>

namespace doublet::bench {

// Expands `#include "name"` (searched next to the including file, then in include_dirs),
// recursively, once per file. False with *error when a file cannot be read.
bool expand_includes(const std::string& path, const std::vector<std::string>& include_dirs, std::string* out,
                     std::string* error);

// The same text with its #version line replaced by "#version 450" (unchanged when it has none).
std::string as_desktop_450(const std::string& source);

}  // namespace doublet::bench
