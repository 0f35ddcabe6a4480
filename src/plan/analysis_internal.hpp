// Internals shared by the analysis' files (analysis.cpp: driver and error model; forward.cpp:
// ranges; backward.cpp: sensitivities). Not part of the plan library's interface.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>

#include "plan/analysis.hpp"

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

namespace detail {

inline int components(const ir::Type& t) {
  if (t.is_array() || t.base == ir::Base::Struct || t.base == ir::Base::Block) return 1;
  return t.is_matrix() ? t.cols * t.vec : t.vec;
}

inline Box top(const ir::Type& t) { return Box(static_cast<size_t>(components(t)), Interval::top()); }

inline Box join(const Box& a, const Box& b) {
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

inline Box fit(const Box& b, size_t n) {  // broadcast a scalar, or hull when shapes disagree
  if (b.size() == n) return b;
  if (b.size() == 1) return Box(n, b[0]);
  return Box(n, Analysis::hull(b));
}

inline Box map2(const Box& a, const Box& b, size_t n, const std::function<Interval(Interval, Interval)>& f) {
  Box x = fit(a, n), y = fit(b, n), r(n);
  for (size_t i = 0; i < n; ++i) r[i] = f(x[i], y[i]);
  return r;
}

inline double mag(const Box& b) { return Analysis::hull(b).mag(); }

inline bool is_arith(const std::string& op) { return op == "+" || op == "-" || op == "*" || op == "/"; }
inline bool is_assign(const std::string& op) {
  return op == "=" || op == "+=" || op == "-=" || op == "*=" || op == "/=" || op == "%=" || op == "<<=" ||
         op == ">>=" || op == "&=" || op == "|=" || op == "^=";
}

// The variable an lvalue writes, and whether it writes the whole of it.
inline const Var* lvalue_root(const ir::ExprPtr& e, bool* whole) {
  *whole = e->kind == Expr::Kind::Sym;
  ir::ExprPtr x = e;
  while (x && (x->kind == Expr::Kind::Member || x->kind == Expr::Kind::Index)) x = x->args[0];
  return x && x->kind == Expr::Kind::Sym ? x->var.get() : nullptr;
}

inline int swizzle_index(char c) {
  switch (c) {
    case 'x': case 'r': case 's': return 0;
    case 'y': case 'g': case 't': return 1;
    case 'z': case 'b': case 'p': return 2;
    case 'w': case 'a': case 'q': return 3;
  }
  return -1;
}

inline bool is_swizzle(const Expr& e) {
  if (e.kind != Expr::Kind::Member || e.args.empty()) return false;
  const ir::Type& t = e.args[0]->type;
  if (t.base == ir::Base::Struct || t.base == ir::Base::Block || t.is_matrix() || t.is_array()) return false;
  for (char c : e.name)
    if (swizzle_index(c) < 0) return false;
  return true;
}

inline bool is_input_storage(ir::Storage s) {
  return s == ir::Storage::In || s == ir::Storage::Uniform || s == ir::Storage::Buffer;
}

}  // namespace detail

using Relations = std::map<std::pair<const Var*, const Var*>, double>;  // (a, b) -> |a - b| bound

// Ranges of every node and declaration, from `env` (the inputs) through global initialisers and main.
void forward_pass(Analysis& a, const ir::Function* main, std::map<const Var*, Box> env, Relations relations);
// Weights of every node and stored value for one output (weight 1 at the end of main).
void backward_pass(Analysis& a, const std::string& output, const ir::Function* main);
// The user function a call resolves to (same name and parameter types), or null.
const ir::Function* resolve_call(const ir::Module& m, const Expr& call);

}  // namespace doublet::plan
