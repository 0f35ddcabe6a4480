// The web page's script (src/demo/web_page.js), embedded at build time by src/demo/CMakeLists.txt.
#pragma once

namespace doublet::demo {

extern const char* const kWebPageScript;

}  // namespace doublet::demo
