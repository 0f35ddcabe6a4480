// guard_constants: where the guard is a uniform, every float-float constant in a function body
// reads it: `df_double(hi, lo)` becomes `df_double(hi - G, lo - G)`, G the guard as the rules read
// it (`df_guard`, or `df_guard[int(df_guard[1])]` where Config::indexed_guard()).
//
// Why: the guard keeps a driver from rewriting a rule's steps only where one operand of each step
// is unknown at compile time. When every operand of an operation is a constant (two literals,
// `f(2.53lf, 0.13lf)` once f is inlined), a driver's constant folding and reassociation evaluate
// the steps in an order of its own and the low word is lost: 25.7 bits on lavapipe for es310
// (docs/accuracy.md, "Constants the driver folds"). G is 0, so each word keeps its value
// (-0.0 - 0.0 is -0.0), but no compiler may assume it.
//
// Global initialisers stay constant expressions (GLSL ES requires them); global-inits moves the
// initialisers holding float-float constants into main first, so that they are reached here.
// A `const` local keeps its initialiser for the same reason (glslang folds those into the
// expressions that read them, which are rewritten).
#include <algorithm>
#include <cmath>

#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"
#include "ir/walk.hpp"

namespace doublet::passes {
namespace {

using Kind = ir::Expr::Kind;

// One word of a float-float constant: a float scalar, vector or matrix constant.
bool is_float_word(const ir::ExprPtr& e) {
  return e->kind == Kind::Const && e->type.base == ir::Base::Float && !e->type.is_array();
}

class GuardConstants {
 public:
  explicit GuardConstants(const pipeline::Config& config) : config_(config) {}

  ir::ExprPtr rewrite(const ir::ExprPtr& e) {
    if (!is_float_float_constant(e)) return e;
    read_ = true;
    return ir::make_node(Kind::Construct, "", e->type, {guarded(e->args[0]), guarded(e->args[1])}, e->loc);
  }
  bool read() const { return read_; }

 private:
  static bool is_positive_zero(const ir::Scalar& v) { return v.d == 0 && !std::signbit(v.d); }

  // A scalar word with the guard: `c - G`, but `0.0 + G` for +0.0. Both are c when G is +0 (and
  // -0.0 - G keeps -0.0), but drivers rewrite 0.0 - G as -G, which is -0.0
  // (docs/accuracy.md, "Constants the driver folds").
  ir::ExprPtr with_guard(const ir::ExprPtr& word) const {
    const bool plus = word->values.size() == 1 && is_positive_zero(word->values[0]);
    return plus ? ir::make_binary("+", word->type, word, guard_value(config_, word->loc)) : less_guard(word, config_);
  }

  // A word with the guard. A vector without +0.0 components as a whole (`vec2(0.1, 0.3) - G`);
  // otherwise, and for matrices (WGSL, which this GLSL is translated to, has no matrix - scalar),
  // one component at a time.
  ir::ExprPtr guarded(const ir::ExprPtr& word) const {
    const bool whole = word->type.vec == 1 && !word->type.is_matrix();
    const bool has_positive_zero = std::any_of(word->values.begin(), word->values.end(), is_positive_zero);
    if (whole || (!word->type.is_matrix() && !has_positive_zero)) return with_guard(word);
    std::vector<ir::ExprPtr> elements;
    for (const ir::Scalar& v : word->values) {
      auto element = ir::Expr::make(Kind::Const, ir::scalar_type(ir::Base::Float), word->loc);
      element->values = {v};
      elements.push_back(with_guard(element));
    }
    return ir::make_node(Kind::Construct, "", word->type, elements, word->loc);
  }

  const pipeline::Config& config_;
  bool read_ = false;  // a constant was rewritten: the guard must be declared
};

}  // namespace

ir::ExprPtr guard_value(const pipeline::Config& config, ir::Loc loc) {
  auto guard = std::make_shared<ir::Var>();  // declared by the runtime linker, not a module global
  guard->name = config.guard_uniform;
  guard->storage = ir::Storage::Uniform;
  guard->type = ir::scalar_type(ir::Base::Float);
  if (!config.guard_is_indexed()) return ir::make_sym(guard, loc);
  guard->type.array_dims = {rules::kIndexedGuardElements};
  auto index = ir::make_node(Kind::Construct, "", ir::scalar_type(ir::Base::Int), {ir::make_index(ir::make_sym(guard, loc), 1)}, loc);
  return ir::make_node(Kind::Index, "", ir::scalar_type(ir::Base::Float), {ir::make_sym(guard, loc), index}, loc);
}

ir::ExprPtr less_guard(const ir::ExprPtr& word, const pipeline::Config& config) {
  return ir::make_binary("-", word->type, word, guard_value(config, word->loc));
}

bool is_float_float_value(const ir::Type& t) { return !t.is_array() && (is_df(t) || matrix::is_matrix(t)); }

bool guards_constants(const pipeline::Config& config) {
  return config.guard == rules::GuardStyle::Uniform && !config.native() && !config.binary64_words();
}

bool is_float_float_constant(const ir::ExprPtr& e) {
  return e->kind == Kind::Construct && is_float_float_value(e->type) && e->args.size() == 2 && is_float_word(e->args[0]) && is_float_word(e->args[1]);
}

bool guard_constants(ir::Module& module, Context& ctx) {
  GuardConstants pass(ctx.config);
  const ir::ExprRewriter rewrite = [&](const ir::ExprPtr& e) { return pass.rewrite(e); };
  for (const auto& f : module.functions)
    ir::visit_statements(f->body, [&](const ir::StmtPtr& s) {
      if (s->kind == ir::Stmt::Kind::Decl && s->var->storage == ir::Storage::Const) return;
      s->expr = ir::rewrite(s->expr, rewrite);
      s->step = ir::rewrite(s->step, rewrite);
    });
  ctx.guard_read_outside_rules = ctx.guard_read_outside_rules || pass.read();
  return !ctx.failed;
}

}  // namespace doublet::passes
