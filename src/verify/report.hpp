// Renders a VerifyReport: the human table (probe first) and the JSON of docs/verify.md.
#pragma once

#include <string>

#include "verify/verify.hpp"

namespace doublet::verify {

inline constexpr const char* kJsonSchema = "doublet-verify/1";

std::string format_table(const VerifyReport&);
std::string to_json(const VerifyReport&);  // pretty-printed

}  // namespace doublet::verify
