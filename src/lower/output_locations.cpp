// assign_fragment_output_locations: GLSL ES 3.00 and later need a location on every fragment
// output of a shader that has several (The OpenGL ES Shading Language 3.00, section 4.3.8.2;
// WebGL2/ANGLE: "must explicitly specify all locations when using multiple fragment outputs"), and
// WGSL on every output; desktop GLSL lets the linker (or glBindFragDataLocation) choose. Outputs
// without one get the free locations in declaration order, which is what the manifest then records,
// and a warning names them so the user can choose instead.
#include <set>

#include "lower/lower.hpp"

namespace doublet::passes {

bool assign_fragment_output_locations(ir::Module& module, Context& context) {
  if (module.stage != ir::StageKind::Fragment) return true;
  std::vector<ir::VarPtr> outputs;
  for (const auto& g : module.globals)
    if (g->storage == ir::Storage::Out && g->name.rfind("gl_", 0) != 0) outputs.push_back(g);
  if (outputs.size() < 2) return true;
  const auto slots = [](const ir::Var& v) {
    int n = 1;
    for (int d : v.type.array_dims) n *= std::max(d, 1);
    return n;
  };
  std::set<int> held;
  for (const auto& v : outputs)
    if (v->layout.location >= 0)
      for (int k = 0; k < slots(*v); ++k) held.insert(v->layout.location + k);
  std::string assigned;
  ir::Loc first;
  int next = 0;
  for (const auto& v : outputs) {
    if (v->layout.location >= 0) continue;
    const int n = slots(*v);
    const auto free_run = [&](int at) {
      for (int k = 0; k < n; ++k)
        if (held.count(at + k)) return false;
      return true;
    };
    while (!free_run(next)) ++next;
    v->layout.location = next;
    for (int k = 0; k < n; ++k) held.insert(next + k);
    next += n;
    if (assigned.empty()) first = v->loc;
    assigned += (assigned.empty() ? "" : ", ") + ("'" + v->name + "' = " + std::to_string(v->layout.location));
  }
  if (!assigned.empty())
    context.warning(first, "fragment outputs without a location get locations in declaration order (" + assigned +
                               "): the target needs one on each of several outputs; write layout(location = N) to choose");
  return true;
}

}  // namespace doublet::passes
