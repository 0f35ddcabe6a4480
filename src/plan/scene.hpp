// The scene file of `doublet plan` / `doublet verify --scene` (format: docs/plan.md): input value
// ranges in the user's units, relations between inputs, and the absolute precision each output
// needs. Parsing only; names are checked against a shader later (check_scene_names).
#pragma once

#include <exception>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/doublet.hpp"
#include "plan/interval.hpp"

namespace doublet::plan {

struct InputRange {
  std::vector<Interval> components;  // one entry: every component; else one per component
  Interval component(size_t i) const { return components.size() == 1 ? components[0] : components.at(i); }
  std::string path;                  // JSON pointer of the entry, for diagnostics
};

// a - b lies in [-abs_max, abs_max], component by component. Each of a, b is a scene input or a
// value the shader computes, named FUNCTION.LOCAL as --mode-for names it (is_computed_value):
// "the eye is within 10 m of the position the shader derives from the inputs".
struct Relation {
  std::string a, b;
  double abs_max = 0;
  std::string path;
};

struct OutputRequirement {
  double abs_error = 0;  // the largest absolute error allowed on every component
  std::string path;
};

struct Scene {
  std::string file;
  std::string text;  // kept to place diagnostics about names found later
  std::map<std::string, InputRange> inputs;
  std::vector<Relation> relations;
  std::map<std::string, OutputRequirement> outputs;
};

// True for FUNCTION.LOCAL: a relation's side that is computed by the shader, not an input.
inline bool is_computed_value(const std::string& name) {
  const size_t dot = name.find('.');
  return dot != std::string::npos && dot > 0 && dot + 1 < name.size() && name.find('.', dot + 1) == std::string::npos;
}

// Parses `text`; on failure returns false with `*error` = "file:line:col: error: ...".
bool parse_scene(std::string_view text, const std::string& file, Scene* out, Diagnostic* error);

// A diagnostic at the JSON value `pointer` ("/inputs/position") of the scene's text.
Diagnostic scene_diagnostic(const Scene& scene, const std::string& pointer, const std::string& message);

// A diagnostic for nlohmann's parse_error `e` on `text` ("WHAT is not valid JSON: ...").
Diagnostic json_syntax_diagnostic(std::string_view text, const std::string& file, const std::string& what,
                                  const std::exception& e, size_t byte);

// Byte offset of the value at JSON pointer `pointer` in valid JSON `text` (0 when not found).
size_t json_value_offset(std::string_view text, const std::string& pointer);

}  // namespace doublet::plan
