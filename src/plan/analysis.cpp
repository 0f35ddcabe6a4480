#include "plan/analysis.hpp"

#include <cmath>
#include <functional>

#include "ir/walk.hpp"

namespace doublet::plan {

using ir::Expr;
using ir::Stmt;
using ir::Var;

// What the forward pass learns about one expression node, for the error model.
struct Analysis::Node {
  const ir::Function* fn = nullptr;
  Box range;                       // hull over every evaluation
  std::vector<Box> args;           // the operands' ranges (hull over evaluations)
  bool rte_operand = false;        // a split value read by an rte subtraction (exact there)
};

namespace {

int components(const ir::Type& t) {
  if (t.is_array() || t.base == ir::Base::Struct || t.base == ir::Base::Block) return 1;
  return t.is_matrix() ? t.cols * t.vec : t.vec;
}

Box top(const ir::Type& t) { return Box(static_cast<size_t>(components(t)), Interval::top()); }

Box join(const Box& a, const Box& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  if (a.size() != b.size()) {  // shapes differ (array element vs whole): hull both
    Interval h = join(Analysis::hull(a), Analysis::hull(b));
    return Box(std::max(a.size(), b.size()), h);
  }
  Box r(a.size());
  for (size_t i = 0; i < a.size(); ++i) r[i] = join(a[i], b[i]);
  return r;
}

Box fit(const Box& b, size_t n) {  // broadcast a scalar, or hull when shapes disagree
  if (b.size() == n) return b;
  if (b.size() == 1) return Box(n, b[0]);
  return Box(n, Analysis::hull(b));
}

Box map2(const Box& a, const Box& b, size_t n, const std::function<Interval(Interval, Interval)>& f) {
  Box x = fit(a, n), y = fit(b, n), r(n);
  for (size_t i = 0; i < n; ++i) r[i] = f(x[i], y[i]);
  return r;
}

double mag(const Box& b) { return Analysis::hull(b).mag(); }

bool is_arith(const std::string& op) { return op == "+" || op == "-" || op == "*" || op == "/"; }
bool is_assign(const std::string& op) {
  return op == "=" || op == "+=" || op == "-=" || op == "*=" || op == "/=" || op == "%=" || op == "<<=" ||
         op == ">>=" || op == "&=" || op == "|=" || op == "^=";
}

// The variable an lvalue writes, and whether it writes the whole of it.
const Var* lvalue_root(const ir::ExprPtr& e, bool* whole) {
  *whole = e->kind == Expr::Kind::Sym;
  ir::ExprPtr x = e;
  while (x && (x->kind == Expr::Kind::Member || x->kind == Expr::Kind::Index)) x = x->args[0];
  return x && x->kind == Expr::Kind::Sym ? x->var.get() : nullptr;
}

int swizzle_index(char c) {
  switch (c) {
    case 'x': case 'r': case 's': return 0;
    case 'y': case 'g': case 't': return 1;
    case 'z': case 'b': case 'p': return 2;
    case 'w': case 'a': case 'q': return 3;
  }
  return -1;
}

bool is_swizzle(const Expr& e) {
  if (e.kind != Expr::Kind::Member || e.args.empty()) return false;
  const ir::Type& t = e.args[0]->type;
  if (t.base == ir::Base::Struct || t.base == ir::Base::Block || t.is_matrix() || t.is_array()) return false;
  for (char c : e.name)
    if (swizzle_index(c) < 0) return false;
  return true;
}

bool is_input_storage(ir::Storage s) {
  return s == ir::Storage::In || s == ir::Storage::Uniform || s == ir::Storage::Buffer;
}

}  // namespace

Interval Analysis::hull(const Box& b) {
  if (b.empty()) return Interval::top();
  Interval h = b[0];
  for (const Interval& i : b) h = join(h, i);
  return h;
}

Box Analysis::range(const Var* v) const {
  auto it = var_range_.find(v);
  return it == var_range_.end() ? Box{Interval::top()} : it->second;
}
Box Analysis::range(const Expr* e) const {
  auto it = nodes_.find(e);
  return it == nodes_.end() ? Box{Interval::top()} : it->second->range;
}
const ir::Function* Analysis::owner(const Var* v) const {
  auto it = owner_.find(v);
  return it == owner_.end() ? nullptr : it->second;
}
const Var* Analysis::output_var(const std::string& name) const {
  auto it = outputs_.find(name);
  return it == outputs_.end() ? nullptr : it->second;
}

// ---- forward: ranges ---------------------------------------------------------------------------
struct Forward {
  Analysis& a;
  const Scene& scene;
  using Env = std::map<const Var*, Box>;
  Env env;
  std::map<std::pair<const Var*, const Var*>, double> relations;  // (a, b) -> |a - b| bound
  std::vector<const ir::Function*> fn_stack;
  std::vector<Box> returns;  // per active call: hull of returned values
  struct LoopExits { Env exits; bool any = false; };
  std::vector<LoopExits> loops;
  int depth = 0;

  const ir::Function* resolve(const Expr& call) const {
    const ir::Function* fallback = nullptr;
    for (const auto& f : a.module_->functions) {
      if (f->name != call.name || f->params.size() != call.args.size()) continue;
      bool same = true;
      for (size_t i = 0; i < call.args.size(); ++i) {
        const ir::Type &p = f->params[i]->declared_type, &q = call.args[i]->type;
        same &= p.base == q.base && p.vec == q.vec && p.cols == q.cols;
      }
      if (same) return f.get();
      if (!fallback) fallback = f.get();
    }
    return fallback;
  }

