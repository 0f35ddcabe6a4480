// The fp32 demotion of a double shader's text: double -> float, dvecN/dmatN[xM] -> vecN/matN[xM],
// 1.0lf -> 1.0. Whole words only (`doubled` stays), comments untouched. Used for the fp32
// baselines of bench and demo and for verify's drop-lo sabotage.
#pragma once

#include <string>
#include <string_view>

namespace doublet::frontend {

std::string demote_doubles(std::string_view source);

// The text with every `precise` outside comments blanked, columns kept: doublet drops the qualifier
// (with a warning) on targets without it, so a recompilation of the user's text as such a target
// must not stop there (pipeline/validation.cpp).
std::string blank_precise(std::string_view source);

}  // namespace doublet::frontend
