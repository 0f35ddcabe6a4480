// Backward pass of the analysis: sensitivities of one output (analysis.hpp, docs/plan.md).
#include <cmath>

#include "plan/analysis_internal.hpp"
#include "plan/transcendentals.hpp"

namespace doublet::plan {
using namespace detail;

struct Backward {
  Analysis& a;
  std::map<const Expr*, double>& node_weight;
  std::map<const Var*, double>& store_weight;
  std::map<const Var*, double> W;  // sensitivity of the output to v's current value
  int loop_depth = 0;
  struct Frame { double ret = 0; std::map<const Var*, double> exit; };
  std::vector<Frame> frames;
  int depth = 0;

  static double add(double x, double y) { return x + y; }
  void note(const Expr* e, double w) {
    if (w == 0) return;
    node_weight[e] = add(node_weight[e], loop_depth > 0 ? kInf : w);
  }
  void store(const Var* v, double w) {
    if (w == 0) return;
    store_weight[v] = add(store_weight[v], loop_depth > 0 ? kInf : w);
  }
  const Analysis::Node* info(const Expr* e) const {
    auto it = a.nodes_.find(e);
    return it == a.nodes_.end() ? nullptr : it->second.get();
  }
  Box arg_range(const Expr* e, size_t i) const {
    const Analysis::Node* n = info(e);
    return n && i < n->args.size() ? n->args[i] : Box{Interval::top()};
  }
  static double mul(double w, double k) { return w == 0 || k == 0 ? 0 : w * k; }
  static double div(double w, double k) { return w == 0 ? 0 : k == 0 ? kInf : w / k; }

  // Weight w on the value of an assignment through `lhs`; the stored value gets W[v] + w.
  double assigned_weight(const ir::ExprPtr& lhs, double w, bool kill) {
    bool whole = false;
    const Var* v = lvalue_root(lhs, &whole);
    if (lhs->kind == Expr::Kind::Index) expr(lhs->args[1], 0);
    if (!v) return w;
    const double total = W[v] + w;
    store(v, total);
    if (whole && kill) W[v] = 0;
    return total;
  }

  void call(const Expr& e, double w) {
    const ir::Function* f = resolve_call(*a.module_, e);
    if (!f || !f->body || depth > 32) {
      for (const auto& x : e.args) expr(x, w == 0 ? 0 : kInf);
      return;
    }
    ++depth;
    // Out parameters receive the callee's final value: their weight flows into the parameter.
    for (size_t i = 0; i < f->params.size(); ++i) {
      const Var* p = f->params[i].get();
      if (ir::is_out_parameter(p->storage))
        W[p] = assigned_weight(e.args[i], 0, true);
      else
        W[p] = 0;
    }
    frames.push_back({w, W});
    stmt(f->body);
    frames.pop_back();
    for (size_t i = 0; i < f->params.size(); ++i) {
      const Var* p = f->params[i].get();
      const double wp = W[p];
      store(p, wp);
      W[p] = 0;
      if (p->storage != ir::Storage::ParamOut) expr(e.args[i], wp);
    }
    --depth;
  }