  Box read(const Var* v) {
    auto it = env.find(v);
    if (it != env.end()) return it->second;
    return top(v->type);
  }

  void write(const Var* v, const Box& value, bool whole) {
    Box stored = fit(value, static_cast<size_t>(components(v->type)));
    if (!whole) stored = join(read(v), Box(stored.size(), Analysis::hull(stored)));
    env[v] = stored;
    a.var_range_[v] = join(a.var_range_.count(v) ? a.var_range_[v] : Box{}, stored);
  }

  Analysis::Node& node(const Expr* e) {
    auto& p = a.nodes_[e];
    if (!p) p = std::make_shared<Analysis::Node>();
    if (!fn_stack.empty()) p->fn = fn_stack.back();
    return *p;
  }

  Box record(const Expr* e, Box value, const std::vector<Box>& args) {
    Analysis::Node& n = node(e);
    n.range = join(n.range, value);
    if (n.args.size() != args.size()) n.args = args;
    else
      for (size_t i = 0; i < args.size(); ++i) n.args[i] = join(n.args[i], args[i]);
    return value;
  }

  // Assignment of `value` through lvalue `lhs` (swizzles write their components only).
  void assign(const ir::ExprPtr& lhs, const Box& value) {
    bool whole = false;
    const Var* v = lvalue_root(lhs, &whole);
    if (!v) return;
    if (!whole && is_swizzle(*lhs) && lhs->args[0]->kind == Expr::Kind::Sym) {
      Box cur = fit(read(v), static_cast<size_t>(components(v->type)));
      Box val = fit(value, lhs->name.size());
      for (size_t i = 0; i < lhs->name.size(); ++i) {
        const int k = swizzle_index(lhs->name[i]);
        if (k >= 0 && static_cast<size_t>(k) < cur.size()) cur[static_cast<size_t>(k)] = val[i];
      }
      write(v, cur, true);
      return;
    }
    write(v, value, whole);
  }

  Box matmul(const Expr& e, const Box& l, const Box& r) {
    const ir::Type &lt = e.args[0]->type, &rt = e.args[1]->type;
    const size_t n = static_cast<size_t>(components(e.type));
    auto at = [](const Box& b, int i) { return b.size() == 1 ? b[0] : b[static_cast<size_t>(i)]; };
    Box out(n, Interval::point(0));
    if (lt.is_matrix() && !rt.is_matrix()) {  // M v: out[r] = sum_c M[c][r] v[c]
      for (int row = 0; row < lt.vec; ++row)
        for (int c = 0; c < lt.cols; ++c) out[static_cast<size_t>(row)] = out[static_cast<size_t>(row)] + at(l, c * lt.vec + row) * at(r, c);
    } else if (!lt.is_matrix() && rt.is_matrix()) {  // v M: out[c] = sum_r v[r] M[c][r]
      for (int c = 0; c < rt.cols; ++c)
        for (int row = 0; row < rt.vec; ++row) out[static_cast<size_t>(c)] = out[static_cast<size_t>(c)] + at(l, row) * at(r, c * rt.vec + row);
    } else {  // A B: out[c][r] = sum_k A[k][r] B[c][k]
      for (int c = 0; c < rt.cols; ++c)
        for (int row = 0; row < lt.vec; ++row)
          for (int k = 0; k < lt.cols; ++k)
            out[static_cast<size_t>(c * lt.vec + row)] =
                out[static_cast<size_t>(c * lt.vec + row)] + at(l, k * lt.vec + row) * at(r, c * rt.vec + k);
    }
    return out;
  }

  Box binary(const Expr& e, const std::string& op, const Box& l, const Box& r) {
    const size_t n = static_cast<size_t>(components(e.type));
    const bool mat = (e.args[0]->type.is_matrix() || e.args[1]->type.is_matrix()) && op == "*" &&
                     !(e.args[0]->type.vec == 1 && !e.args[0]->type.is_matrix()) &&
                     !(e.args[1]->type.vec == 1 && !e.args[1]->type.is_matrix());
    if (mat) return matmul(e, l, r);
    if (op == "+") return map2(l, r, n, [](Interval x, Interval y) { return x + y; });
    if (op == "-") {
      Box d = map2(l, r, n, [](Interval x, Interval y) { return x - y; });
      // A scene relation bounds a - b of two inputs read directly.
      if (e.args[0]->kind == Expr::Kind::Sym && e.args[1]->kind == Expr::Kind::Sym) {
        auto it = relations.find({e.args[0]->var.get(), e.args[1]->var.get()});
        if (it != relations.end())
          for (Interval& c : d) c = meet(c, {-it->second, it->second});
      }
      return d;
    }
    if (op == "*") return map2(l, r, n, [](Interval x, Interval y) { return x * y; });
    if (op == "/") return map2(l, r, n, [](Interval x, Interval y) { return x / y; });
    if (op == "%") return map2(l, r, n, [](Interval, Interval y) { double m = y.mag(); return Interval{-m, m}; });
    if (op == "==" || op == "!=" || op == "<" || op == ">" || op == "<=" || op == ">=" || op == "&&" ||
        op == "||" || op == "^^")
      return Box(n, Interval{0, 1});
    return top(e.type);  // bitwise, shifts
  }

