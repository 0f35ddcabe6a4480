#include "ir/check.hpp"

#include <map>
#include <set>

namespace doublet::ir {
namespace {

class Checker {
 public:
  std::string problem;

  void function(const Function& f) {
    function_ = &f;
    declared_.clear();
    params_.clear();
    for (const auto& p : f.params)
      if (p) params_.insert(p.get());
    if (!f.body) return fail("function '" + f.name + "' has no body");
    stmt(f.body);
    for (const Var* v : used_locals_)
      if (!declared_.count(v)) return fail("local '" + v->name + "' is used in '" + f.name + "' but not declared there");
    used_locals_.clear();
  }

  void global_init(const ExprPtr& e) {
    function_ = nullptr;
    if (e) expr(e);
  }

 private:
  void fail(const std::string& what) {
    if (problem.empty()) problem = what;
  }
  std::string where() const { return function_ ? " in '" + function_->name + "'" : " in a global initialiser"; }

  void stmt(const StmtPtr& s) {
    if (!problem.empty()) return;
    if (!s) return fail("a null statement" + where());
    using K = Stmt::Kind;
    switch (s->kind) {
      case K::Decl:
        if (!s->var) return fail("a declaration without a variable" + where());
        if (s->var->storage == Storage::Local && !declared_.insert(s->var.get()).second)
          return fail("local '" + s->var->name + "' is declared twice" + where());
        break;
      case K::If:
        if (s->body.empty() || s->body.size() > 2 || !s->body[0] || !s->expr) return fail("a malformed if" + where());
        break;
      case K::Loop:
        if (s->body.size() != 2 || !s->body[1]) return fail("a malformed loop" + where());
        if (s->body[0]) stmt(s->body[0]);
        if (s->expr) expr(s->expr);
        if (s->step) expr(s->step);
        stmt(s->body[1]);
        return;
      case K::Switch:
        if (s->body.size() != 1 || !s->expr) return fail("a malformed switch" + where());
        break;
      case K::Expr:
        if (!s->expr) return fail("an expression statement without an expression" + where());
        break;
      default: break;
    }
    if (s->expr) expr(s->expr);
    if (s->step) expr(s->step);
    for (const auto& b : s->body)
      if (b || s->kind != K::If) stmt(b);
  }

  void expr(const ExprPtr& e) {
    if (!problem.empty()) return;
    if (!e) return fail("a null expression" + where());
    using K = Expr::Kind;
    size_t want = 0;
    switch (e->kind) {
      case K::Unary: want = 1; break;
      case K::Binary: want = 2; break;
      case K::Ternary: want = 3; break;
      case K::Member: want = 1; break;
      case K::Index: want = 2; break;
      default: want = e->args.size(); break;
    }
    if (e->args.size() != want)
      return fail("a " + kind_name(e->kind) + " with " + std::to_string(e->args.size()) + " operands" + where());
    if (e->kind == K::Sym) {
      if (!e->var) return fail("a symbol without a variable" + where());
      const Var* v = e->var.get();
      if (v->storage == Storage::Local && function_) used_locals_.insert(v);
      const bool param = v->storage == Storage::ParamIn || v->storage == Storage::ParamOut ||
                         v->storage == Storage::ParamInOut;
      if (param && function_ && !params_.count(v))
        return fail("parameter '" + v->name + "' is used in '" + function_->name + "', which does not have it");
    }
    for (const auto& a : e->args) expr(a);
  }

  static std::string kind_name(Expr::Kind k) {
    switch (k) {
      case Expr::Kind::Unary: return "unary operation";
      case Expr::Kind::Binary: return "binary operation";
      case Expr::Kind::Ternary: return "ternary";
      case Expr::Kind::Member: return "member access";
      case Expr::Kind::Index: return "index";
      default: return "node";
    }
  }

  const Function* function_ = nullptr;
  std::set<const Var*> declared_, params_, used_locals_;
};

}  // namespace

std::string check(const Module& module) {
  Checker c;
  for (const auto& init : module.global_inits) c.global_init(init);
  for (const auto& f : module.functions) {
    if (!f) return "a null function";
    c.function(*f);
  }
  return c.problem;
}

}  // namespace doublet::ir
