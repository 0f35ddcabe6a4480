// uniform_defaults: `uniform double zoom = 1.0lf;` and `uniform int n = 4;` (desktop GLSL 1.20+:
// the value a uniform has until the application sets one).
//
// Every such value goes to the manifest (InterfaceVariable::default_value, the original numbers).
// Where the target has uniform initializers (desktop GLSL) the lowered shader keeps them: a
// non-double uniform as written, a split double as X_hi = hi, X_lo = lo (split_interfaces).
// GLSL ES and WGSL have none, and mode exact's words are not written here: there the uniform is
// declared without one, and one warning says that the application must set the manifest's value
// (doublet verify and the host helpers do; README, `--manifest`). A struct
// initializer is refused: the manifest has no place for one.
#include <string>
#include <vector>

#include "lower/lower.hpp"
#include "target/target.hpp"

namespace doublet::passes {

bool uniform_defaults(ir::Module& module, Context& ctx) {
  const bool target_keeps = ctx.config.facts->uniform_initializers();
  std::vector<std::string> dropped;
  ir::Loc first;
  for (size_t i = 0; i < module.globals.size(); ++i) {
    const ir::VarPtr& v = module.globals[i];
    ir::ExprPtr& init = module.global_inits[i];
    if (v->storage != ir::Storage::Uniform || !init) continue;
    if (init->kind != ir::Expr::Kind::Const) {
      ctx.error(v->loc, "uniform '" + v->name + "' has a struct initializer: doublet carries initializers of "
                        "scalars, vectors, matrices and arrays of them; set its value from the application");
      continue;
    }
    std::vector<double>& value = ctx.uniform_defaults[v.get()];
    for (const ir::Scalar& s : init->values)
      value.push_back(s.base == ir::Base::Bool ? (s.b ? 1.0 : 0.0)
                      : s.base == ir::Base::Int || s.base == ir::Base::Uint ? static_cast<double>(s.i)
                                                                             : s.d);
    const bool words = ctx.config.binary64_words() && v->declared_type.contains_double();
    if (target_keeps && !words) continue;
    init = nullptr;
    if (dropped.empty()) first = v->loc;
    dropped.push_back("'" + v->name + "'");
  }
  if (!dropped.empty()) {
    std::string names;
    for (size_t k = 0; k < dropped.size(); ++k) names += (k ? ", " : "") + dropped[k];
    const std::string why = target_keeps ? std::string("mode exact declares double uniforms as words without one")
                                         : "target " + std::string(to_string(ctx.config.output)) +
                                               " has no uniform initializers";
    ctx.warning(first, "uniform" + std::string(dropped.size() > 1 ? "s " : " ") + names + " declared with an initializer: " +
                           why + ", so the lowered shader starts at 0; the manifest lists the value (\"default\") for "
                           "the application to set");
  }
  return !ctx.failed;
}

}  // namespace doublet::passes
