// hoist_commas (--target wgsl only): WGSL has no comma operator. A comma inside a statement's
// expression, `s = f((t = a, t * b))`, becomes statements before it, `t = a; s = f(t * b);`, where
// that cannot change what the statement computes (GLSL 4.60, 5.9: the left operands are evaluated
// first, then the right one, which gives the value):
//   - the comma is evaluated whenever the statement is: not under the right operand of && or ||,
//     a branch of ?:, nor in a loop's condition or step (those keep the WGSL printer's refusal);
//   - the statement is a direct child of a block (an expression statement, a declaration, a
//     return, the condition of an if or a switch);
//   - neither its left operands nor the rest of the statement (less the comma) calls a built-in
//     with effects, no variable one of them writes is used by the other (a runtime call with an out
//     parameter counts as writing what is passed to it, a call of the user's as writing all it is
//     passed), and where one calls a function of the user's the other touches no global. What
//     encloses the comma (an assignment, a call) takes effect after it, hoisted or not: a call
//     counts as reading its arguments, the variable an enclosing assignment writes is free to
//     be read or written by the comma (`v[6] = (t2 = modf(x, t1), v[8] = t1, t2)`).
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
  std::set<const ir::Var*> targets;  // written by an enclosing assignment, after the comma
  bool opaque = false, calls = false;
  bool touches_globals() const {
    auto global = [](const ir::Var* v) { return !ir::is_function_local(v->storage) && v->storage != ir::Storage::Const; };
    return calls || std::any_of(reads.begin(), reads.end(), global) || std::any_of(writes.begin(), writes.end(), global);
  }
};

// Collects over `e`, leaving out the subtree `skip`. The effects of `after` (the comma's ancestors:
// a call, an assignment) happen once their operands, the comma among them, are evaluated: they
// count as reads only.
void collect(const ir::ExprPtr& e, const ir::ExprPtr& skip, const std::set<const Expr*>& after, const Context& ctx,
             Access& a) {
  if (!e || e == skip) return;
  if (e->kind == Kind::Sym) a.reads.insert(e->var.get());
  if (after.count(e.get())) {
    // An enclosing plain assignment writes its target once the comma is evaluated: the target's
    // variable is kept apart (indices in it are read as usual).
    if (e->kind == Kind::Binary && e->op == "=" && e->args[0]->kind != Kind::Sym)
      if (const ir::Var* v = ir::root_variable(e->args[0])) {
        a.targets.insert(v);
        for (ir::ExprPtr part = e->args[0]; part->kind == Kind::Index || part->kind == Kind::Member; part = part->args[0])
          if (part->kind == Kind::Index) collect(part->args[1], skip, after, ctx, a);
        collect(e->args[1], skip, after, ctx, a);
        return;
      }
    for (const auto& arg : e->args) collect(arg, skip, after, ctx, a);
    return;
  }
  if (e->kind == Kind::Call && !is_runtime_call(*e)) {
    a.calls = true;
    for (const auto& arg : e->args)
      if (const ir::Var* v = ir::root_variable(arg)) a.writes.insert(v);
  }
  if (is_runtime_call(*e) && ctx.runtime_call_writes_arguments(*e))
    for (const auto& arg : e->args)
      if (const ir::Var* v = ir::root_variable(arg)) a.writes.insert(v);
  if (e->kind == Kind::Builtin && ir::builtin_has_side_effects(e->name)) a.opaque = true;
  if ((e->kind == Kind::Binary && ir::is_assignment_operator(e->op)) || ir::is_increment(*e)) {
    if (const ir::Var* v = ir::root_variable(e->args[0])) a.writes.insert(v);
    else a.opaque = true;
  }
  for (const auto& arg : e->args) collect(arg, skip, after, ctx, a);
}

// The nodes from `root` down to `target` (both included); empty when `target` is not under it.
bool path_to(const ir::ExprPtr& root, const ir::ExprPtr& target, std::set<const Expr*>& path) {
  if (!root) return false;
  if (root == target) return path.insert(root.get()), true;
  for (const auto& arg : root->args)
    if (path_to(arg, target, path)) return path.insert(root.get()), true;
  return false;
}

bool meet(const std::set<const ir::Var*>& x, const std::set<const ir::Var*>& y) {
  for (const ir::Var* v : x)
    if (y.count(v)) return true;
  return false;
}

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
      if (!statement || !statement->expr) continue;
      const auto k = statement->kind;
      if (k != ir::Stmt::Kind::Expr && k != ir::Stmt::Kind::Decl && k != ir::Stmt::Kind::Return &&
          k != ir::Stmt::Kind::If && k != ir::Stmt::Kind::Switch)
        continue;
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
    size_t operands = e->args.size();
    if ((e->kind == Kind::Binary && (e->op == "&&" || e->op == "||")) || e->kind == Kind::Ternary) operands = 1;
    for (size_t a = 0; a < operands; ++a)
      if (ir::ExprPtr c = find_comma(e->args[a], false)) return c;
    return nullptr;
  }

  // The conditions of the header comment, for `comma` inside `statement`: its left operands and
  // the rest of the statement (less the comma) touch no variable one writes and the other uses.
  bool movable(const ir::StmtPtr& statement, const ir::ExprPtr& comma) const {
    Access left, rest;
    for (size_t a = 0; a + 1 < comma->args.size(); ++a) collect(comma->args[a], nullptr, {}, ctx_, left);
    std::set<const Expr*> ancestors;
    path_to(statement->expr, comma, ancestors);
    collect(statement->expr, comma, ancestors, ctx_, rest);
    if (statement->kind == ir::Stmt::Kind::Decl && statement->var) rest.reads.insert(statement->var.get());
    // rest.targets are written after the comma is evaluated, hoisted or not: no conflict.
    return !left.opaque && !rest.opaque && !meet(left.writes, rest.reads) && !meet(left.writes, rest.writes) &&
           !meet(left.reads, rest.writes) && !(left.calls && rest.touches_globals()) &&
           !(rest.calls && left.touches_globals());
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