  Box builtin(const Expr& e, const std::vector<Box>& args) {
    const std::string& f = e.name;
    const size_t n = static_cast<size_t>(components(e.type));
    auto arg = [&](size_t i) { return fit(args[i], n); };
    auto each = [&](const std::function<Interval(Interval)>& g) {
      Box x = arg(0), r(n);
      for (size_t i = 0; i < n; ++i) r[i] = g(x[i]);
      return r;
    };
    auto dot = [&](const Box& x, const Box& y) {
      Interval s = Interval::point(0);
      const size_t m = std::max(x.size(), y.size());
      Box p = fit(x, m), q = fit(y, m);
      for (size_t i = 0; i < m; ++i) s = s + p[i] * q[i];
      return s;
    };
    auto self_dot = [&](const Box& x) {
      Interval s = Interval::point(0);
      for (const Interval& c : x) s = s + square(c);
      return s;
    };
    if (f == "sqrt") return each([](Interval x) { return sqrt(x); });
    if (f == "inversesqrt") return each([](Interval x) { return reciprocal(sqrt(x)); });
    if (f == "abs") return each([](Interval x) { return abs(x); });
    if (f == "sign") return Box(n, Interval{-1, 1});
    if (f == "floor" || f == "ceil" || f == "trunc" || f == "round" || f == "roundEven")
      return each([](Interval x) { return Interval{std::floor(x.lo), std::ceil(x.hi)}; });
    if (f == "fract" || f == "step" || f == "smoothstep") return Box(n, Interval{0, 1});
    if (f == "sin" || f == "cos") return Box(n, Interval{-1, 1});
    if (f == "normalize") return Box(n, Interval{-1, 1});
    if (f == "min" || f == "max") {
      Box x = arg(0), y = arg(1), r(n);
      for (size_t i = 0; i < n; ++i)
        r[i] = f == "min" ? Interval{std::min(x[i].lo, y[i].lo), std::min(x[i].hi, y[i].hi)}
                          : Interval{std::max(x[i].lo, y[i].lo), std::max(x[i].hi, y[i].hi)};
      return r;
    }
    if (f == "clamp") {
      Box x = arg(0), lo = arg(1), hi = arg(2), r(n);
      for (size_t i = 0; i < n; ++i)
        r[i] = {std::min(std::max(x[i].lo, lo[i].lo), hi[i].hi), std::max(std::min(x[i].hi, hi[i].hi), lo[i].lo)};
      return r;
    }
    if (f == "mix" && args.size() == 3 && e.args[2]->type.base != ir::Base::Bool) {
      Box x = arg(0), y = arg(1), t = arg(2), r(n);
      for (size_t i = 0; i < n; ++i) r[i] = x[i] + t[i] * (y[i] - x[i]);
      return r;
    }
    if (f == "mix") return join(arg(0), arg(1));
    if (f == "fma") {
      Box x = arg(0), y = arg(1), z = arg(2), r(n);
      for (size_t i = 0; i < n; ++i) r[i] = x[i] * y[i] + z[i];
      return r;
    }
    if (f == "dot") return Box(1, dot(args[0], args[1]));
    if (f == "length") return Box(1, sqrt(self_dot(args[0])));
    if (f == "distance") {
      const size_t m = std::max(args[0].size(), args[1].size());
      Box d = map2(args[0], args[1], m, [](Interval x, Interval y) { return x - y; });
      return Box(1, sqrt(self_dot(d)));
    }
    if (f == "cross") {
      Box x = fit(args[0], 3), y = fit(args[1], 3);
      return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    }
    if (f == "matrixCompMult") return map2(args[0], args[1], n, [](Interval x, Interval y) { return x * y; });
    if (f == "transpose") {
      const ir::Type& t = e.args[0]->type;
      Box x = fit(args[0], static_cast<size_t>(components(t))), r(n);
      for (int c = 0; c < t.cols; ++c)
        for (int row = 0; row < t.vec; ++row) r[static_cast<size_t>(row * t.cols + c)] = x[static_cast<size_t>(c * t.vec + row)];
      return r;
    }
    if (f == "exp") return each([](Interval x) { return Interval{std::exp(x.lo), std::exp(x.hi)}; });
    return top(e.type);
  }

  Box construct(const Expr& e, const std::vector<Box>& args) {
    const size_t n = static_cast<size_t>(components(e.type));
    if (e.type.is_array() || e.type.base == ir::Base::Struct) {
      Box all;
      for (const Box& b : args) all.push_back(Analysis::hull(b));
      return Box(1, Analysis::hull(all));
    }
    if (args.size() == 1 && args[0].size() == 1 && n > 1) {
      if (!e.type.is_matrix()) return Box(n, args[0][0]);
      Box r(n, Interval::point(0));  // matN(s): s on the diagonal
      for (int c = 0; c < e.type.cols; ++c)
        if (c < e.type.vec) r[static_cast<size_t>(c * e.type.vec + c)] = args[0][0];
      return r;
    }
    if (args.size() == 1 && e.type.is_matrix() && e.args[0]->type.is_matrix()) {
      const ir::Type& from = e.args[0]->type;
      Box r(n, Interval::point(0));
      for (int c = 0; c < e.type.cols; ++c)
        for (int row = 0; row < e.type.vec; ++row) {
          if (c < from.cols && row < from.vec) r[static_cast<size_t>(c * e.type.vec + row)] = args[0][static_cast<size_t>(c * from.vec + row)];
          else if (c == row) r[static_cast<size_t>(c * e.type.vec + row)] = Interval::point(1);
        }
      return r;
    }
    Box flat;
    for (const Box& b : args) flat.insert(flat.end(), b.begin(), b.end());
    flat.resize(std::max<size_t>(n, 1), flat.empty() ? Interval::top() : flat.back());
    flat.resize(n);
    return flat;
  }

