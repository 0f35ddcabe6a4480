// guard_uniform_reads: where no rule reads the guard (Config::reads_uniforms_through_guard: the
// `precise` targets and df64-int), every read of a float-float value in a uniform block or a
// struct uniform becomes `T(e.hi - G, e.lo - G)`, G the indexed guard. split_interfaces does the
// same for loose double uniforms when it joins their words at the top of main.
//
// Why: lavapipe specialises a shader on the uniforms that decide a branch; a condition computed
// from a block's double and constants alone made it fold the float-float code on that value and
// spend minutes compiling it (differential tester seed 15035: df64-int for es320 gave no result in
// 60 s; docs/accuracy.md, "Lavapipe's inliner on the user's own uniforms"). With the guard in
// every such read, no condition is computed from uniforms and constants alone.
//
// The wrapped expression is the longest access path of float-float type rooted at the uniform
// (`b0`, `params.b0`, `params.arr[i]`), so what reads a word or a component of it (`b0.hi.y`)
// reads the guarded value. A path whose index has effects is left as it is (it would be
// evaluated twice).
#include "ir/walk.hpp"
#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"

namespace doublet::passes {
namespace {

using Kind = ir::Expr::Kind;

// A variable access rooted at a uniform that is not yet a float-float value (a block, a struct,
// an array): what a float-float path continues.
bool is_uniform_path(const ir::ExprPtr& e) {
  switch (e->kind) {
    case Kind::Sym: return e->var->storage == ir::Storage::Uniform;
    case Kind::Member: return !is_float_float_value(e->args[0]->type) && is_uniform_path(e->args[0]);
    case Kind::Index:
      return !is_float_float_value(e->args[0]->type) && ir::is_pure(e->args[1]) && is_uniform_path(e->args[0]);
    default: return false;
  }
}

// The type of a float-float value's hi and lo words.
ir::Type word_type(const ir::Type& t) {
  if (is_df(t)) return ir::scalar_type(ir::Base::Float, df_width(t));
  ir::Type m = ir::scalar_type(ir::Base::Float, matrix::rows(t));
  m.cols = matrix::cols(t);
  return m;
}

ir::ExprPtr word_of(const ir::ExprPtr& value, const char* word) {
  auto member = ir::Expr::make(Kind::Member, word_type(value->type), value->loc);
  member->name = word;
  member->args = {value};
  return member;
}

class GuardUniformReads {
 public:
  explicit GuardUniformReads(Context& ctx) : ctx_(ctx) {}

  // Pre-order: a word of a uniform's float-float value (`b0.hi`, what a component read starts
  // from) becomes `(b0.hi - G)`; the value itself, read whole, `T(b0.hi - G, b0.lo - G)`.
  ir::ExprPtr rewrite(const ir::ExprPtr& e) {
    if (!e) return e;
    if (e->kind == Kind::Member && (e->name == "hi" || e->name == "lo") && is_float_float_value(e->args[0]->type) &&
        is_uniform_path(e->args[0]))
      return read(less_guard(e, ctx_.config));
    if (is_float_float_value(e->type) && is_uniform_path(e))
      return read(ir::make_node(Kind::Construct, "", e->type,
                                {less_guard(word_of(e, "hi"), ctx_.config), less_guard(word_of(ir::clone(e), "lo"), ctx_.config)},
                                e->loc));
    for (auto& a : e->args) a = rewrite(a);
    return e;
  }

 private:
  ir::ExprPtr read(ir::ExprPtr guarded) {
    ctx_.guard_read_outside_rules = true;
    return guarded;
  }

  Context& ctx_;
};

}  // namespace

bool guard_uniform_reads(ir::Module& module, Context& ctx) {
  GuardUniformReads pass(ctx);
  for (const auto& f : module.functions)
    ir::visit_statements(f->body, [&](const ir::StmtPtr& s) {
      s->expr = pass.rewrite(s->expr);
      s->step = pass.rewrite(s->step);
    });
  return !ctx.failed;
}

}  // namespace doublet::passes
