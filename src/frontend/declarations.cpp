#include "frontend/declarations.hpp"

#include <map>
#include <set>

#include "ir/walk.hpp"

namespace doublet::frontend {
namespace {

using ir::Expr;
using ir::Stmt;

// `v = e` with v a local that e does not read.
const ir::Var* initialised_local(const ir::StmtPtr& s) {
  if (!s || s->kind != Stmt::Kind::Expr || s->expr->kind != Expr::Kind::Binary || s->expr->op != "=") return nullptr;
  const auto& lhs = s->expr->args[0];
  if (lhs->kind != Expr::Kind::Sym || lhs->var->storage != ir::Storage::Local) return nullptr;
  if (ir::count_uses(s->expr->args[1], lhs->var.get()) != 0) return nullptr;
  return lhs->var.get();
}

ir::StmtPtr make_decl(const ir::StmtPtr& assign) {
  auto d = Stmt::make(Stmt::Kind::Decl, assign->loc);
  d->var = assign->expr->args[0]->var;
  d->expr = assign->expr->args[1];
  return d;
}

class Placer {
 public:
  explicit Placer(const ir::StmtPtr& body) {
    ir::visit(body, [&](const ir::ExprPtr& e) {
      if (e->kind == Expr::Kind::Sym && e->var->storage == ir::Storage::Local) {
        if (!total_.count(e->var.get())) order_.push_back(e->var);
        ++total_[e->var.get()];
      }
    });
  }

  // Adds `sign` for every reference to a local in `s` (the references ir::count_uses counts).
  static void add_uses(const ir::StmtPtr& s, std::map<const ir::Var*, int>& uses, int sign) {
    ir::visit(s, [&](const ir::ExprPtr& e) {
      if (e->kind == Expr::Kind::Sym && e->var->storage == ir::Storage::Local) uses[e->var.get()] += sign;
    });
  }

  void place(std::vector<ir::StmtPtr>& list) {
    // Uses of each local in list[i..]: counted once for the list, then each statement's own
    // uses are taken off as i passes it (linear in the list, not quadratic).
    std::map<const ir::Var*, int> remaining;
    for (const auto& s : list) add_uses(s, remaining, +1);
    for (size_t i = 0; i < list.size(); ++i) {
      ir::StmtPtr& s = list[i];
      const ir::StmtPtr original = s;
      if (const ir::Var* v = initialised_local(s); v && !declared_.count(v) && remaining[v] == total_[v]) {
        declared_.insert(v);
        s = make_decl(s);
      }
      add_uses(original, remaining, -1);
      descend(s);
    }
  }

  // Declarations for every local not declared in place, in first-use order.
  std::vector<ir::StmtPtr> hoisted() const {
    std::vector<ir::StmtPtr> out;
    for (const auto& v : order_) {
      if (declared_.count(v.get())) continue;
      auto d = Stmt::make(Stmt::Kind::Decl, v->loc);
      d->var = v;
      out.push_back(d);
    }
    return out;
  }

 private:
  void descend(const ir::StmtPtr& s) {
    switch (s->kind) {
      case Stmt::Kind::Block: place(s->body); break;
      case Stmt::Kind::If:
      case Stmt::Kind::Switch:
        for (auto& b : s->body) descend(b);
        break;
      case Stmt::Kind::Loop: {
        // The for-init's scope is the loop itself.
        if (const ir::Var* v = initialised_local(s->body[0]); v && !declared_.count(v) &&
                                                              ir::count_uses(s, v) == total_[v]) {
          declared_.insert(v);
          s->body[0] = make_decl(s->body[0]);
        }
        descend(s->body[1]);
        break;
      }
      default: break;
    }
  }

  std::map<const ir::Var*, int> total_;
  std::vector<ir::VarPtr> order_;
  std::set<const ir::Var*> declared_;
};

void collect_locals(const ir::StmtPtr& s, std::vector<ir::VarPtr>& out, std::set<const ir::Var*>& seen) {
  if (!s) return;
  if (s->kind == Stmt::Kind::Decl && seen.insert(s->var.get()).second) out.push_back(s->var);
  for (const auto& b : s->body) collect_locals(b, out, seen);
}

}  // namespace

bool place_declarations(ir::Module& module, const Options& options, std::vector<Diagnostic>& diagnostics) {
  bool ok = true;
  // Mode exact's runtime (rules/exact.glsl) is named ex_*: reserved there too, or a user's `ex_add`
  // would collide with it in the lowered text.
  const bool exact = options.mode == Mode::Exact || options.mode == Mode::RteExact;
  auto reserved = [&](const std::string& name, ir::Loc loc) {
    const bool df = name.rfind("df_", 0) == 0, ex = exact && name.rfind("ex_", 0) == 0;
    if (!df && !ex) return;
    diagnostics.push_back({ir::file_of(loc, options.file_name), loc.line, loc.column, Severity::Error,
                           "identifier '" + name + "' uses the prefix '" + (df ? "df_" : "ex_") +
                               "', which doublet reserves for its " + (df ? "float-float" : "binary64 (mode exact)") +
                               " runtime; rename it"});
    ok = false;
  };

  std::set<std::string> global_names;
  for (const auto& t : module.structs) { global_names.insert(t.name); reserved(t.name, {}); }
  for (const auto& g : module.globals) {
    global_names.insert(g->name);
    reserved(g->name, g->loc);
    if (g->type.base == ir::Base::Block && g->type.fields)
      for (const auto& f : *g->type.fields) global_names.insert(f.name);
  }
  for (const auto& f : module.functions) { global_names.insert(f->name); reserved(f->name, f->loc); }

  for (const auto& f : module.functions) {
    Placer placer(f->body);
    placer.place(f->body->body);
    auto hoisted = placer.hoisted();
    f->body->body.insert(f->body->body.begin(), hoisted.begin(), hoisted.end());

    std::vector<ir::VarPtr> locals(f->params.begin(), f->params.end());
    std::set<const ir::Var*> seen;
    for (const auto& p : f->params) seen.insert(p.get());
    collect_locals(f->body, locals, seen);
    std::set<std::string> local_names;  // not a copy of global_names per function: that was quadratic
    auto taken = [&](const std::string& name) { return global_names.count(name) || local_names.count(name); };
    for (const auto& v : locals) {
      reserved(v->name, v->loc);
      std::string name = v->name;
      for (int n = 1; taken(name); ++n) name = ir::join_identifier(v->name, "_" + std::to_string(n));
      v->name = name;
      local_names.insert(name);
    }
  }
  return ok;
}

}  // namespace doublet::frontend
