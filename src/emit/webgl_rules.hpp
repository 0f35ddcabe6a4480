// WebGL 2.0's rules on top of GLSL ES 3.00, checked on printed text (--target webgl2): the
// regression guard that catches what a browser would reject, without a browser.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace doublet::emit {

struct WebglViolation {
  int line = 0;  // in the printed text, 1-based
  std::string message;
};

// What the printed shader does that WebGL 2.0 forbids: `precise`, an `#extension` directive, an
// identifier beginning with webgl_ or _webgl_ or longer than the target table allows (target/target.hpp), a float
// literal beyond the float range (ANGLE warns 'Float overflow' and clamps it). A struct-typed
// ternary cannot be seen in text; check_target finds those on the IR.
std::vector<WebglViolation> webgl_violations(std::string_view text);

// `runtime` with FLT_MAX spelled 3.4028234663852886e38 (the exact value of FLT_MAX, so the float it
// denotes is the same) instead of 3.40282347e38, which exceeds FLT_MAX as a real number and makes
// ANGLE warn "Float overflow".
std::string spell_float_max_for_webgl(std::string runtime);

}  // namespace doublet::emit
