// glslang's name for a doublet stage (glslang's headers are needed to say it, so it is not in
// frontend.hpp, which the passes include).
#pragma once

#include <glslang/Public/ShaderLang.h>

#include "doublet/doublet.hpp"

namespace doublet::frontend {

EShLanguage glslang_stage(Stage stage);

}  // namespace doublet::frontend
