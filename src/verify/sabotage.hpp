// Deliberately broken lowerings, so the suite can prove its accuracy checks can fail.
//   DropLo:    every double demoted to float before lowering (what users have without doublet);
//   DropGuard: the lowering's optimizer guard removed (GuardKind::None): Mesa deletes error terms.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::verify {

enum class Sabotage { None, DropLo, DropGuard };

std::string_view to_string(Sabotage);
std::optional<Sabotage> parse_sabotage(std::string_view);  // "none", "drop-lo", "drop-guard"


// The lowering options and source a sabotage implies.
void apply_sabotage(Sabotage, std::string* source, Options* options);

}  // namespace doublet::verify
