// Target wgsl: the validated ES 3.10 text of the GLSL pipeline is imported again and printed as
// WGSL (docs/web.md). doublet has no WGSL front end; the browser tests compile the output.
#pragma once

#include "pipeline/pipeline.hpp"

namespace doublet::pipeline {

// state.printed.text (the ES 3.10 intermediate) → state.printed.text as WGSL, the manifest's
// bindings and uniform buffer filled in.
bool print_wgsl(State& state);

}  // namespace doublet::pipeline
