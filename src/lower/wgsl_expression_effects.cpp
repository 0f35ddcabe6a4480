// wgsl_expression_effects (--target wgsl only): WGSL's `x++` and assignments are statements, never
// parts of an expression. An increment or an assignment whose value the statement uses
// (`r[n++] = x`, `v[m++] + v[m++]`, `(acc = a * b) + acc`) becomes a comma over a temporary the
// pass declares at the top of the function, which evaluates to the same value:
//
//   x++      →  (t = x, x = x + 1, t)          ++x     →  (x = x + 1, t = x, t)
//   a = b    →  (t = b, a = t, t)               a += b  →  (t = a + b, a = t, t)
//
// and an index with effects, `x[next(c)]`, becomes `x[(t = next(c), t)]`; then hoist-commas moves
// those commas before their statement, where it can (its conditions), so that `r[n++] = x` prints
// as `t = n; n = n + 1; r[t] = x;`. It runs before wgsl-out-arguments,
// whose copies need the index of a buffer element free of effects (`r[n++] += y` through the
// compound-assignment helper). Only the operands evaluated whenever the statement is are rewritten
// that way. An operand evaluated only sometimes, with effects (under && or ||, a branch of ?:),
// makes its whole && / || / ?: statements before the statement, where hoist-commas' conditions
// allow: `t = a; if (t) { t = b; }`, `if (c) { t = x; } else { t = y; }`, the inner statements
// rewritten in turn. A for or while condition with effects becomes `if (!(c)) break;` at the top
// of the body. A loop's step and a do-while's condition keep the WGSL printer's refusal. The assigned
// place is written back through the same access, so an access whose indices have effects is left
// as it is (it has been rewritten first, inner operands before outer ones). Increments of integer
// and float scalars and vectors only (a double's is a call of the runtime by now); assignments of
// any type (a float-float pair's too).
#include <string>
#include <vector>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

// What `x = x + 1` can step: integer and float scalars and vectors.
bool steppable(const ir::Type& t) {
  return (t.base == ir::Base::Int || t.base == ir::Base::Uint || t.base == ir::Base::Float) && !t.is_array() &&
         !t.is_matrix();
}

ExprPtr one_like(const ir::Type& t, ir::Loc loc) {
  ir::Type scalar = t;
  scalar.vec = 1;
  auto c = Expr::make(Kind::Const, scalar, loc);
  ir::Scalar v;
  v.base = t.base;
  v.d = 1.0;
  v.i = 1;
  c->values = {v};
  return c;
}

// An access whose evaluation has no effect and reads the same place when repeated.
bool plain_access(const ExprPtr& e) {
  if (e->kind == Kind::Sym) return true;
  if (e->kind == Kind::Member) return plain_access(e->args[0]);
  if (e->kind == Kind::Index) return plain_access(e->args[0]) && ir::is_pure(e->args[1]) && !ir::has_side_effects(e->args[1]);
  return false;
}

class EffectRewriter {
 public:
  EffectRewriter(ir::Module& m, const Context& ctx) : module_(m), ctx_(ctx) {}

  void run() {
    rewrite_functions_with_temporaries(module_, temporaries_, [&](const ir::StmtPtr& body) { rewrite_block(body); });
  }

 private:
  void rewrite_block(const ir::StmtPtr& s) {
    if (!s) return;
    if (s->kind == ir::Stmt::Kind::Loop) test_inside(*s);
    for (const auto& child : s->body) rewrite_block(child);
    if (s->kind != ir::Stmt::Kind::Block) return;
    for (size_t i = 0; i < s->body.size(); ++i) {
      const ir::StmtPtr statement = s->body[i];
      if (!has_leading_expression(statement)) continue;
      const auto k = statement->kind;
      // A && / || / ?: whose conditional operand has effects: if/else before the statement.
      while (ExprPtr conditional = find_conditional(statement->expr)) {
        if (!can_move_before(statement, conditional, {conditional}, ctx_)) break;
        s->body.insert(s->body.begin() + static_cast<long>(i), as_statements(statement, conditional));
        ++i;
      }
      // An expression statement's own assignment or increment (or a whole-statement comma's
      // operands) is a statement already: only what is below it is rewritten.
      ExprPtr& root = statement->expr;
      const bool statement_level = k == ir::Stmt::Kind::Expr;
      if (statement_level && root->kind == Kind::Comma) {
        for (auto& operand : root->args) rewrite_below(operand);
      } else if (statement_level && is_effect(*root)) {
        rewrite_below(root);
      } else {
        root = rewrite(root);
      }
    }
  }

