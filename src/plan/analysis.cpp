#include "plan/analysis.hpp"

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "ir/walk.hpp"
#include "plan/analysis_internal.hpp"
#include "plan/transcendentals.hpp"

namespace doublet::plan {
using namespace detail;

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
    // An anonymous block's instance (anon@N) is no value of its own: its members are (inputs,
    // outputs, double declarations).
    const bool block_instance = v->declared_type.base == ir::Base::Block;
    if (v->declared_type.contains_double() && !block_instance) double_vars_.push_back(v);
    // Inputs: in, uniform, and buffer members a shader may read (not writeonly).
    if (is_input_storage(v->storage) && !is_writeonly(v) && !block_instance) inputs_.emplace(v->name, v);
    if (v->storage == ir::Storage::Out || v->storage == ir::Storage::BuiltIn ||
        (v->storage == ir::Storage::Buffer && !is_readonly(v) && !block_instance))
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
  std::map<const Var*, Box> env;
  Relations relations;
  // STRUCT.MEMBER inputs (`sats.pos`, as verify names a buffer's struct members): a struct has one
  // hull here, the join of every member's range, so every member needs one.
  std::map<const Var*, std::pair<std::optional<Interval>, std::set<std::string>>> member_hulls;
  for (const auto& [name, range] : scene.inputs) {
    auto it = inputs_.find(name);
    const size_t dot = name.find('.');
    const auto whole = dot == std::string::npos || it != inputs_.end() ? inputs_.end() : inputs_.find(name.substr(0, dot));
    if (whole != inputs_.end() && whole->second->type.element().base == ir::Base::Struct && whole->second->type.fields) {
      const std::string member = name.substr(dot + 1);
      const auto& fields = *whole->second->type.fields;
      if (std::none_of(fields.begin(), fields.end(), [&](const ir::Field& f) { return f.name == member; })) {
        diagnostics->push_back(scene_diagnostic(scene, range.path, "the struct '" + whole->first + "' has no member '" + member + "'"));
        ok = false;
        continue;
      }
      auto& [hull, named] = member_hulls[whole->second];
      for (const Interval& c : range.components) hull = hull ? join(*hull, c) : c;
      named.insert(member);
      continue;
    }
    if (it == inputs_.end()) {
      diagnostics->push_back(scene_diagnostic(scene, range.path, "the shader has no input (in, uniform or buffer) named '" + name + "'"));
      ok = false;
      continue;
    }
    // An array of vectors or scalars (a buffer's `dvec3 position[]`): the range is per element.
    const ir::Type& type = it->second->type;
    const bool per_element = type.is_array() && type.base != ir::Base::Struct && type.base != ir::Base::Block;
    const size_t n = static_cast<size_t>(components(per_element ? type.element() : type));
    if (range.components.size() != 1 && range.components.size() != n) {
      diagnostics->push_back(scene_diagnostic(scene, range.path, "'" + name + "' has " + std::to_string(n) +
                                                                     " components; give one range or " + std::to_string(n)));
      ok = false;
      continue;
    }
    Box b;
    for (size_t i = 0; i < n; ++i) b.push_back(range.component(i));
    env[it->second] = b;
    var_range_[it->second] = b;
  }
  for (const auto& [v, hull_and_named] : member_hulls) {
    if (env.count(v)) {
      diagnostics->push_back({scene.file, 0, 0, Severity::Error,
                              "the struct input '" + v->name + "' has a range of its own and ranges per member: give one or the other"});
      ok = false;
      continue;
    }
    std::string missing;
    for (const ir::Field& f : *v->type.fields)
      if (!hull_and_named.second.count(f.name)) missing += (missing.empty() ? "" : ", ") + v->name + "." + f.name;
    if (!missing.empty()) {
      diagnostics->push_back({scene.file, 0, 0, Severity::Error,
                              "the struct input '" + v->name + "' is ranged member by member, without " + missing +
                                  ": give every member a range, or one range for '" + v->name + "'"});
      ok = false;
      continue;
    }
    env[v] = Box{*hull_and_named.first};
    var_range_[v] = env[v];
  }
  for (const auto& [name, req] : scene.outputs)
    if (!outputs_.count(name)) {
      diagnostics->push_back(scene_diagnostic(scene, req.path, "the shader has no output (out, gl_Position or buffer) named '" + name + "'"));
      ok = false;
    }
  // A relation's side is an input, or every declaration of a FUNCTION.LOCAL the shader computes.
  auto sides = [&](const Relation& r, const std::string& name) {
    std::vector<const Var*> vars;
    if (!is_computed_value(name)) return std::vector<const Var*>{inputs_.at(name)};
    for (const auto& [v, f] : owner_)
      if (f && f->name + "." + v->name == name && v->declared_type.contains_double()) vars.push_back(v);
    if (vars.empty()) {
      diagnostics->push_back(scene_diagnostic(scene, r.path + "/difference", "the shader has no double local or parameter '" + name + "'"));
      ok = false;
    }
    return vars;
  };
  for (const Relation& r : scene.relations) {
    const std::vector<const Var*> as = sides(r, r.a), bs = sides(r, r.b);
    for (const Var* x : as)
      for (const Var* y : bs) {
        relations[{x, y}] = r.abs_max;
        relations[{y, x}] = r.abs_max;
      }
  }
  if (!ok) return false;
  for (const auto& [name, v] : inputs_)
    if (!scene.inputs.count(name) && v->declared_type.contains_double())
      notes_.push_back("input '" + name + "' has no range in the scene: unbounded");