  void builtin(const Expr& e, double w) {
    const std::string& f = e.name;
    auto r = [&](size_t i) { return arg_range(&e, i); };
    auto pass = [&](size_t i, double k) { expr(e.args[i], mul(w, k)); };
    const size_t n = e.args.empty() ? 0 : static_cast<size_t>(components(e.args[0]->type));
    if (f == "abs" || f == "min" || f == "max" || f == "clamp" || f == "floor" || f == "ceil" || f == "trunc" ||
        f == "round" || f == "roundEven" || f == "fract" || f == "mod") {
      // 1-Lipschitz in each argument (floor & co. jump, but by an amount the same in both shaders
      // except at the jump itself: a documented limit).
      for (size_t i = 0; i < e.args.size(); ++i) pass(i, 1);
      return;
    }
    if (f == "sqrt") { pass(0, div(1, 2 * std::sqrt(Analysis::hull(r(0)).mig()))); return; }
    if (f == "dot") {
      double s0 = 0, s1 = 0;
      for (const Interval& c : r(1)) s0 += c.mag();
      for (const Interval& c : r(0)) s1 += c.mag();
      pass(0, s0);
      pass(1, s1);
      return;
    }
    if (f == "length") { pass(0, std::sqrt(static_cast<double>(n))); return; }
    if (f == "distance") { pass(0, std::sqrt(static_cast<double>(n))); pass(1, std::sqrt(static_cast<double>(n))); return; }
    if (f == "normalize") {
      Interval len2 = Interval::point(0);
      for (const Interval& c : r(0)) len2 = len2 + square(c);
      pass(0, div(2 * std::sqrt(static_cast<double>(n)), std::sqrt(len2.mig())));
      return;
    }
    if (f == "mix" && e.args.size() == 3 && e.args[2]->type.base != ir::Base::Bool) {
      const Interval t = Analysis::hull(r(2));
      pass(0, std::max(std::fabs(1 - t.lo), std::fabs(1 - t.hi)));
      pass(1, t.mag());
      pass(2, mag(r(0)) + mag(r(1)));
      return;
    }
    if (f == "cross") { pass(0, 2 * mag(r(1))); pass(1, 2 * mag(r(0))); return; }
    if (f == "fma") { pass(0, mag(r(1))); pass(1, mag(r(0))); pass(2, 1); return; }
    if (f == "matrixCompMult") { pass(0, mag(r(1))); pass(1, mag(r(0))); return; }
    if (f == "transpose") { pass(0, 1); return; }
    if (is_transcendental(f)) {  // componentwise: the largest slope over the arguments' hulls
      const int arity = static_cast<int>(e.args.size());
      const Interval x = Analysis::hull(r(0)), y = arity > 1 ? Analysis::hull(r(1)) : Interval::top();
      for (size_t i = 0; i < e.args.size(); ++i) pass(i, transcendental_slope(f, arity, i, x, y));
      return;
    }
    for (size_t i = 0; i < e.args.size(); ++i) pass(i, kInf);  // no derivative bound known
  }

  void binary(const Expr& e, const std::string& op, double w) {
    const Box l = arg_range(&e, 0), r = arg_range(&e, 1);
    const ir::Type &lt = e.args[0]->type, &rt = e.args[1]->type;
    if (op == "+" || op == "-") { expr(e.args[0], w); expr(e.args[1], w); return; }
    if (op == "*") {
      if (lt.is_matrix() && rt.vec > 1 && !rt.is_matrix()) {  // M v
        double rows = 0;
        for (int row = 0; row < lt.vec; ++row) {
          double s = 0;
          for (int c = 0; c < lt.cols; ++c) s += fit(l, static_cast<size_t>(lt.cols * lt.vec))[static_cast<size_t>(c * lt.vec + row)].mag();
          rows = std::max(rows, s);
        }
        double vs = 0;
        for (const Interval& c : fit(r, static_cast<size_t>(rt.vec))) vs += c.mag();
        expr(e.args[0], mul(w, vs));
        expr(e.args[1], mul(w, rows));
        return;
      }
      if (lt.is_matrix() || rt.is_matrix()) {  // v M, A B: bound by the contraction length
        const int k = lt.is_matrix() ? lt.cols : lt.vec;
        expr(e.args[0], mul(w, k * mag(r)));
        expr(e.args[1], mul(w, k * mag(l)));
        return;
      }
      expr(e.args[0], mul(w, mag(r)));
      expr(e.args[1], mul(w, mag(l)));
      return;
    }
    if (op == "/") {
      const double m = Analysis::hull(r).mig();
      expr(e.args[0], div(w, m));
      expr(e.args[1], div(mul(w, mag(l)), m * m));
      return;
    }
    expr(e.args[0], 0);  // comparisons, logic, bits: no error flows through as a value
    expr(e.args[1], 0);
  }

