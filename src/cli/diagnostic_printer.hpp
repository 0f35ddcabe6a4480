// Prints diagnostics to stderr the way compilers do, in colour only when a person is
// looking: stderr is a terminal, NO_COLOR is unset or empty (https://no-color.org) and
// TERM is not "dumb". `--color always|never` overrides the guess.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "doublet/doublet.hpp"

namespace doublet::cli {

enum class ColorChoice { Auto, Always, Never };

std::optional<ColorChoice> parse_color_choice(std::string_view name);  // auto|always|never
bool stderr_wants_color(ColorChoice choice);

// `file:line:col: error: message` plus a newline; with colour, the place is bold and the
// severity coloured (red error, magenta warning, cyan note), as GCC and Clang do.
std::string render_diagnostic(const Diagnostic& d, bool color);

// A message from the tool itself: "doublet: error: <message>".
Diagnostic tool_error(std::string message);

}  // namespace doublet::cli
