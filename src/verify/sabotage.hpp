// Deliberately broken lowerings, so the suite can prove its accuracy checks can fail.
//   DropLo:    every double demoted to float before lowering (what users have without doublet);
//   DropGuard: the lowering's optimizer guard removed (GuardKind::None): Mesa deletes error terms.
//   TiesAway:  mode exact's round-and-pack rounds ties away from zero instead of to even (an edit
//              of the lowered text, rules/exact.glsl's tie line): results must stop matching.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::verify {

enum class Sabotage { None, DropLo, DropGuard, TiesAway };

std::string_view to_string(Sabotage);
std::optional<Sabotage> parse_sabotage(std::string_view);  // "none", "drop-lo", "drop-guard", "ties-away"


// The lowering options and source a sabotage implies.
void apply_sabotage(Sabotage, std::string* source, Options* options);
// The lowered text a sabotage implies (TiesAway); false when the text has nothing to sabotage.
bool apply_output_sabotage(Sabotage, std::string* lowered);

}  // namespace doublet::verify
