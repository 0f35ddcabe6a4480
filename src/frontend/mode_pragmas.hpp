// `#pragma doublet mode(MODE)` lines of the user's source. glslang ignores pragmas it does not
// know, so they are recovered from the text, with the user's line numbers.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"

namespace doublet::frontend {

struct ModePragma {
  int line = 0;    // 1-based
  int column = 0;  // of '#'
  Mode mode = Mode::Df64;
  bool top_level = true;  // outside every { }: names a global or a function, else a local
  int next_line = 0;      // the next line with code (not blank, comment or #directive); 0: none
  std::shared_ptr<const std::string> next_text;  // that line (shared by the pragmas before it); null: none
};

// Pragmas of the main file (not of #included files), in source order. Malformed ones
// (`#pragma doublet mode(fast)`, `#pragma doublet speed`) are errors in `diagnostics`.
std::vector<ModePragma> scan_mode_pragmas(std::string_view source, const std::string& file_name,
                                          std::vector<Diagnostic>& diagnostics);

}  // namespace doublet::frontend
