// TEMPORARY STUB so the tree links while the core is written.
#include "doublet/doublet.hpp"
namespace doublet {
std::string format_diagnostic(const Diagnostic& d) { return d.file + ": error: " + d.message; }
Result lower(std::string_view, const Options& o) {
  Result r;
  r.diagnostics.push_back({o.file_name, 1, 1, Severity::Error, "not implemented yet"});
  return r;
}
std::string Manifest::to_json() const { return "{}"; }
std::string_view to_string(Target) { return "es300"; }
std::string_view to_string(Stage) { return "vert"; }
std::optional<Target> parse_target(std::string_view) { return Target::Es300; }
std::optional<Stage> parse_stage(std::string_view) { return Stage::Vertex; }
std::optional<Stage> stage_from_path(std::string_view) { return Stage::Vertex; }
bool target_is_es(Target) { return true; }
int target_version(Target) { return 300; }
}  // namespace doublet
