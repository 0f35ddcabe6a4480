// The precisions a demo renders with, and how one double-precision shader becomes each of them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <doublet/doublet.hpp>

namespace doublet::demo {

enum class Mode {
  Fp32,    // every double demoted to float (frontend::demote_doubles): what the app would get without doublet
  Df64,    // doublet's default lowering (float-float)
  Native,  // the original fp64 shader on lavapipe (shaderFloat64)
};

std::string_view mode_name(Mode);
// "fp32" | "df64" | "native"; nullopt for anything else (precision modes such as rte or df64-fast
// are not implemented yet, so they are rejected, not approximated).
std::optional<Mode> parse_mode(std::string_view);
std::vector<Mode> all_modes();
// Parses --mode values (empty: all modes). On an unknown name returns false and sets *error.
bool parse_modes(const std::vector<std::string>& names, std::vector<Mode>* out, std::string* error);


// The shader for a mode: Fp32 → demoted text, Df64 → doublet::lower to `target`, Native → the
// text with its #version line replaced by "#version 450" (desktop GLSL, where doubles are core).
// Returns false with *error (diagnostics) when lowering fails.
bool shader_for_mode(Mode, std::string_view source, Stage, Target target, std::string* out, std::string* error);

}  // namespace doublet::demo
