// luma.gl's fp64 shader library (npm @luma.gl/shadertools, pinned by tools/peers/package-lock.json)
// as a peer to measure doublet's transcendentals against. Nothing of it is stored in doublet's
// tree: tools/peers/luma-fp64.mjs prints the library as luma.gl's own assembler builds it for an
// application (docs/transcendentals.md, "Peer: luma.gl").
#pragma once

#include <map>
#include <string>

namespace doublet::bench {

struct LumaLibrary {
  bool ok = false;
  bool unavailable = false;  // node or the npm package is missing here: skip, not fail
  std::string error;
  std::string version;       // of @luma.gl/shadertools
  // GLSL (no #version line) defining exp_fp64, log_fp64, sin_fp64, cos_fp64, tan_fp64 on vec2(hi, lo).
  // luma.gl's uniform block `fp64arithmeticUniforms { float ONE; float SPLIT; } fp64` becomes two
  // loose uniforms (luma_fp64_ONE, luma_fp64_SPLIT): the same opaque runtime values to a compiler,
  // and settable by the runner, which binds loose uniforms only.
  std::string glsl;
  std::map<std::string, float> uniforms;  // the module's defaults, which luma.gl uploads: ONE 1, SPLIT 4097
};

// $DOUBLET_PEER_TOOLS, else the source tree's tools/peers.
std::string peer_tools_dir();

// Runs tools/peers/luma-fp64.mjs once per process and keeps the result.
const LumaLibrary& luma_fp64_library();

}  // namespace doublet::bench