  // A write-only buffer holds, for the analysis, only what the shader writes: its earlier
  // contents are no value of the shader's (else an element write would join them, unbounded).
  for (const auto& [name, v] : outputs_)
    if (v->storage == ir::Storage::Buffer && is_writeonly(v)) env.emplace(v, Box{});

  // Forward: global initialisers, then main (callees analysed at each call).
  forward_pass(*this, main, std::move(env), std::move(relations));
  for (const auto& [name, v] : outputs_)
    if (!var_range_.count(v)) var_range_[v] = top(v->type);

  // Backward, once per scene output: the output's value at the end of main has weight 1.
  for (const auto& [name, req] : scene.outputs) backward_pass(*this, name, main);
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
  const Mode mode = f ? c.mode_of(f) : c.base;
  const bool fp32 = c.fp32_vars.count(v) || (f && (mode == Mode::Fp32 || mode == Mode::Rte));
  if (fp32) return float_half_ulp(m);
  if (mode == Mode::Exact) return 0;  // binary64 words: the value itself
  if (is_input_storage(v->storage)) return float_float_error(m, kDf64Repr);
  return m > kFloatMax ? kInf : 0;  // a float-float local beyond float's range overflows
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
  const bool exact = mode == Mode::Exact;
  const double half = float_half_ulp(m);
  // One double operation's rounding: binary64's half ulp (exact), or float-float's relative bound
  // inside float's range.
  const double wide = exact ? double_half_ulp(m) : float_float_error(m, mode == Mode::Df64Fast ? kDf64FastRel : kDf64Rel);
  auto by_mode = [&](double fp32_ulps) { return single ? fp32_ulps * half : wide; };
  // k roundings relative to `terms` (sums of products): float and float-float only in float's range.
  const double rel = single ? 0x1p-24 : exact ? kExactRel : kDf64Rel;
  auto of_terms = [&](double k, double terms) { return !exact && terms > kFloatMax ? kInf : k * rel * terms; };
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
      if (exact) return 0;
      if (!single) return float_float_error(m, kDf64Repr);
      double worst = 0;
      for (const ir::Scalar& s : e->values)
        worst = std::max(worst, std::fabs(s.d) > kFloatMax ? kInf : std::fabs(s.d - static_cast<double>(static_cast<float>(s.d))));
      return worst;
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
          return of_terms(k, terms);
        }
        return by_mode(1);
      }
      if (op == "/") return by_mode(5);  // GLSL ES: 2.5 ulp
      return 0;
    }
    case Expr::Kind::Call: {
      // An exact function's result, back in float-float code, is its nearest float-float pair
      // (df_from_exact, docs/modes.md "Exact functions"); its arguments convert exactly.
      if (exact) return 0;
      for (const auto& f : module_->functions)
        if (f->name == e->name && c.mode_of(f.get()) == Mode::Exact) return float_float_error(m, kDf64Repr);
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
        const double err = of_terms(static_cast<double>(k), s);
        if (f == "dot") return err;
        const double len_min = hull(n.range).mig();
        const double through_sqrt = len_min > 0 ? err / (2 * len_min) : std::sqrt(err);
        return std::min(through_sqrt, std::sqrt(err)) + by_mode(6);
      }
      if (f == "normalize") return rel * (2.0 * static_cast<double>(n.args.empty() ? 4 : n.args[0].size()) + 8);
      if (f == "mix" || f == "fma" || f == "cross" || f == "matrixCompMult") {
        double s = 0;
        for (const Box& b : n.args) s = std::max(s, hull(b).mag());
        return of_terms(6, std::max(s * s, m));
      }
      if (is_transcendental(f)) {
        const int arity = static_cast<int>(e->args.size());
        const Interval x = n.args.empty() ? Interval::top() : hull(n.args[0]);
        const Interval y = n.args.size() > 1 ? hull(n.args[1]) : Interval::top();
        if (single) return transcendental_error_float(f, arity, x, y, hull(n.range));
        if (exact) return transcendental_error_exact(f, arity, x, y, hull(n.range));
        return transcendental_error_df64(f, arity, x, y, hull(n.range));
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
double node_flops(const Expr* e, const Analysis::Node& n, Mode mode);

// Mode exact in float-operation equivalents: the time of one binary64 operation in integer
// arithmetic over fp32's, measured on lavapipe (docs/modes.md: add/sub 65x, mul 25x, div 37x,
// sqrt 34x); anything else as its float-float count times add's ratio to df64 (65/20).
double exact_flops(const Expr* e, const Analysis::Node& n) {
  const double k = std::max(1, components(e->type));
  if (e->kind == Expr::Kind::Binary) {
    std::string op = e->op;
    if (is_assign(op) && op != "=") op = op.substr(0, op.size() - 1);
    const ir::Type &lt = e->args[0]->type, &rt = e->args[1]->type;
    if (op == "*" && (lt.is_matrix() || rt.is_matrix())) {
      const double c = lt.is_matrix() ? lt.cols : lt.vec;
      return k * (25 * c + 65 * (c - 1));
    }
    if (op == "+" || op == "-") return 65 * k;
    if (op == "*") return 25 * k;
    if (op == "/") return 37 * k;
  }
  if (e->kind == Expr::Kind::Builtin && e->name == "sqrt") return 34 * k;
  return node_flops(e, n, Mode::Df64) * 65 / 20;
}

double node_flops(const Expr* e, const Analysis::Node& n, Mode mode) {
  if (!e->type.is_double() && !(e->kind == Expr::Kind::Construct && !e->args.empty() && e->args[0]->type.is_double()))
    return 0;
  if (mode == Mode::Exact) return exact_flops(e, n);
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
      if (is_transcendental(f)) return k * (single ? 1 : transcendental_flops_df64(f, static_cast<int>(e->args.size())));
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