  void expr(const ir::ExprPtr& ep, double w) {
    const Expr& e = *ep;
    switch (e.kind) {
      case Expr::Kind::Sym:
        note(&e, w);
        W[e.var.get()] += w;
        return;
      case Expr::Kind::Const: note(&e, w); return;
      case Expr::Kind::Unary: {
        note(&e, w);
        if (e.op == "-") { expr(e.args[0], w); return; }
        if (e.op == "!" || e.op == "~") { expr(e.args[0], 0); return; }
        const double total = assigned_weight(e.args[0], w, false);  // x += 1: old value weight unchanged
        (void)total;
        return;
      }
      case Expr::Kind::Binary: {
        if (is_assign(e.op)) {
          if (e.op == "=") {
            const double total = assigned_weight(e.args[0], w, true);
            expr(e.args[1], total);
            return;
          }
          // v op= x is v = v op x: the node rounds, the old v and x carry the new value's weight.
          bool whole = false;
          const Var* v = lvalue_root(e.args[0], &whole);
          const double total = assigned_weight(e.args[0], w, true);
          note(&e, total);
          const std::string op = e.op.substr(0, e.op.size() - 1);
          const Box old = arg_range(&e, 0), x = arg_range(&e, 1);
          double wold = total, wx = total;
          if (op == "*") { wold = mul(total, mag(x)); wx = mul(total, mag(old)); }
          if (op == "/") { const double m = Analysis::hull(x).mig(); wold = div(total, m); wx = div(mul(total, mag(old)), m * m); }
          if (!is_arith(op)) wold = wx = 0;
          expr(e.args[1], wx);
          if (v) W[v] += wold;
          return;
        }
        note(&e, w);
        binary(e, e.op, w);
        return;
      }
      case Expr::Kind::Ternary:
        note(&e, w);
        expr(e.args[2], w);
        expr(e.args[1], w);
        expr(e.args[0], 0);
        return;
      case Expr::Kind::Call: note(&e, w); call(e, w); return;
      case Expr::Kind::Builtin: note(&e, w); builtin(e, w); return;
      case Expr::Kind::Construct:
      case Expr::Kind::Member:
        note(&e, w);
        for (auto it = e.args.rbegin(); it != e.args.rend(); ++it) expr(*it, w);
        return;
      case Expr::Kind::Index:
        note(&e, w);
        expr(e.args[1], 0);
        expr(e.args[0], w);
        return;
      case Expr::Kind::Comma:
        note(&e, w);
        for (size_t i = e.args.size(); i-- > 0;) expr(e.args[i], i + 1 == e.args.size() ? w : 0);
        return;
    }
  }

  static std::map<const Var*, double> max_env(const std::map<const Var*, double>& x, const std::map<const Var*, double>& y) {
    auto r = x;
    for (const auto& [v, w] : y) r[v] = std::max(r[v], w);
    return r;
  }

  void stmt(const ir::StmtPtr& s) {
    if (!s) return;
    switch (s->kind) {
      case Stmt::Kind::Expr: if (s->expr) expr(s->expr, 0); break;
      case Stmt::Kind::Decl:
        if (s->var) {
          const double w = W[s->var.get()];
          W[s->var.get()] = 0;
          if (s->expr) {
            store(s->var.get(), w);
            expr(s->expr, w);
          }
        }
        break;
      case Stmt::Kind::Block:
        for (auto it = s->body.rbegin(); it != s->body.rend(); ++it) stmt(*it);
        break;
      case Stmt::Kind::If: {
        auto after = W;
        if (!s->body.empty()) stmt(s->body[0]);
        auto then_w = W;
        W = after;
        if (s->body.size() > 1) stmt(s->body[1]);
        W = max_env(then_w, W);
        expr(s->expr, 0);
        break;
      }
      case Stmt::Kind::Loop: {
        ++loop_depth;
        auto head = W;
        for (int round = 0; round < 40; ++round) {
          W = head;
          if (s->step) expr(s->step, 0);
          if (s->body.size() > 1) stmt(s->body[1]);
          if (s->expr) expr(s->expr, 0);
          auto next = max_env(head, W);
          if (round >= 3)
            for (auto& [v, w] : next)
              if (w > head[v]) w = kInf;
          if (next == head) break;
          head = next;
        }
        W = head;
        --loop_depth;
        if (!s->body.empty()) stmt(s->body[0]);
        break;
      }
      case Stmt::Kind::Switch:
        if (!s->body.empty() && s->body[0]) {
          auto after = W;
          for (auto it = s->body[0]->body.rbegin(); it != s->body[0]->body.rend(); ++it) {
            stmt(*it);
            W = max_env(W, after);
          }
        }
        if (s->expr) expr(s->expr, 0);
        break;
      case Stmt::Kind::Return:
        if (!frames.empty()) W = max_env(W, frames.back().exit);
        if (s->expr) expr(s->expr, frames.empty() ? 0 : frames.back().ret);
        break;
      default: break;
    }
  }
};

void backward_pass(Analysis& a, const std::string& output, const ir::Function* main) {
  Backward bw{a, a.node_weight_[output], a.store_weight_[output], {}, 0, {}, 0};
  bw.W[a.outputs_.at(output)] = 1;
  bw.stmt(main->body);
  const ir::Module& module = *a.module_;
  for (size_t i = module.globals.size(); i-- > 0;)
    if (i < module.global_inits.size() && module.global_inits[i]) {
      const Var* g = module.globals[i].get();
      const double w = bw.W[g];
      bw.W[g] = 0;
      bw.store(g, w);
      bw.expr(module.global_inits[i], w);
    }
  for (const auto& [name, v] : a.inputs_) bw.store(v, bw.W[v]);  // inputs are stored once, by the host
}

}  // namespace doublet::plan
