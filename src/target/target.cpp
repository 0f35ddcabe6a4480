#include "target/target.hpp"

namespace doublet::target {
namespace {

// WebGL 2.0 (ANGLE's translator) refuses identifiers longer than 1024 characters and the prefixes
// webgl_ and _webgl_; every GLSL reserves gl_.
const std::vector<Facts>& table() {
  static const std::vector<Facts> rows = {
      //  id               name       es  ver  version line       precise p5  comp  geom  tess  uint  casts intf  frexp fma   ssbo  ioblk ovl   webgl wgsl  ext   idlen
      {Target::Es100, "es100", true, 100, "#version 100", false, false, false, false, false, false, false, false, false, false, false, false, false, false, false, true, 0, {"gl_"}},
      {Target::Es300, "es300", true, 300, "#version 300 es", false, false, false, false, false, true, true, false, false, false, false, false, false, false, false, true, 0, {"gl_"}},
      {Target::Es310, "es310", true, 310, "#version 310 es", false, true, true, false, false, true, true, true, true, false, true, false, false, false, false, true, 0, {"gl_"}},
      {Target::Es320, "es320", true, 320, "#version 320 es", true, false, true, true, true, true, true, true, true, true, true, true, false, false, false, true, 0, {"gl_"}},
      {Target::Glsl330, "glsl330", false, 330, "#version 330 core", false, false, false, true, false, true, true, false, false, false, false, true, true, false, false, true, 0, {"gl_"}},
      {Target::Glsl450, "glsl450", false, 450, "#version 450 core", true, false, true, true, true, true, true, true, true, true, true, true, true, false, false, true, 0, {"gl_"}},
      {Target::Webgl2, "webgl2", true, 300, "#version 300 es", false, false, false, false, false, true, true, false, false, false, false, false, false, true, false, false, 1024, {"gl_", "webgl_", "_webgl_"}},
      {Target::Wgsl, "wgsl", false, 0, "", false, false, true, false, false, true, true, true, true, true, true, false, false, false, true, false, 0, {}},
  };
  return rows;
}

}  // namespace

const Facts& facts(Target t) {
  for (const Facts& f : table())
    if (f.id == t) return f;
  return table()[1];
}

std::vector<Target> all_targets(bool with_wgsl) {
  std::vector<Target> out;
  for (const Facts& f : table())
    if (with_wgsl || !f.wgsl) out.push_back(f.id);
  return out;
}

std::string version_directive(Target target) { return facts(target).version_line; }

const char* stage_noun(Stage stage) {
  switch (stage) {
    case Stage::Vertex: return "vertex";
    case Stage::Fragment: return "fragment";
    case Stage::Compute: return "compute";
    case Stage::Geometry: return "geometry";
    case Stage::TessControl: return "tessellation control";
    case Stage::TessEvaluation: return "tessellation evaluation";
  }
  return "vertex";
}

const char* stage_extension(const Facts& t, Stage stage) {
  if (t.id != Target::Es310) return nullptr;
  if (stage == Stage::Geometry) return "GL_EXT_geometry_shader";
  if (stage == Stage::TessControl || stage == Stage::TessEvaluation) return "GL_EXT_tessellation_shader";
  return nullptr;
}

bool has_stage(const Facts& t, Stage stage) {
  if (stage_extension(t, stage)) return true;
  switch (stage) {
    case Stage::Compute: return t.compute;
    case Stage::Geometry: return t.geometry;
    case Stage::TessControl:
    case Stage::TessEvaluation: return t.tessellation;
    default: return true;
  }
}

}  // namespace doublet::target
