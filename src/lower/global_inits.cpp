// move_global_initialisers: a global whose initialiser is not a constant expression is
// initialised at the top of main instead, in declaration order.
//
// Why: a double uniform or input X is split into X_hi/X_lo and joined into the private df_*
// global X at the top of main (split_interfaces), so an initialiser that reads X at global
// scope would read it before the join (zero: a silently wrong value). GLSL ES also requires
// constant global initialisers (ES 1.00 §4.3, ES 3.00 §4.3) and forbids calling functions from
// global scope, which every lowered double operation does (df_* calls). Global initialisers run
// before main in declaration order, so running them first thing in main, in the same order,
// computes the same values. Runs after lower_doubles, before split_interfaces (whose join is
// then inserted in front of these assignments).
//
// Where the guard is a uniform, an initialiser holding a float-float constant moves too, although
// it is constant: guard_constants (which runs after) makes every such constant in a function body
// read the guard, and a global initialiser must stay a constant expression.
#include <algorithm>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using Kind = ir::Expr::Kind;

// A constant expression in the sense of GLSL ES: literals, constants, and constructors,
// operators and built-ins over them; never a user function (every df_* rule is one).
bool is_constant_expression(const ir::ExprPtr& e) {
  switch (e->kind) {
    case Kind::Const: return true;
    case Kind::Sym: return e->var->storage == ir::Storage::Const;
    case Kind::Call: return false;
    default:
      return std::all_of(e->args.begin(), e->args.end(), is_constant_expression);
  }
}

bool holds_float_float_constant(const ir::ExprPtr& e) {
  bool found = false;
  ir::visit(e, [&](const ir::ExprPtr& x) {
    found = found || is_float_float_constant(x);
  });
  return found;
}

ir::StmtPtr assignment(const ir::VarPtr& target, const ir::ExprPtr& value) {
  return ir::make_statement(ir::make_assign(ir::make_sym(target), value));
}

}  // namespace

bool move_global_initialisers(ir::Module& module, Context& ctx) {
  auto main = std::find_if(module.functions.begin(), module.functions.end(),
                           [](const ir::FunctionPtr& f) { return f->name == "main"; });
  if (main == module.functions.end()) return !ctx.failed;
  const bool guard_reads_constants = guards_constants(ctx.config);
  std::vector<ir::StmtPtr> moved;
  for (size_t i = 0; i < module.globals.size(); ++i) {
    ir::ExprPtr& init = module.global_inits[i];
    if (!init || module.globals[i]->storage != ir::Storage::Global) continue;
    if (is_constant_expression(init) && !(guard_reads_constants && holds_float_float_constant(init))) continue;
    moved.push_back(assignment(module.globals[i], init));
    init = nullptr;
  }
  auto& body = (*main)->body->body;
  body.insert(body.begin(), moved.begin(), moved.end());
  return !ctx.failed;
}

}  // namespace doublet::passes
