// rename_functions_named_like_builtins: on GLSL ES targets, a user function whose name is a
// built-in function's (`double exp(double)`, `float mix(float)`) is renamed, with every call of it.
//
// Why: desktop GLSL lets a shader overload built-in names, GLSL ES does not (The OpenGL ES
// Shading Language 3.00.6, section 6.1: "built-in functions cannot be redefined or overloaded";
// ES 1.00 section 6.1 likewise). A desktop shader lowered for ES kept such a name and the
// re-validation failed ("function name is redeclaration of existing name"): an internal error.
// Which names are built-ins of the target and stage is asked of glslang, in one parse of a
// probe that declares every user function's name, rather than kept in a table here.
#include <map>
#include <set>
#include <string>

#include "target/glslang_checks.hpp"
#include "target/target.hpp"
#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
bool rename_functions_named_like_builtins(ir::Module& module, Context& ctx) {
  if (ctx.config.facts->overloads_builtin_names) return true;
  std::set<std::string> user_functions, taken;
  for (const auto& f : module.functions)
    if (f->name != "main") user_functions.insert(f->name);
  if (user_functions.empty()) return true;
  // glslang's ES 1.00 accepts an overload of a built-in name (the probe's) and refuses only a
  // redefinition, which fp32's demotion makes of `double exp(double)`: ES 1.00 asks ES 3.00's
  // names (a superset; renaming one more function there is harmless).
  const Target probe_target = ctx.config.target == Target::Es100 ? Target::Es300 : ctx.config.target;
  const std::set<std::string> builtins = target::builtin_function_names(user_functions, probe_target, module.stage);
  if (builtins.empty()) return true;
  for (const auto& f : module.functions) taken.insert(f->name);
  for (const auto& g : module.globals) taken.insert(g->name);
  for (const auto& t : module.structs) taken.insert(t.name);
  std::map<std::string, std::string> new_name;
  for (const auto& name : builtins) {
    std::string candidate = name + "_user";
    for (int n = 2; taken.count(candidate); ++n) candidate = name + "_user" + std::to_string(n);
    taken.insert(candidate);
    new_name[name] = candidate;
  }
  for (auto& f : module.functions)
    if (auto it = new_name.find(f->name); it != new_name.end()) f->name = it->second;
  const ir::ExprVisitor rename_calls = [&](const ir::ExprPtr& e) {
    if (e->kind != ir::Expr::Kind::Call) return;
    if (auto it = new_name.find(e->name); it != new_name.end()) e->name = it->second;
  };
  for (const auto& f : module.functions) ir::visit(f->body, rename_calls);
  for (const auto& init : module.global_inits)
    if (init) ir::visit(init, rename_calls);
  return true;
}

}  // namespace doublet::passes
