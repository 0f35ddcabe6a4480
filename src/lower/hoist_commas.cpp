// hoist_commas (--target wgsl only): WGSL has no comma operator. A comma inside a statement's
// expression, `s = f((t = a, t * b))`, becomes statements before it, `t = a; s = f(t * b);`, where
// that cannot change what the statement computes (GLSL 4.60, 5.9: the left operands are evaluated
// first, then the right one, which gives the value):
//   - the comma is evaluated whenever the statement is: not under the right operand of && or ||,
//     a branch of ?:, nor in a loop's condition or step (those keep the WGSL printer's refusal);
//   - the statement is a direct child of a block (an expression statement, a declaration, a
//     return, the condition of an if or a switch);
//   - its left operands and what the statement evaluates before the comma (left to right, as
//     glslang and WGSL do: the operands left of the comma's at each level, an assignment's target
//     indices) call no built-in with effects, no variable one of them writes is used by the other
//     (a runtime call with an out parameter counts as writing what is passed to it, a call of the
//     user's as writing all it is passed), and where one calls a function of the user's the other
//     touches no global. What the statement evaluates after the comma stays after its left
//     operands once they are hoisted, so `s = take(w.z) + take(w.x)` moves both calls' commas, and
//     the variable an enclosing assignment writes is free to be used by the comma
//     (`v[6] = (t2 = modf(x, t1), v[8] = t1, t2)`).
// The pass runs on the lowered IR, so the intermediate GLSL the WGSL is printed from has no such
// comma left. docs/web.md ("The WGSL target") lists what is still refused.
#include <algorithm>
#include <functional>
#include <set>
#include <vector>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using Kind = ir::Expr::Kind;

// What a part of a statement reads and writes; `opaque` when it has an effect this pass does not
// follow (a built-in with effects, a write through an expression). A call of the user's may read and
// write any global (a buffer, a private global) and what is passed to it, nothing else: a function
// cannot reach its caller's locals but through its out parameters.
struct Access {
  std::set<const ir::Var*> reads, writes;
  bool opaque = false, calls = false;
  bool touches_globals() const {
    auto global = [](const ir::Var* v) { return !ir::is_function_local(v->storage) && v->storage != ir::Storage::Const; };
    return calls || std::any_of(reads.begin(), reads.end(), global) || std::any_of(writes.begin(), writes.end(), global);
  }
};

// Collects what `e` reads and writes.
void collect(const ir::ExprPtr& e, const Context& ctx, Access& a) {
  if (!e) return;
  if (e->kind == Kind::Sym) a.reads.insert(e->var.get());
  if (e->kind == Kind::Call && !is_runtime_call(*e)) {
    a.calls = true;
    for (const auto& arg : e->args)
      if (const ir::Var* v = ir::root_variable(arg)) a.writes.insert(v);
  }
  if (is_runtime_call(*e) && ctx.runtime_call_writes_arguments(*e))
    for (const auto& arg : e->args)
      if (const ir::Var* v = ir::root_variable(arg)) a.writes.insert(v);
  if (ir::builtin_writes_second_argument(*e)) {
    if (const ir::Var* v = ir::root_variable(e->args[1])) a.writes.insert(v);
    else a.opaque = true;
  } else if (e->kind == Kind::Builtin && ir::builtin_has_side_effects(e->name)) {
    a.opaque = true;
  }
  if ((e->kind == Kind::Binary && ir::is_assignment_operator(e->op)) || ir::is_increment(*e)) {
    if (const ir::Var* v = ir::root_variable(e->args[0])) a.writes.insert(v);
    else a.opaque = true;
  }
  for (const auto& arg : e->args) collect(arg, ctx, a);
}

bool meet(const std::set<const ir::Var*>& x, const std::set<const ir::Var*>& y) {
  for (const ir::Var* v : x)
    if (y.count(v)) return true;
  return false;
}

bool contains(const ir::ExprPtr& e, const ir::ExprPtr& target) {
  if (!e) return false;
  if (e == target) return true;
  return std::any_of(e->args.begin(), e->args.end(), [&](const ir::ExprPtr& x) { return contains(x, target); });
}

