// Locations of stage inputs and outputs the shader leaves to the linker, given where the target
// cannot leave them (docs/architecture.md, pass table):
//
// assign_fragment_output_locations: GLSL ES 3.00 and later need a location on every fragment
// output of a shader that has several (The OpenGL ES Shading Language 3.00, section 4.3.8.2;
// WebGL2/ANGLE: "must explicitly specify all locations when using multiple fragment outputs"), and
// WGSL on every output; desktop GLSL lets the linker (or glBindFragDataLocation) choose. Outputs
// without one get the free locations in declaration order, which is what the manifest then records,
// and a warning names them so the user can choose instead.
//
// assign_wgsl_io_locations: WGSL has no linker either: every vertex input, inter-stage variable and
// fragment output of the entry point carries @location(N). After split-interfaces (hi/lo and word
// variables are interface variables of their own), each one without a location gets the first free
// run of locations in declaration order, and the manifest records every interface variable's
// locations, so that a WebGPU host builds its vertex buffer layout from the manifest alone.
#include <set>

#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

// Locations a variable fills: one per array element and matrix column.
int location_slots(const ir::Var& v) {
  int n = std::max(v.type.cols, 1);
  for (int d : v.type.array_dims) n *= std::max(d, 1);
  return n;
}

// Gives each variable without a location the first free run of locations, in order; returns the
// variables that got one.
std::vector<ir::VarPtr> assign_free_locations(const std::vector<ir::VarPtr>& vars) {
  std::set<int> held;
  for (const auto& v : vars)
    if (v->layout.location >= 0)
      for (int k = 0; k < location_slots(*v); ++k) held.insert(v->layout.location + k);
  std::vector<ir::VarPtr> assigned;
  int next = 0;
  for (const auto& v : vars) {
    if (v->layout.location >= 0) continue;
    const int n = location_slots(*v);
    const auto free_run = [&](int at) {
      for (int k = 0; k < n; ++k)
        if (held.count(at + k)) return false;
      return true;
    };
    while (!free_run(next)) ++next;
    v->layout.location = next;
    for (int k = 0; k < n; ++k) held.insert(next + k);
    next += n;
    assigned.push_back(v);
  }
  return assigned;
}

std::vector<ir::VarPtr> user_interface(const ir::Module& module, ir::Storage storage) {
  std::vector<ir::VarPtr> vars;
  for (const auto& g : module.globals)
    if (g->storage == storage && g->name.rfind("gl_", 0) != 0) vars.push_back(g);
  return vars;
}

}  // namespace

bool assign_fragment_output_locations(ir::Module& module, Context& context) {
  if (module.stage != ir::StageKind::Fragment) return true;
  std::vector<ir::VarPtr> outputs = user_interface(module, ir::Storage::Out);
  if (outputs.size() < 2) return true;
  const std::vector<ir::VarPtr> assigned = assign_free_locations(outputs);
  if (assigned.empty()) return true;
  std::string list;
  for (const auto& v : assigned)
    list += (list.empty() ? "" : ", ") + ("'" + v->name + "' = " + std::to_string(v->layout.location));
  context.warning(assigned.front()->loc, "fragment outputs without a location get locations in declaration order (" + list +
                                             "): the target needs one on each of several outputs; write layout(location = N) to choose");
  return true;
}

bool assign_wgsl_io_locations(ir::Module& module, Manifest& manifest) {
  if (module.stage != ir::StageKind::Vertex && module.stage != ir::StageKind::Fragment) return true;
  std::map<std::string, const ir::Var*> by_name;
  for (ir::Storage storage : {ir::Storage::In, ir::Storage::Out}) {
    std::vector<ir::VarPtr> vars = user_interface(module, storage);
    assign_free_locations(vars);
    for (const auto& v : vars) by_name[v->name] = v.get();
  }
  for (InterfaceVariable& entry : manifest.variables) {
    if (entry.storage != "in" && entry.storage != "out") continue;
    std::vector<int> locations;
    for (const std::string& name : entry.lowered_names)
      if (auto it = by_name.find(name); it != by_name.end()) locations.push_back(it->second->layout.location);
    if (locations.size() == entry.lowered_names.size()) entry.locations = locations;
  }
  return true;
}

}  // namespace doublet::passes
