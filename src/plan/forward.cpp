// Forward pass of the analysis: interval ranges (analysis.hpp, docs/plan.md).
#include <cmath>

#include "plan/analysis_internal.hpp"
#include "plan/transcendentals.hpp"

namespace doublet::plan {
using namespace detail;

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

  const ir::Function* resolve(const Expr& call) const { return resolve_call(*a.module_, call); }

  // The variable `x` reads directly: a symbol, or an element of an array symbol.
  static const Var* direct_input(const ir::ExprPtr& x) {
    if (x->kind == Expr::Kind::Sym) return x->var.get();
    if (x->kind == Expr::Kind::Index && x->args[0]->kind == Expr::Kind::Sym && x->args[0]->type.is_array())
      return x->args[0]->var.get();
    return nullptr;
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
      // A scene relation bounds a - b of two inputs read directly (or an element of an input array).
      if (const Var *x = direct_input(e.args[0]), *y = direct_input(e.args[1]); x && y) {
        auto it = relations.find({x, y});
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
    if (is_transcendental(f)) {
      const int arity = static_cast<int>(args.size());
      Box x = arg(0), y = arity > 1 ? arg(1) : Box(n, Interval::top()), r(n);
      for (size_t i = 0; i < n; ++i) r[i] = transcendental_range(f, arity, x[i], y[i]);
      return r;
    }
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
      if (ir::is_out_parameter(p->storage)) assign(e.args[i], read(p));
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
        // A struct's member: the struct's one hull holds every member's values.
        if (!is_swizzle(e) && e.args[0]->type.base == ir::Base::Struct && !e.args[0]->type.is_array() && !args[0].empty())
          return record(&e, Box(static_cast<size_t>(components(e.type)), Analysis::hull(args[0])), args);
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
        // A vector's component (glslang spells `.x` as an index): the components the index may name.
        if (!t.is_array() && !t.is_matrix() && n == 1 && args[0].size() == static_cast<size_t>(components(t)) &&
            args.size() > 1) {
          Interval c{kInf, -kInf};
          const Interval at = Analysis::hull(args[1]);
          for (size_t k = 0; k < args[0].size(); ++k)
            if (at.lo <= static_cast<double>(k) && static_cast<double>(k) <= at.hi) c = join(c, args[0][k]);
          return record(&e, Box(1, c.lo > c.hi ? Analysis::hull(args[0]) : c), args);
        }
        // An input array whose scene range is per element component: every element has that box.
        if (t.is_array() && args[0].size() == n && n > 1) return record(&e, args[0], args);
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

const ir::Function* resolve_call(const ir::Module& m, const Expr& call) {
  auto same_shape = [](const ir::Var& param, const Expr& arg) {
    const ir::Type &p = param.declared_type, &q = arg.type;
    return p.base == q.base && p.vec == q.vec && p.cols == q.cols;
  };
  auto found = ir::overloads(m, call, same_shape);
  if (found.empty()) found = ir::overloads(m, call, [](const ir::Var&, const Expr&) { return true; });
  return found.empty() ? nullptr : found.front();
}

void forward_pass(Analysis& a, const ir::Function* main, std::map<const Var*, Box> env, Relations relations) {
  Forward fw{a, *a.scene_, std::move(env), std::move(relations), {}, {}, {}, 0};
  const ir::Module& module = *a.module_;
  for (size_t i = 0; i < module.globals.size(); ++i)
    if (i < module.global_inits.size() && module.global_inits[i])
      fw.write(module.globals[i].get(), fw.expr(module.global_inits[i]), true);
  fw.fn_stack.push_back(main);
  fw.stmt(main->body);
}

}  // namespace doublet::plan