  // A for or while loop whose condition has effects tests it at the top of its body instead
  // (`if (!(cond)) break;`), where it is a statement. `continue` still runs the step, then the
  // body's test. A do-while's test would follow a `continue` in its body: left as it is.
  void test_inside(ir::Stmt& loop) {
    if (!loop.test_first || !loop.expr || !has_effects(loop.expr)) return;
    auto negated = ir::make_node(Kind::Unary, "", loop.expr->type, {loop.expr}, loop.expr->loc);
    negated->op = "!";
    auto test = ir::Stmt::make(ir::Stmt::Kind::If, loop.loc);
    test->expr = negated;
    auto leave = ir::Stmt::make(ir::Stmt::Kind::Block, loop.loc);
    leave->body.push_back(ir::Stmt::make(ir::Stmt::Kind::Break, loop.loc));
    test->body.push_back(leave);
    auto body = ir::Stmt::make(ir::Stmt::Kind::Block, loop.loc);
    body->body = {test, loop.body[1]};
    loop.body[1] = body;
    loop.expr = nullptr;
  }

  // Effects an operand WGSL evaluates only sometimes must not be inside an expression: an
  // increment, an assignment, a comma, a built-in with effects, a call of the user's, a runtime
  // call that writes its arguments.
  bool has_effects(const ExprPtr& e) const {
    bool found = false;
    ir::visit(e, [&](const ExprPtr& x) {
      if (is_effect(*x) || x->kind == Kind::Comma || (x->kind == Kind::Builtin && ir::builtin_has_side_effects(x->name)))
        found = true;
      else if (x->kind == Kind::Call)
        found = found || !is_runtime_call(*x) || ctx_.runtime_call_writes_arguments(*x);
    });
    return found;
  }

  // The first && / || / ?: evaluated whenever `e` is whose conditional operands have effects.
  ExprPtr find_conditional(const ExprPtr& e) const {
    if (!e) return nullptr;
    const bool logical = e->kind == Kind::Binary && (e->op == "&&" || e->op == "||");
    if ((logical && has_effects(e->args[1])) ||
        (e->kind == Kind::Ternary && (has_effects(e->args[1]) || has_effects(e->args[2]))))
      return e;
    for (size_t a = 0; a < ir::unconditional_operands(*e); ++a)
      if (ExprPtr c = find_conditional(e->args[a])) return c;
    return nullptr;
  }

  // `a && b` → { t = a; if (t) { t = b; } }, `a || b` → { t = a; if (!t) { t = b; } },
  // `c ? x : y` → { if (c) { t = x; } else { t = y; } }; `conditional` becomes t in `statement`.
  ir::StmtPtr as_statements(const ir::StmtPtr& statement, const ExprPtr& conditional) {
    const ir::Loc loc = conditional->loc;
    ir::VarPtr t = temporary(conditional->type, loc);
    auto assign_to_t = [&](const ExprPtr& value) {
      auto block = ir::Stmt::make(ir::Stmt::Kind::Block, loc);
      auto st = ir::Stmt::make(ir::Stmt::Kind::Expr, loc);
      st->expr = ir::make_binary("=", conditional->type, ir::make_sym(t, loc), value);
      block->body.push_back(st);
      return block;
    };
    auto result = ir::Stmt::make(ir::Stmt::Kind::Block, loc);
    auto branch = ir::Stmt::make(ir::Stmt::Kind::If, loc);
    if (conditional->kind == Kind::Ternary) {
      branch->expr = conditional->args[0];
      branch->body = {assign_to_t(conditional->args[1]), assign_to_t(conditional->args[2])};
    } else {
      result->body = assign_to_t(conditional->args[0])->body;
      branch->expr = ir::make_sym(t, loc);
      if (conditional->op == "||") {
        branch->expr = ir::make_node(Kind::Unary, "", conditional->type, {ir::make_sym(t, loc)}, loc);
        branch->expr->op = "!";
      }
      branch->body = {assign_to_t(conditional->args[1])};
    }
    result->body.push_back(branch);
    statement->expr =
        ir::rewrite(statement->expr, [&](const ExprPtr& e) { return e == conditional ? ir::make_sym(t, loc) : nullptr; });
    rewrite_block(result);
    return result;
  }