  Box call(const Expr& e, const std::vector<Box>& args) {
    const ir::Function* f = resolve(e);
    if (!f || !f->body || depth > 32) return top(e.type);
    ++depth;
    for (size_t i = 0; i < f->params.size(); ++i) {
      const Var* p = f->params[i].get();
      if (p->storage == ir::Storage::ParamOut) write(p, top(p->type), true);
      else write(p, args[i], true);
    }
    fn_stack.push_back(f);
    returns.emplace_back();
    stmt(f->body);
    Box ret = returns.back();
    returns.pop_back();
    fn_stack.pop_back();
    for (size_t i = 0; i < f->params.size(); ++i) {
      const Var* p = f->params[i].get();
      if (p->storage == ir::Storage::ParamOut || p->storage == ir::Storage::ParamInOut) assign(e.args[i], read(p));
    }
    --depth;
    return ret.empty() ? top(e.type) : ret;
  }

  Box expr(const ir::ExprPtr& ep) {
    const Expr& e = *ep;
    std::vector<Box> args;
    auto eval_args = [&](size_t from) {
      for (size_t i = from; i < e.args.size(); ++i) args.push_back(expr(e.args[i]));
    };
    switch (e.kind) {
      case Expr::Kind::Sym: {
        Box v = read(e.var.get());
        return record(&e, v, {});
      }
      case Expr::Kind::Const: {
        Box v;
        for (const ir::Scalar& s : e.values)
          v.push_back(Interval::point(s.base == ir::Base::Bool ? (s.b ? 1 : 0)
                                      : s.base == ir::Base::Int || s.base == ir::Base::Uint ? static_cast<double>(s.i) : s.d));
        if (v.empty()) v = top(e.type);
        if (e.type.is_array() || e.type.base == ir::Base::Struct) v = Box(1, Analysis::hull(v));
        return record(&e, fit(v, static_cast<size_t>(components(e.type))), {});
      }
      case Expr::Kind::Unary: {
        eval_args(0);
        const std::string& op = e.op;
        if (op == "-") {
          Box r;
          for (const Interval& c : args[0]) r.push_back(-c);
          return record(&e, r, args);
        }
        if (op == "!" ) return record(&e, Box(1, Interval{0, 1}), args);
        if (op == "~") return record(&e, top(e.type), args);
        const Interval one = Interval::point(op[0] == '+' || op[1] == '+' ? 1 : -1);
        Box next;
        for (const Interval& c : args[0]) next.push_back(c + one);
        assign(e.args[0], next);
        return record(&e, op.size() == 3 && op[0] != 'x' ? next : args[0], args);  // ++x: new; x++: old
      }
      case Expr::Kind::Binary: {
        if (is_assign(e.op)) {
          Box rhs = expr(e.args[1]);
          Box value = rhs;
          std::vector<Box> rec{Box{}, rhs};
          if (e.op != "=") {
            Box old = expr(e.args[0]);
            rec[0] = old;
            value = binary(e, e.op.substr(0, e.op.size() - 1), old, rhs);
          }
          assign(e.args[0], value);
          return record(&e, value, rec);
        }
        eval_args(0);
        return record(&e, binary(e, e.op, args[0], args[1]), args);
      }
      case Expr::Kind::Ternary: {
        eval_args(0);
        return record(&e, join(args[1], args[2]), args);
      }
      case Expr::Kind::Call: {
        eval_args(0);
        return record(&e, call(e, args), args);
      }
      case Expr::Kind::Builtin: {
        eval_args(0);
        if (args.empty()) return record(&e, top(e.type), args);
        return record(&e, builtin(e, args), args);
      }
      case Expr::Kind::Construct: {
        eval_args(0);
        return record(&e, construct(e, args), args);
      }
      case Expr::Kind::Member: {
        eval_args(0);
        if (!is_swizzle(e)) return record(&e, top(e.type), args);
        Box r;
        for (char c : e.name) {
          const int k = swizzle_index(c);
          r.push_back(static_cast<size_t>(k) < args[0].size() ? args[0][static_cast<size_t>(k)] : Analysis::hull(args[0]));
        }
        return record(&e, r, args);
      }
      case Expr::Kind::Index: {
        eval_args(0);
        const ir::Type& t = e.args[0]->type;
        const size_t n = static_cast<size_t>(components(e.type));
        if (t.is_matrix() && !t.is_array() && args[0].size() == static_cast<size_t>(t.cols * t.vec)) {
          Box col(n, Interval{kInf, -kInf});
          for (int c = 0; c < t.cols; ++c)
            if (Analysis::hull(args[1]).lo <= c && c <= Analysis::hull(args[1]).hi)
              for (size_t row = 0; row < n; ++row) col[row] = join(col[row], args[0][static_cast<size_t>(c) * n + row]);
          for (Interval& i : col)
            if (i.lo > i.hi) i = Interval::top();
          return record(&e, col, args);
        }
        return record(&e, Box(n, Analysis::hull(args[0])), args);
      }
      case Expr::Kind::Comma: {
        eval_args(0);
        return record(&e, args.empty() ? top(e.type) : args.back(), args);
      }
    }
    return top(e.type);
  }

