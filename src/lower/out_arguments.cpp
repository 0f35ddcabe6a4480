// out_argument_temporaries: a component of a double vector or matrix passed to an out/inout
// parameter (`f(v.y)`, `f(m[1])`, `f(m[1][2])`) goes through a temporary the pass declares. After
// lowering, such a component is a value built from two words (df_double(v.hi.y, v.lo.y)), which
// GLSL cannot pass as an lvalue; a whole double variable can. GLSL's own semantics are copy-in,
// copy-out (GLSL 4.60 §6.1.1), so the temporary changes nothing:
//
//   f(v.y);              →   { df_out1 = v.y; f(df_out1); v.y = df_out1; }
//   x = g(v.y) + 1.0;    →   x = (df_out1 = v.y, df_out2 = g(df_out1), v.y = df_out1, df_out2) + 1.0;
//
// The first form where the call is a whole statement, the second anywhere else (it stays one
// expression, so it is right inside a loop condition or a && operand). The temporaries are declared,
// uninitialised, at the top of the enclosing function. The argument is written back through the
// same access, so it is rewritten only when evaluating that access twice reads the same place: its
// indices are computed by operators from constants and local variables that the call cannot write.
// Others keep the lowering's diagnostic ("use a temporary").
//
// For --target wgsl the same rewrite runs again after lowering on every out/inout argument that is
// not a whole local variable (`f(buf[i])`, `f(g)` with g a global), of a user's function, a
// generated helper (its head), a rule (its signature) or float modf/frexp: WGSL passes them as
// pointers, which may point to function memory only. Its temporaries are df_argN (df_outN are the
// first run's, in the same functions). The comma form is then moved before its statement by
// hoist-commas where it can be; what stays keeps the WGSL printer's refusal.
#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using Kind = ir::Expr::Kind;

bool same_type(const ir::Type& a, const ir::Type& b) {
  return a.base == b.base && a.vec == b.vec && a.cols == b.cols && a.array_dims == b.array_dims && a.name == b.name;
}

// A swizzle or index of a double vector or matrix (not of an array or a struct: those are lvalues
// after lowering too).
bool is_double_component(const ir::ExprPtr& e) {
  if (e->kind != Kind::Member && e->kind != Kind::Index) return false;
  const ir::Type& base = e->args[0]->type;
  return base.is_double() && !base.is_array() && (base.vec > 1 || base.is_matrix());
}

// A whole local variable or parameter: what a WGSL pointer argument may point to (function memory).
bool is_whole_local(const ir::ExprPtr& e) { return e->kind == Kind::Sym && ir::is_function_local(e->var->storage); }

class OutArgumentRewriter {
 public:
  // wgsl: after lowering, every out/inout argument that is not a whole local variable (WGSL's
  // pointers point to function memory only: a buffer element, a global, a component); else, before
  // lowering, a component of a double vector or matrix.
  OutArgumentRewriter(ir::Module& m, const Context& context, bool wgsl) : module_(m), context_(context), wgsl_(wgsl) {}

  void run() {
    rewrite_functions_with_temporaries(module_, temporaries_, [&](const ir::StmtPtr& body) { rewrite_block(body); });
  }

 private:
  const ir::Function* callee(const ir::ExprPtr& call) const {
    const auto found = ir::overloads(module_, *call, [&](const ir::Var& param, const ir::Expr& arg) {
      return same_type(wgsl_ ? param.type : param.declared_type, arg.type);
    });
    return found.empty() ? nullptr : found.front();
  }

  // The storage of each parameter of `call`: a user function's, or (wgsl, after lowering) a
  // generated helper's or a rule's (df_assign_component_* on a buffer element, modf's whole part);
  // empty for anything else.
  std::vector<ir::Storage> parameters(const ir::ExprPtr& call) const {
    std::vector<ir::Storage> params;
    if (call->kind == Kind::Builtin) {
      // modf's whole part, frexp's exponent (the float forms; the double ones are rules by now).
      if (wgsl_ && ir::builtin_writes_second_argument(*call))
        params = {ir::Storage::ParamIn, ir::Storage::ParamOut};
    } else if (const ir::Function* f = callee(call)) {
      for (const auto& p : f->params) params.push_back(p->storage);
    } else if (wgsl_) {
      params = context_.runtime_parameters(*call);
      if (params.size() != call->args.size()) params.clear();
    }
    return params;
  }

  // An index computed without effects: constants and variables joined by operators (`i + 4u`).
  static bool is_plain_index(const ir::ExprPtr& e) {
    switch (e->kind) {
      case Kind::Sym:
      case Kind::Const: return true;
      case Kind::Unary:
        if (e->op.size() == 3) return false;  // ++x, x--
        break;
      case Kind::Binary:
        if (ir::is_assignment_operator(e->op)) return false;
        break;
      case Kind::Member:
      case Kind::Index:
      case Kind::Construct: break;
      default: return false;
    }
    return std::all_of(e->args.begin(), e->args.end(), is_plain_index);
  }

  // An access path (variable, members, indices) whose indices are plain.
  static bool is_plain_access(const ir::ExprPtr& e) {
    if (e->kind == Kind::Sym) return true;
    if (e->kind == Kind::Member) return is_plain_access(e->args[0]);
    if (e->kind == Kind::Index) return is_plain_access(e->args[0]) && is_plain_index(e->args[1]);
    return false;
  }

