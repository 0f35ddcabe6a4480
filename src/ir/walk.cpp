#include "ir/walk.hpp"

namespace doublet::ir {

void visit(const ExprPtr& e, const ExprVisitor& f) {
  if (!e) return;
  f(e);
  for (const auto& a : e->args) visit(a, f);
}

void visit(const StmtPtr& s, const ExprVisitor& f) {
  if (!s) return;
  visit(s->expr, f);
  visit(s->step, f);
  for (const auto& b : s->body) visit(b, f);
}

void visit_statements(const StmtPtr& s, const std::function<void(const StmtPtr&)>& f) {
  if (!s) return;
  f(s);
  for (const auto& b : s->body) visit_statements(b, f);
}

ExprPtr rewrite(const ExprPtr& e, const ExprRewriter& f) {
  if (!e) return e;
  for (auto& a : e->args) a = rewrite(a, f);
  ExprPtr replacement = f(e);
  return replacement ? replacement : e;
}

void rewrite(const StmtPtr& s, const ExprRewriter& f) {
  if (!s) return;
  s->expr = rewrite(s->expr, f);
  s->step = rewrite(s->step, f);
  for (auto& b : s->body) rewrite(b, f);
}

int count_uses(const ExprPtr& e, const Var* v) {
  int n = 0;
  visit(e, [&](const ExprPtr& x) { n += x->kind == Expr::Kind::Sym && x->var.get() == v; });
  return n;
}

int count_uses(const StmtPtr& s, const Var* v) {
  int n = 0;
  visit(s, [&](const ExprPtr& x) { n += x->kind == Expr::Kind::Sym && x->var.get() == v; });
  return n;
}

}  // namespace doublet::ir