  static bool same(const Env& x, const Env& y) { return x == y; }
  static Env join_env(const Env& x, const Env& y) {
    Env r = x;
    for (const auto& [v, b] : y) r[v] = r.count(v) ? join(r[v], b) : b;
    return r;
  }
  // Bounds that still move after a few rounds go to ±inf: loops terminate, and a value a loop
  // keeps growing is unbounded (it then needs df64, docs/plan.md).
  static Env widen(const Env& old, const Env& now) {
    Env r = now;
    for (auto& [v, b] : r) {
      auto it = old.find(v);
      if (it == old.end() || it->second.size() != b.size()) continue;
      for (size_t i = 0; i < b.size(); ++i) {
        if (b[i].lo < it->second[i].lo) b[i].lo = -kInf;
        if (b[i].hi > it->second[i].hi) b[i].hi = kInf;
      }
    }
    return r;
  }

  void stmt(const ir::StmtPtr& s) {
    if (!s) return;
    switch (s->kind) {
      case Stmt::Kind::Expr: if (s->expr) expr(s->expr); break;
      case Stmt::Kind::Decl:
        if (s->var) {
          if (!a.owner_.count(s->var.get()) && !fn_stack.empty()) a.owner_[s->var.get()] = fn_stack.back();
          write(s->var.get(), s->expr ? expr(s->expr) : Box(static_cast<size_t>(components(s->var->type)), Interval::point(0)), true);
        }
        break;
      case Stmt::Kind::Block: for (const auto& b : s->body) stmt(b); break;
      case Stmt::Kind::If: {
        expr(s->expr);
        Env before = env;
        if (!s->body.empty()) stmt(s->body[0]);
        Env after_then = env;
        env = before;
        if (s->body.size() > 1) stmt(s->body[1]);
        env = join_env(after_then, env);
        break;
      }
      case Stmt::Kind::Loop: {
        if (!s->body.empty()) stmt(s->body[0]);
        loops.emplace_back();
        Env head = env;
        for (int round = 0; round < 40; ++round) {
          env = head;
          if (s->expr) expr(s->expr);
          if (s->body.size() > 1) stmt(s->body[1]);
          if (s->step) expr(s->step);
          Env next = join_env(head, env);
          if (round >= 3) next = widen(head, next);
          if (same(next, head)) break;
          head = next;
        }
        env = head;
        if (loops.back().any) env = join_env(env, loops.back().exits);
        loops.pop_back();
        break;
      }
      case Stmt::Kind::Switch: {
        if (s->expr) expr(s->expr);
        Env entry = env;
        if (!s->body.empty() && s->body[0])
          for (const auto& b : s->body[0]->body) {
            if (b->kind == Stmt::Kind::Case || b->kind == Stmt::Kind::Default) env = join_env(env, entry);
            stmt(b);
          }
        env = join_env(env, entry);
        break;
      }
      case Stmt::Kind::Break:
      case Stmt::Kind::Continue:
        if (!loops.empty()) {
          loops.back().exits = loops.back().any ? join_env(loops.back().exits, env) : env;
          loops.back().any = true;
        }
        break;
      case Stmt::Kind::Return:
        if (s->expr) {
          Box v = expr(s->expr);
          if (!returns.empty()) returns.back() = join(returns.back(), v);
        }
        break;
      default: break;
    }
  }
};

// ---- backward: sensitivities -------------------------------------------------------------------
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
    const ir::Function* f = nullptr;
    {
      Forward finder{a, *a.scene_, {}, {}, {}, {}, {}, 0};
      f = finder.resolve(e);
    }
    if (!f || !f->body || depth > 32) {
      for (const auto& x : e.args) expr(x, w == 0 ? 0 : kInf);
      return;
    }
    ++depth;
    // Out parameters receive the callee's final value: their weight flows into the parameter.
    for (size_t i = 0; i < f->params.size(); ++i) {
      const Var* p = f->params[i].get();
      if (p->storage == ir::Storage::ParamOut || p->storage == ir::Storage::ParamInOut)
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

// ---- driver ------------------------------------------------------------------------------------
bool Analysis::run(const ir::Module& module, const Scene& scene, std::vector<Diagnostic>* diagnostics) {
  module_ = &module;
  scene_ = &scene;
  const ir::Function* main = nullptr;
  for (const auto& f : module.functions)
    if (f->name == "main") main = f.get();
  if (!main) {
    diagnostics->push_back({scene.file, 0, 0, Severity::Error, "the shader has no main()"});
    return false;
  }
  // Every variable the IR mentions, found once: globals, block members, locals, parameters.
  std::set<const Var*> seen;
  auto visit_var = [&](const Var* v, const ir::Function* f) {
    if (!v || !seen.insert(v).second) return;
    if (f) owner_[v] = f;
    if (v->declared_type.contains_double()) double_vars_.push_back(v);
    if (is_input_storage(v->storage) || (v->storage == ir::Storage::Global && false)) inputs_.emplace(v->name, v);
    if (v->storage == ir::Storage::Out || v->storage == ir::Storage::BuiltIn ||
        (v->storage == ir::Storage::Buffer && !v->readonly))
      outputs_.emplace(v->name, v);
  };
  for (const auto& g : module.globals) visit_var(g.get(), nullptr);
  for (const auto& f : module.functions) {
    for (const auto& p : f->params) visit_var(p.get(), f.get());
    if (!f->body) continue;
    std::function<void(const ir::StmtPtr&)> walk = [&](const ir::StmtPtr& s) {
      if (!s) return;
      if (s->kind == Stmt::Kind::Decl && s->var) {
        visit_var(s->var.get(), f.get());
        if (s->expr) defs_[s->var.get()].push_back(s->expr);
      }
      for (const auto& b : s->body) walk(b);
    };
    walk(f->body);
    ir::visit(f->body, [&](const ir::ExprPtr& e) {
      if (e->kind == Expr::Kind::Sym) visit_var(e->var.get(), e->var->storage == ir::Storage::Local ? f.get() : nullptr);
      if (e->kind == Expr::Kind::Binary && is_assign(e->op)) {
        bool whole = false;
        if (const Var* v = lvalue_root(e->args[0], &whole)) defs_[v].push_back(e->args[1]);
      }
    });
  }

  bool ok = true;
  Forward fw{*this, scene, {}, {}, {}, {}, {}, 0};
  for (const auto& [name, range] : scene.inputs) {
    auto it = inputs_.find(name);
    if (it == inputs_.end()) {
      diagnostics->push_back(scene_diagnostic(scene, range.path, "the shader has no input (in, uniform or buffer) named '" + name + "'"));
      ok = false;
      continue;
    }
    const size_t n = static_cast<size_t>(components(it->second->type));
    if (range.components.size() != 1 && range.components.size() != n) {
      diagnostics->push_back(scene_diagnostic(scene, range.path, "'" + name + "' has " + std::to_string(n) +
                                                                     " components; give one range or " + std::to_string(n)));
      ok = false;
      continue;
    }
    Box b;
    for (size_t i = 0; i < n; ++i) b.push_back(range.component(i));
    fw.env[it->second] = b;
    var_range_[it->second] = b;
  }
  for (const auto& [name, req] : scene.outputs)
    if (!outputs_.count(name)) {
      diagnostics->push_back(scene_diagnostic(scene, req.path, "the shader has no output (out, gl_Position or buffer) named '" + name + "'"));
      ok = false;
    }
  if (!ok) return false;
  for (const Relation& r : scene.relations) {
    const Var *x = inputs_.at(r.a), *y = inputs_.at(r.b);
    fw.relations[{x, y}] = r.abs_max;
    fw.relations[{y, x}] = r.abs_max;
  }
  for (const auto& [name, v] : inputs_)
    if (!scene.inputs.count(name) && v->declared_type.contains_double())
      notes_.push_back("input '" + name + "' has no range in the scene: unbounded");

  // Forward: global initialisers, then main (callees analysed at each call).
  for (size_t i = 0; i < module.globals.size(); ++i)
    if (i < module.global_inits.size() && module.global_inits[i])
      fw.write(module.globals[i].get(), fw.expr(module.global_inits[i]), true);
  fw.fn_stack.push_back(main);
  fw.stmt(main->body);
  for (const auto& [name, v] : outputs_)
    if (!var_range_.count(v)) var_range_[v] = top(v->type);

  // Backward, once per scene output: the output's value at the end of main has weight 1.
  for (const auto& [name, req] : scene.outputs) {
    Backward bw{*this, node_weight_[name], store_weight_[name], {}, 0, {}, 0};
    bw.W[outputs_.at(name)] = 1;
    bw.stmt(main->body);
    for (size_t i = module.globals.size(); i-- > 0;)
      if (i < module.global_inits.size() && module.global_inits[i]) {
        const Var* g = module.globals[i].get();
        const double w = bw.W[g];
        bw.W[g] = 0;
        bw.store(g, w);
        bw.expr(module.global_inits[i], w);
      }
    for (const auto& [in_name, v] : inputs_) bw.store(v, bw.W[v]);  // inputs are stored once, by the host
    (void)req;
  }
  // rte: the operands of a subtraction of two split values are exact there.
  for (auto& [e, n] : nodes_)
    if (e->kind == Expr::Kind::Binary && e->op == "-" && e->type.is_double())
      for (const auto& x : e->args)
        if (x->kind == Expr::Kind::Sym && nodes_.count(x.get())) nodes_[x.get()]->rte_operand = true;
  return true;
}

// ---- error model -------------------------------------------------------------------------------
double Analysis::storage_error(const Var* v, const Candidate& c) const {
  if (!v->declared_type.contains_double()) return 0;
  const double m = hull(range(v)).mag();
  const ir::Function* f = owner(v);
  const bool fp32 = c.fp32_vars.count(v) || (f && (c.mode_of(f) == Mode::Fp32 || c.mode_of(f) == Mode::Rte));
  if (fp32) return float_half_ulp(m);
  if (is_input_storage(v->storage)) return m == 0 ? 0 : m * kDf64Repr;
  return 0;
}

double Analysis::rounding(const Expr* e, const Node& n, const Candidate& c) const {
  const double m = hull(n.range).mag();
  if (m == 0) return 0;
  // An explicit conversion of a double to float rounds whatever the mode. The native shader
  // rounds the same value too: near a rounding boundary the two land one ulp apart.
  if (e->kind == Expr::Kind::Construct && !e->type.contains_double() && !e->args.empty() &&
      e->args[0]->type.is_double() && e->type.base == ir::Base::Float)
    return 2 * float_half_ulp(m);
  if (!e->type.is_double()) return 0;
  const Mode mode = c.mode_of(n.fn);
  const bool single = mode == Mode::Fp32 || mode == Mode::Rte;
  const double half = float_half_ulp(m);
  const double df = (mode == Mode::Df64Fast ? kDf64FastRel : kDf64Rel) * m;
  auto by_mode = [&](double fp32_ulps) { return single ? fp32_ulps * half : df; };
  switch (e->kind) {
    case Expr::Kind::Sym: {
      if (!single) return 0;
      if (mode == Mode::Rte && n.rte_operand) return 0;
      // A double read by float arithmetic rounds unless it is already stored as float.
      const Var* v = e->var.get();
      const ir::Function* f = owner(v);
      if (c.fp32_vars.count(v) || (f && (c.mode_of(f) == Mode::Fp32 || c.mode_of(f) == Mode::Rte))) return 0;
      return half;
    }
    case Expr::Kind::Const: {
      double worst = 0;
      for (const ir::Scalar& s : e->values) worst = std::max(worst, std::fabs(s.d - static_cast<double>(static_cast<float>(s.d))));
      return single ? worst : m * kDf64Repr;
    }
    case Expr::Kind::Unary: return e->op == "-" ? 0 : by_mode(1);
    case Expr::Kind::Binary: {
      std::string op = e->op;
      if (is_assign(op) && op != "=") op = op.substr(0, op.size() - 1);
      if (op == "-" && mode == Mode::Rte && e->args[0]->kind == Expr::Kind::Sym && e->args[1]->kind == Expr::Kind::Sym)
        return half;  // exact float-float difference, rounded once to float
      if (op == "+" || op == "-") return by_mode(1);
      if (op == "*") {
        const ir::Type &lt = e->args[0]->type, &rt = e->args[1]->type;
        if (lt.is_matrix() || rt.is_matrix()) {  // k products summed: k roundings of the largest term
          const int k = lt.is_matrix() ? lt.cols : lt.vec;
          const double terms = n.args.size() == 2 ? k * hull(n.args[0]).mag() * hull(n.args[1]).mag() : kInf;
          return (single ? k * 0x1p-24 : k * kDf64Rel) * terms;
        }
        return by_mode(1);
      }
      if (op == "/") return by_mode(5);  // GLSL ES: 2.5 ulp
      return 0;
    }
    case Expr::Kind::Builtin: {
      const std::string& f = e->name;
      if (f == "abs" || f == "min" || f == "max" || f == "clamp" || f == "sign" || f == "floor" || f == "ceil" ||
          f == "trunc" || f == "round" || f == "roundEven" || f == "transpose")
        return 0;
      if (f == "sqrt") return by_mode(6);  // GLSL ES: sqrt as 1/inversesqrt, 3 ulp
      if (f == "fract" || f == "mod") return by_mode(2);
      if (f == "dot" || f == "length" || f == "distance") {
        // Higham: a sum of k products has error <= k u sum|a_i b_i|.
        const Box a0 = n.args.empty() ? Box{} : n.args[0];
        const Box a1 = f == "dot" && n.args.size() > 1 ? n.args[1] : a0;
        double s = 0;
        const size_t k = std::max(a0.size(), a1.size());
        for (size_t i = 0; i < k; ++i) s += fit(a0, k)[i].mag() * fit(a1, k)[i].mag();
        if (f == "distance") s *= 4;  // (a - b)^2 <= 2a^2 + 2b^2, and the subtraction rounds
        const double err = (single ? static_cast<double>(k) * 0x1p-24 : static_cast<double>(k) * kDf64Rel) * s;
        if (f == "dot") return err;
        const double len_min = hull(n.range).mig();
        const double through_sqrt = len_min > 0 ? err / (2 * len_min) : std::sqrt(err);
        return std::min(through_sqrt, std::sqrt(err)) + by_mode(6);
      }
      if (f == "normalize") return (single ? 0x1p-24 : kDf64Rel) * (2.0 * static_cast<double>(n.args.empty() ? 4 : n.args[0].size()) + 8);
      if (f == "mix" || f == "fma" || f == "cross" || f == "matrixCompMult") {
        double s = 0;
        for (const Box& b : n.args) s = std::max(s, hull(b).mag());
        return (single ? 0x1p-24 : kDf64Rel) * 6 * std::max(s * s, m);
      }
      return kInf;  // no bound known for this built-in (docs/plan.md, limits)
    }
    default: return 0;  // constructors, swizzles, indexing, calls (their bodies count)
  }
}

double Analysis::error_estimate(const std::string& output, const Candidate& c) const {
  auto nw = node_weight_.find(output);
  auto sw = store_weight_.find(output);
  if (nw == node_weight_.end()) return kInf;
  double total = 0;
  auto term = [](double w, double r) { return w == 0 || r == 0 ? 0 : w * r; };
  for (const auto& [e, w] : nw->second) {
    auto it = nodes_.find(e);
    if (it != nodes_.end()) total += term(w, rounding(e, *it->second, c));
  }
  for (const auto& [v, w] : sw->second) total += term(w, storage_error(v, c));
  // The output itself: float outputs round the value they are given (counted at their
  // conversion); double outputs leave as hi + lo.
  return total;
}

double Analysis::sensitivity(const std::string& output, const Var* v) const {
  auto sw = store_weight_.find(output);
  if (sw == store_weight_.end()) return 0;
  auto it = sw->second.find(v);
  return it == sw->second.end() ? 0 : it->second;
}

double Analysis::budget(const std::string& output, const Var* v) const {
  const double s = sensitivity(output, v);
  auto req = scene_->outputs.find(output);
  if (s == 0 || req == scene_->outputs.end()) return kInf;
  return req->second.abs_error / s;
}

bool Analysis::may_cancel(const ir::Function* f) const {
  for (const auto& [e, n] : nodes_) {
    if (n->fn != f || !e->type.is_double() || e->kind != Expr::Kind::Binary || n->args.size() != 2) continue;
    std::string op = e->op;
    if (is_assign(op) && op != "=") op = op.substr(0, op.size() - 1);
    if (op != "+" && op != "-") continue;
    const Interval x = hull(n->args[0]), y = hull(n->args[1]);
    const bool x_pos = x.lo >= 0, x_neg = x.hi <= 0, y_pos = y.lo >= 0, y_neg = y.hi <= 0;
    const bool same_sign = (x_pos && y_pos) || (x_neg && y_neg);
    const bool opposite = (x_pos && y_neg) || (x_neg && y_pos);
    if (op == "+" ? !same_sign : !opposite) return true;
  }
  return false;
}

namespace {

// Flops of one node (docs/rules.md): float ops count 1 per component and operation.
double node_flops(const Expr* e, const Analysis::Node& n, Mode mode) {
  if (!e->type.is_double() && !(e->kind == Expr::Kind::Construct && !e->args.empty() && e->args[0]->type.is_double()))
    return 0;
  const double k = std::max(1, components(e->type));
  const bool single = mode == Mode::Fp32 || mode == Mode::Rte;
  const int w = n.args.empty() ? 1 : static_cast<int>(n.args[0].size());
  switch (e->kind) {
    case Expr::Kind::Construct: return e->type.is_double() ? 0 : k;  // df_to_float: 1
    case Expr::Kind::Unary: return e->op == "-" ? (single ? k : 2 * k) : (single ? k : 20 * k);
    case Expr::Kind::Binary: {
      std::string op = e->op;
      if (is_assign(op) && op != "=") op = op.substr(0, op.size() - 1);
      if (op == "-" && mode == Mode::Rte && e->args[0]->kind == Expr::Kind::Sym && e->args[1]->kind == Expr::Kind::Sym)
        return 23 * k;  // df_sub then df_to_float
      const ir::Type &lt = e->args[0]->type, &rt = e->args[1]->type;
      if (op == "*" && (lt.is_matrix() || rt.is_matrix())) {
        const double c = lt.is_matrix() ? lt.cols : lt.vec;  // products per result component
        return single ? k * (2 * c - 1) : k * (24 * c + 20 * (c - 1));
      }
      if (op == "+") return k * (single ? 1 : mode == Mode::Df64Fast ? 11 : 20);
      if (op == "-") return k * (single ? 1 : mode == Mode::Df64Fast ? 11 : 22);
      if (op == "*") return k * (single ? 1 : 24);
      if (op == "/") return k * (single ? 1 : 33);
      return 0;
    }
    case Expr::Kind::Builtin: {
      const std::string& f = e->name;
      static const double dot_df[] = {0, 24, 68, 112, 156};
      const int i = std::clamp(w, 1, 4);
      if (f == "sqrt") return k * (single ? 1 : 27);
      if (f == "abs") return k * (single ? 1 : 3);
      if (f == "dot") return single ? 2 * w - 1 : dot_df[i];
      if (f == "length") return single ? 2 * w : (w == 1 ? 3 : 183);
      if (f == "distance") return single ? 3 * w : 183 + 22 * w;
      if (f == "normalize") return single ? 3 * w + 1 : 183 + 33 * w;
      if (f == "cross") return single ? 9 : 210;
      if (f == "mix") return k * (single ? 3 : 66);
      return k * (single ? 1 : 20);
    }
    default: return 0;
  }
}

}  // namespace

double Analysis::flops(const Candidate& c, const ir::Function* only) const {
  double total = 0;
  for (const auto& [e, n] : nodes_)
    if (!only || n->fn == only) total += node_flops(e, *n, c.mode_of(n->fn));
  return total;
}

double Analysis::flops_of(const Var* v, const Candidate& c) const {
  auto it = defs_.find(v);
  if (it == defs_.end()) return 0;
  double total = 0;
  for (const ir::ExprPtr& root : it->second) {
    ir::visit(root, [&](const ir::ExprPtr& e) {
                auto n = nodes_.find(e.get());
                if (n != nodes_.end()) total += node_flops(e.get(), *n->second, c.mode_of(n->second->fn));
              });
  }
  return total;
}

}  // namespace doublet::plan