  // Evaluating `arg` again after the call reads the same place: every variable in its indices is a
  // constant or a local variable that is not what another out/inout argument of the call writes.
  static bool stable(const ir::ExprPtr& arg, const ir::ExprPtr& call, const std::vector<ir::Storage>& params) {
    if (!is_plain_access(arg)) return false;
    bool ok = true;
    std::vector<const ir::Var*> passed;
    for (size_t i = 0; i < call->args.size(); ++i)
      if (call->args[i] != arg && ir::is_out_parameter(params[i]))
        if (const ir::Var* v = ir::root_variable(call->args[i])) passed.push_back(v);
    std::function<void(const ir::ExprPtr&)> check = [&](const ir::ExprPtr& e) {
      if (e->kind == Kind::Index) {
        ir::visit(e->args[1], [&](const ir::ExprPtr& i) {
          if (i->kind != Kind::Sym) return;
          const ir::Storage s = i->var->storage;
          const bool local = ir::is_function_local(s) || s == ir::Storage::Const;
          if (!local || std::find(passed.begin(), passed.end(), i->var.get()) != passed.end()) ok = false;
        });
      }
      if (e->kind == Kind::Index || e->kind == Kind::Member) check(e->args[0]);
    };
    check(arg);
    return ok;
  }

  ir::VarPtr temporary(const ir::Type& type, ir::Loc loc) {
    // Its own prefix for --target wgsl: the pass runs again after lowering, in the same functions.
    return declare_temporary((wgsl_ ? "df_arg" : "df_out") + std::to_string(++counter_), type, loc, temporaries_);
  }

  // The copy-in assignments, the call on the temporaries and the copy-out assignments; empty when
  // the call passes no double component to an out/inout parameter (or one it cannot rewrite).
  struct Parts {
    std::vector<ir::ExprPtr> before, after;
    ir::ExprPtr call;
  };
  bool split(const ir::ExprPtr& call, Parts& parts) {
    if (call->kind != Kind::Call && call->kind != Kind::Builtin) return false;
    const std::vector<ir::Storage> params = parameters(call);
    if (params.empty()) return false;
    ir::ExprPtr rewritten = ir::make_node(call->kind, call->name, call->type, call->args, call->loc);
    for (size_t i = 0; i < params.size(); ++i) {
      const ir::ExprPtr& arg = call->args[i];
      const bool needs_copy = wgsl_ ? !is_whole_local(arg) : is_double_component(arg);
      if (!ir::is_out_parameter(params[i]) || !needs_copy || !stable(arg, call, params)) continue;
      ir::VarPtr tmp = temporary(arg->type, arg->loc);
      if (params[i] == ir::Storage::ParamInOut)
        parts.before.push_back(ir::make_assign(ir::make_sym(tmp, arg->loc), ir::clone(arg)));
      parts.after.push_back(ir::make_assign(ir::clone(arg), ir::make_sym(tmp, arg->loc)));
      rewritten->args[i] = ir::make_sym(tmp, arg->loc);
    }
    parts.call = rewritten;
    return !parts.after.empty();
  }

  void rewrite_block(const ir::StmtPtr& s) {
    if (!s) return;
    for (size_t i = 0; i < s->body.size(); ++i) {
      const ir::StmtPtr child = s->body[i];
      if (!child) continue;
      Parts parts;
      // A call that is a whole statement: the copies become statements around it (calls nested in
      // its arguments first, in the comma form).
      const bool call_statement = s->kind == ir::Stmt::Kind::Block && child->kind == ir::Stmt::Kind::Expr &&
                                  child->expr && child->expr->kind == Kind::Call;
      if (call_statement)
        for (auto& arg : child->expr->args) arg = rewrite_expr(arg);
      if (call_statement && split(child->expr, parts)) {
        auto block = ir::Stmt::make(ir::Stmt::Kind::Block, child->loc);
        auto statement = [&](const ir::ExprPtr& e) {
          auto st = ir::Stmt::make(ir::Stmt::Kind::Expr, e->loc);
          st->expr = e;
          block->body.push_back(st);
        };
        for (const auto& e : parts.before) statement(e);
        statement(parts.call);
        for (const auto& e : parts.after) statement(e);
        s->body[i] = block;
        continue;
      }
      rewrite_block(child);
    }
    if (s->expr) s->expr = rewrite_expr(s->expr);
    if (s->step) s->step = rewrite_expr(s->step);
  }

  ir::ExprPtr rewrite_expr(const ir::ExprPtr& root) {
    return ir::rewrite(root, [&](const ir::ExprPtr& e) -> ir::ExprPtr {
      Parts parts;
      if (!split(e, parts)) return nullptr;
      std::vector<ir::ExprPtr> sequence = parts.before;
      ir::VarPtr result;
      if (e->type.base == ir::Base::Void) {
        sequence.push_back(parts.call);
      } else {
        result = temporary(e->type, e->loc);
        sequence.push_back(ir::make_assign(ir::make_sym(result, e->loc), parts.call));
      }
      sequence.insert(sequence.end(), parts.after.begin(), parts.after.end());
      if (result) sequence.push_back(ir::make_sym(result, e->loc));
      return ir::make_node(Kind::Comma, "", sequence.back()->type, sequence, e->loc);
    });
  }

  ir::Module& module_;
  const Context& context_;
  const bool wgsl_;
  std::vector<ir::StmtPtr> temporaries_;
  int counter_ = 0;
};

}  // namespace

bool out_argument_temporaries(ir::Module& module, Context& context) {
  OutArgumentRewriter(module, context, false).run();
  return !context.failed;
}

bool wgsl_out_argument_temporaries(ir::Module& module, Context& context) {
  OutArgumentRewriter(module, context, true).run();
  return !context.failed;
}

}  // namespace doublet::passes
