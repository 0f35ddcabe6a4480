// Spellings shared by the library, the CLI and the tests; the manifest's JSON.
#include <nlohmann/json.hpp>

#include "doublet/doublet.hpp"
#include "target/target.hpp"

namespace doublet {

std::string_view to_string(Target t) { return target::facts(t).name; }
bool target_is_es(Target t) { return target::facts(t).es; }
int target_version(Target t) { return target::facts(t).version; }

std::optional<Target> parse_target(std::string_view name) {
  for (Target t : target::all_targets())
    if (name == target::facts(t).name) return t;
  return std::nullopt;
}

namespace {
constexpr std::pair<Mode, const char*> kModes[] = {
    {Mode::Fp32, "fp32"}, {Mode::Rte, "rte"}, {Mode::Df64Fast, "df64-fast"}, {Mode::Df64, "df64"}, {Mode::Native, "native"},
    {Mode::Df64Int, "df64-int"},
    {Mode::Exact, "exact"},
    {Mode::RteExact, "rte-exact"},
};
}  // namespace

std::string_view to_string(Mode m) {
  for (const auto& [mode, name] : kModes)
    if (mode == m) return name;
  return "df64";
}

std::optional<Mode> parse_mode(std::string_view name) {
  for (const auto& [mode, name_of] : kModes)
    if (name == name_of) return mode;
  return std::nullopt;
}

std::string_view to_string(Stage s) {
  switch (s) {
    case Stage::Vertex: return "vert";
    case Stage::Fragment: return "frag";
    case Stage::Compute: return "comp";
    case Stage::Geometry: return "geom";
    case Stage::TessControl: return "tesc";
    case Stage::TessEvaluation: return "tese";
  }
  return "vert";
}

std::optional<Stage> parse_stage(std::string_view name) {
  if (name == "vert") return Stage::Vertex;
  if (name == "frag") return Stage::Fragment;
  if (name == "comp") return Stage::Compute;
  if (name == "geom") return Stage::Geometry;
  if (name == "tesc") return Stage::TessControl;
  if (name == "tese") return Stage::TessEvaluation;
  return std::nullopt;
}

std::optional<GuardKind> parse_guard(std::string_view name) {
  if (name == "auto") return GuardKind::Auto;
  if (name == "precise") return GuardKind::Precise;
  if (name == "uniform") return GuardKind::Uniform;
  return std::nullopt;
}

std::optional<Stage> stage_from_path(std::string_view path) {
  auto slash = path.find_last_of("/\\");
  std::string_view file = slash == std::string_view::npos ? path : path.substr(slash + 1);
  if (file.size() > 5 && file.substr(file.size() - 5) == ".glsl") file.remove_suffix(5);
  auto dot = file.find_last_of('.');
  if (dot == std::string_view::npos) return std::nullopt;
  return parse_stage(file.substr(dot + 1));
}

std::string format_diagnostic(const Diagnostic& d) {
  std::string s = d.file.empty() ? "<input>" : d.file;
  if (d.line > 0) {
    s += ":" + std::to_string(d.line);
    s += ":" + std::to_string(d.column > 0 ? d.column : 1);
  }
  s += d.severity == Severity::Error ? ": error: " : d.severity == Severity::Warning ? ": warning: " : ": note: ";
  return s + d.message;
}

std::string Manifest::to_json() const {
  nlohmann::ordered_json j;
  j["stage"] = stage;
  j["target"] = target;
  if (!mode.empty() && mode != "df64") j["mode"] = mode;
  j["variables"] = nlohmann::ordered_json::array();
  for (const auto& v : variables) {
    nlohmann::ordered_json e;
    e["name"] = v.name;
    e["storage"] = v.storage;
    e["type"] = v.type;
    e["split"] = v.split;
    e["lowered_type"] = v.lowered_type;
    e["lowered_names"] = v.lowered_names;
    if (!v.lowered_types.empty()) e["lowered_types"] = v.lowered_types;
    if (!v.encoding.empty()) e["encoding"] = v.encoding;
    if (!v.locations.empty()) e["locations"] = v.locations;
    if (!v.default_value.empty()) e["default"] = v.default_value;
    if (!v.block.empty()) e["block"] = v.block;
    if (!v.layout.empty()) e["layout"] = v.layout;
    if (v.group >= 0) e["group"] = v.group;
    if (v.binding >= 0) e["binding"] = v.binding;
    if (!v.members.empty()) {
      e["members"] = nlohmann::ordered_json::array();
      for (const auto& m : v.members) {
        nlohmann::ordered_json jm;
        jm["name"] = m.name;
        jm["type"] = m.type;
        jm["lowered_type"] = m.lowered_type;
        jm["offset"] = m.offset;
        jm["size"] = m.size;
        if (m.array_stride) jm["array_stride"] = m.array_stride;
        if (m.matrix_stride) jm["matrix_stride"] = m.matrix_stride;
        if (m.hi_offset >= 0) {
          jm["hi_offset"] = m.hi_offset;
          jm["lo_offset"] = m.lo_offset;
        }
        if (!m.encoding.empty()) jm["encoding"] = m.encoding;
        e["members"].push_back(jm);
      }
    }
    j["variables"].push_back(e);
  }
  nlohmann::ordered_json g;
  g["kind"] = guard.kind;
  if (!guard.uniform_name.empty()) {  // kind "uniform", or a zero uniform the shader's uniforms are read through
    g["uniform"] = guard.uniform_name;
    g["type"] = guard.uniform_type;
    g["required_value"] = guard.required_value;
    g["note"] = "GL and GLES zero-initialise uniforms at link time: leave it unset";
  }
  j["guard"] = g;
  return j.dump(2) + "\n";
}

}  // namespace doublet