  static bool is_effect(const Expr& e) {
    return (e.kind == Kind::Binary && ir::is_assignment_operator(e.op)) || ir::is_increment(e);
  }

  void rewrite_below(ExprPtr& e) {
    if (!is_effect(*e)) {
      e = rewrite(e);
      return;
    }
    for (size_t a = 0; a < ir::unconditional_operands(*e); ++a) e->args[a] = rewrite(e->args[a]);
  }


  // Post-order over the unconditional operands: inner effects first, so an index's increment is a
  // temporary before its access is judged.
  ExprPtr rewrite(const ExprPtr& e) {
    if (!e) return e;
    if (e->kind == Kind::Comma) {  // its left operands' values are dropped: statements once hoisted
      for (size_t a = 0; a + 1 < e->args.size(); ++a) rewrite_below(e->args[a]);
      e->args.back() = rewrite(e->args.back());
      return e;
    }
    for (size_t a = 0; a < ir::unconditional_operands(*e); ++a) e->args[a] = rewrite(e->args[a]);
    // An index with effects (`x[next(c)] *= y`) is computed once into a temporary, so that the
    // access can be repeated (wgsl-out-arguments' copy back, a compound assignment).
    if (e->kind == Kind::Index && e->args[1]->kind != Kind::Comma && ir::has_side_effects(e->args[1])) {
      const ExprPtr& index = e->args[1];
      ir::VarPtr t = temporary(index->type, index->loc);
      auto store = ir::make_binary("=", index->type, ir::make_sym(t, index->loc), index);
      e->args[1] = ir::make_node(Kind::Comma, "", index->type, {store, ir::make_sym(t, index->loc)}, index->loc);
      return e;
    }
    if (!is_effect(*e) || !plain_access(e->args[0]) || e->type.base == ir::Base::Void) return e;
    if (ir::is_increment(*e) && !steppable(e->type)) return e;
    const ExprPtr& place = e->args[0];
    ir::VarPtr t = temporary(e->type, e->loc);
    std::vector<ExprPtr> sequence;
    if (ir::is_increment(*e)) {
      const std::string op = e->op.find("++") != std::string::npos ? "+" : "-";
      const ExprPtr next = ir::make_binary(op, e->type, ir::clone(place), one_like(e->type, e->loc));
      const ExprPtr step = ir::make_binary("=", e->type, ir::clone(place), next);
      if (e->op[0] == 'x') {  // x++: the old value
        sequence = {ir::make_binary("=", e->type, ir::make_sym(t, e->loc), ir::clone(place)), step};
      } else {
        sequence = {step, ir::make_binary("=", e->type, ir::make_sym(t, e->loc), ir::clone(place))};
      }
    } else {
      ExprPtr value = e->args[1];
      if (e->op != "=") value = ir::make_binary(e->op.substr(0, e->op.size() - 1), e->type, ir::clone(place), value);
      sequence = {ir::make_binary("=", e->type, ir::make_sym(t, e->loc), value),
                  ir::make_binary("=", e->type, ir::clone(place), ir::make_sym(t, e->loc))};
    }
    sequence.push_back(ir::make_sym(t, e->loc));
    return ir::make_node(Kind::Comma, "", e->type, sequence, e->loc);
  }

  ir::VarPtr temporary(const ir::Type& type, ir::Loc loc) {
    return declare_temporary("df_value" + std::to_string(++counter_), type, loc, temporaries_);
  }

  ir::Module& module_;
  const Context& ctx_;
  std::vector<ir::StmtPtr> temporaries_;
  int counter_ = 0;
};

}  // namespace

bool wgsl_expression_effects(ir::Module& module, Context& context) {
  EffectRewriter(module, context).run();
  return hoist_commas(module, context);
}

}  // namespace doublet::passes