// What is evaluated before `comma` inside `e`, left to right (glslang's order, and WGSL's): at
// each node on the way down, the operands left of the one holding the comma. An assignment's
// target counts as evaluated before its value (its indices read, the variable not: it is written
// after the comma either way). What follows the comma keeps its place after the comma's left
// operands once they are hoisted, so it needs no check.
void collect_before(const ir::ExprPtr& e, const ir::ExprPtr& comma, const Context& ctx, Access& a) {
  if (!e || e == comma) return;
  size_t holder = 0;
  while (holder < e->args.size() && !contains(e->args[holder], comma)) ++holder;
  if (holder == e->args.size()) return;
  const bool assignment = e->kind == Kind::Binary && ir::is_assignment_operator(e->op);
  // `a[i][f()]`: before the index, the access's own indices are evaluated, no element is read.
  const bool access = e->kind == Kind::Index && holder == 1;
  const bool path_first = (access || (assignment && e->op == "=")) && ir::root_variable(e->args[0]);
  for (size_t i = 0; i < holder; ++i) {
    if (path_first && i == 0) {
      for (ir::ExprPtr part = e->args[0]; part->kind == Kind::Index || part->kind == Kind::Member; part = part->args[0])
        if (part->kind == Kind::Index) collect(part->args[1], ctx, a);
      continue;
    }
    collect(e->args[i], ctx, a);
  }
  collect_before(e->args[holder], comma, ctx, a);
}

}  // namespace

bool can_move_before(const ir::StmtPtr& statement, const ir::ExprPtr& part, const std::vector<ir::ExprPtr>& evaluated,
                     const Context& ctx) {
  Access left, before;
  for (const auto& e : evaluated) collect(e, ctx, left);
  collect_before(statement->expr, part, ctx, before);
  if (statement->kind == ir::Stmt::Kind::Decl && statement->var) before.reads.insert(statement->var.get());
  return !left.opaque && !before.opaque && !meet(left.writes, before.reads) && !meet(left.writes, before.writes) &&
         !meet(left.reads, before.writes) && !(left.calls && before.touches_globals()) &&
         !(before.calls && left.touches_globals());
}

namespace {

class CommaHoister {
 public:
  CommaHoister(ir::Module& m, const Context& c) : module_(m), ctx_(c) {}

  void run() {
    for (const auto& f : module_.functions) hoist_in_block(f->body);
  }

 private:
  void hoist_in_block(const ir::StmtPtr& s) {
    if (!s) return;
    for (const auto& child : s->body) hoist_in_block(child);
    if (s->kind != ir::Stmt::Kind::Block) return;
    for (size_t i = 0; i < s->body.size(); ++i) {
      const ir::StmtPtr statement = s->body[i];
      if (!has_leading_expression(statement)) continue;
      const auto k = statement->kind;
      // The printer writes a whole-statement comma as statements already.
      const bool whole_is_comma = k == ir::Stmt::Kind::Expr && statement->expr->kind == Kind::Comma;
      while (ir::ExprPtr comma = find_comma(statement->expr, whole_is_comma)) {
        if (!movable(statement, comma)) break;
        std::vector<ir::StmtPtr> before;
        for (size_t a = 0; a + 1 < comma->args.size(); ++a) {
          auto hoisted = ir::Stmt::make(ir::Stmt::Kind::Expr, comma->args[a]->loc);
          hoisted->expr = comma->args[a];
          before.push_back(hoisted);
        }
        const ir::ExprPtr value = comma->args.back();
        statement->expr = ir::rewrite(statement->expr, [&](const ir::ExprPtr& e) { return e == comma ? value : nullptr; });
        s->body.insert(s->body.begin() + static_cast<long>(i), before.begin(), before.end());
        i += before.size();
      }
    }
  }

  // The first comma evaluated whenever `e` is (pre-order, unconditional operands only).
  static ir::ExprPtr find_comma(const ir::ExprPtr& e, bool skip_self) {
    if (!e) return nullptr;
    if (e->kind == Kind::Comma && !skip_self) return e;
    for (size_t a = 0; a < ir::unconditional_operands(*e); ++a)
      if (ir::ExprPtr c = find_comma(e->args[a], false)) return c;
    return nullptr;
  }

  bool movable(const ir::StmtPtr& statement, const ir::ExprPtr& comma) const {
    const std::vector<ir::ExprPtr> left(comma->args.begin(), comma->args.end() - 1);
    return can_move_before(statement, comma, left, ctx_);
  }

  ir::Module& module_;
  const Context& ctx_;
};

}  // namespace

bool hoist_commas(ir::Module& module, Context& context) {
  CommaHoister(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
