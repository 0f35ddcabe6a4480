// optimize_df: see optimize_df.hpp. One post-order walk over every expression of the lowered
// module; each rewrite looks only at a rule call and its (already rewritten) operands.
#include "lower/optimize_df.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "frontend/text_scan.hpp"
#include "ir/walk.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

ExprPtr make_call(const std::string& name, ir::Type type, std::vector<ExprPtr> args, ir::Loc loc) {
  return ir::make_node(Kind::Call, name, std::move(type), std::move(args), loc);
}

bool is_const_zero(const ExprPtr& e) {
  if (e->kind == Kind::Const)
    return std::all_of(e->values.begin(), e->values.end(), [](const ir::Scalar& s) { return s.d == 0.0 && s.i == 0; });
  // vec3(0.0): a constructor of one zero constant.
  if (e->kind == Kind::Construct && e->args.size() == 1 && e->type.base == ir::Base::Float)
    return is_const_zero(e->args[0]) && e->args[0]->type.vec == 1;
  return false;
}

// The float (same width as the df value) that `e` is known to equal exactly, i.e. `e`'s lo word
// is known to be zero; null when unknown.
ExprPtr known_float(const ExprPtr& e) {
  if (!is_df(e->type)) return nullptr;
  if (e->kind == Kind::Call && e->name == "df_from_float" && e->args.size() == 1) return e->args[0];
  if (e->kind == Kind::Construct && e->args.size() == 2 && is_const_zero(e->args[1]) &&
      e->args[0]->type.base == ir::Base::Float && e->args[0]->type.vec == df_width(e->type))
    return e->args[0];
  if (e->kind == Kind::Call && e->name.rfind("df_splat_dvec", 0) == 0 && e->args.size() == 1) {
    ExprPtr s = known_float(e->args[0]);
    if (!s) return nullptr;
    auto v = Expr::make(Kind::Construct, ir::scalar_type(ir::Base::Float, df_width(e->type)), e->loc);
    v->args = {s};
    return v;
  }
  return nullptr;
}

bool is_pow2(double v) {
  if (v == 0.0 || !std::isfinite(v)) return false;
  int exp = 0;
  return std::fabs(std::frexp(v, &exp)) == 0.5;
}

// A float constant (or a constructor splatting one) whose every component is +-2^k.
bool const_pow2(const ExprPtr& e, std::vector<double>* values = nullptr) {
  if (e->kind == Kind::Const && e->type.base == ir::Base::Float && !e->values.empty()) {
    for (const auto& s : e->values)
      if (!is_pow2(s.d)) return false;
    if (values)
      for (const auto& s : e->values) values->push_back(s.d);
    return true;
  }
  if (e->kind == Kind::Construct && e->type.base == ir::Base::Float && e->args.size() == 1 &&
      e->args[0]->type.vec == 1)
    return const_pow2(e->args[0], values);
  return false;
}

// 1/p for a power-of-two constant: exact.
ExprPtr reciprocal(const ExprPtr& p) {
  std::vector<double> values;
  const_pow2(p, &values);
  auto r = Expr::make(Kind::Const, p->type, p->loc);
  for (size_t i = 0; i < static_cast<size_t>(p->type.vec); ++i) {
    ir::Scalar s;
    s.base = ir::Base::Float;
    s.d = 1.0 / values[std::min(i, values.size() - 1)];
    r->values.push_back(s);
  }
  return r;
}

ExprPtr negate_float(const ExprPtr& f) {
  if (f->kind == Kind::Const) {
    auto c = std::make_shared<Expr>(*f);
    for (auto& s : c->values) s.d = -s.d;
    return c;
  }
  auto n = Expr::make(Kind::Unary, f->type, f->loc);
  n->op = "-";
  n->args = {f};
  return n;
}

// Structural equality of side-effect-free expressions (variables, constants, members, indices
// and constructors of those): evaluating either gives the same value.
bool same_pure(const ExprPtr& a, const ExprPtr& b) {
  if (a->kind != b->kind || a->args.size() != b->args.size()) return false;
  switch (a->kind) {
    case Kind::Sym: return a->var == b->var;
    case Kind::Const:
      if (a->values.size() != b->values.size() || ir::type_name(a->type) != ir::type_name(b->type)) return false;
      for (size_t i = 0; i < a->values.size(); ++i)
        if (a->values[i].d != b->values[i].d || a->values[i].i != b->values[i].i || a->values[i].b != b->values[i].b)
          return false;
      return true;
    case Kind::Member:
      if (a->name != b->name) return false;
      break;
    case Kind::Index: break;
    case Kind::Construct:
      if (ir::type_name(a->type) != ir::type_name(b->type) || a->type.is_array() || b->type.is_array()) return false;
      break;
    default: return false;
  }
  for (size_t i = 0; i < a->args.size(); ++i)
    if (!same_pure(a->args[i], b->args[i])) return false;
  return true;
}

class Optimizer {
 public:
  explicit Optimizer(OptimizeStats& stats) : stats_(stats) {}

  ExprPtr operator()(const ExprPtr& e) {
    // float(double(f)) is f (df_to_float keeps a zero's sign where the sum is zero).
    if (e->kind == Kind::Call && e->name == "df_to_float" && e->args.size() == 1 && e->args[0]->kind == Kind::Call &&
        e->args[0]->name == "df_from_float" && e->args[0]->args.size() == 1) {
      ++stats_.low_words;
      return e->args[0]->args[0];
    }
    if (e->kind != Kind::Call || e->args.size() != 2 || !is_df(e->type)) return nullptr;
    const std::string& n = e->name;
    const ExprPtr& a = e->args[0];
    const ExprPtr& b = e->args[1];
    if (n == "df_mul") return mul(e, a, b);
    if (n == "df_div") {
      if (!is_df(b->type)) return nullptr;
      ExprPtr fb = known_float(b);
      if (fb && const_pow2(fb)) return pow2(e, a, reciprocal(fb));
      return nullptr;
    }
    if (n == "df_mul_f" && const_pow2(b)) return pow2(e, a, b);
    if (n == "df_add" || n == "df_sub") return add(e, a, b, n == "df_sub");
    return nullptr;
  }

 private:
  ExprPtr pow2(const ExprPtr& e, const ExprPtr& a, const ExprPtr& p) {
    ++stats_.pow2;
    return make_call("df_mul_pow2", e->type, {a, p}, e->loc);
  }

  ExprPtr mul(const ExprPtr& e, const ExprPtr& a, const ExprPtr& b) {
    if (!is_df(a->type) || !is_df(b->type)) return nullptr;
    ExprPtr fa = known_float(a), fb = known_float(b);
    if (fb && const_pow2(fb)) return pow2(e, a, fb);
    if (fa && const_pow2(fa)) return pow2(e, b, fa);
    if (fa && fb) {
      ++stats_.exact_pairs;
      return make_call("df_two_prod", e->type, {fa, fb}, e->loc);
    }
    if (fb) {
      ++stats_.float_operands;
      return make_call("df_mul_f2", e->type, {a, fb}, e->loc);
    }
    if (fa) {
      ++stats_.float_operands;
      return make_call("df_mul_f2", e->type, {b, fa}, e->loc);
    }
    if (same_pure(a, b)) {
      ++stats_.squares;
      return make_call("df_sqr", e->type, {a}, e->loc);
    }
    return nullptr;
  }

  ExprPtr add(const ExprPtr& e, const ExprPtr& a, const ExprPtr& b, bool subtract) {
    if (!is_df(a->type) || !is_df(b->type)) return nullptr;
    ExprPtr fa = known_float(a), fb = known_float(b);
    if (subtract && fb && fb->kind == Kind::Call && fb->name == "df_to_float" && fb->args.size() == 1 &&
        same_pure(fb->args[0], a)) {
      ++stats_.low_words;
      return make_call("df_from_float", e->type, {low_word(a)}, e->loc);
    }
    if (fa && fb) {
      ++stats_.exact_pairs;
      return make_call("df_two_sum", e->type, {fa, subtract ? negate_float(fb) : fb}, e->loc);
    }
    if (fb) {
      ++stats_.float_operands;
      return make_call("df_add_f", e->type, {a, subtract ? negate_float(fb) : fb}, e->loc);
    }
    if (fa) {
      ++stats_.float_operands;
      // f - b = (-b) + f; negation of a double-word is exact.
      ExprPtr other = subtract ? make_call("df_neg", b->type, {b}, b->loc) : b;
      return make_call("df_add_f", e->type, {other, fa}, e->loc);
    }
    return nullptr;
  }

  // The lo word of a side-effect-free df expression: a constructor's second argument, else `.lo`.
  static ExprPtr low_word(const ExprPtr& a) {
    if (a->kind == Kind::Construct && a->args.size() == 2) return a->args[1];
    auto lo = Expr::make(Kind::Member, ir::scalar_type(ir::Base::Float, df_width(a->type)), a->loc);
    lo->name = "lo";
    lo->args = {a};
    return lo;
  }

  OptimizeStats& stats_;
};

// A rule call (name, width) made by the module's code: the width is that of the first df argument,
// else of the df result (df_add_f(a, f): a's width; df_two_sum(f, g): the result's).
void collect_call(const ExprPtr& e, std::set<std::pair<std::string, int>>& out) {
  if (e->kind != Kind::Call || e->name.rfind("df_", 0) != 0) return;
  int width = 0;
  for (const auto& a : e->args)
    if (is_df(a->type)) {
      width = df_width(a->type);
      break;
    }
  if (!width && is_df(e->type)) width = df_width(e->type);
  out.insert({e->name, width});
}

}  // namespace

bool optimize_df(ir::Module& module, Context& ctx, OptimizeStats* stats) {
  if (ctx.failed) return false;
  OptimizeStats local;
  OptimizeStats& s = stats ? *stats : local;
  Optimizer opt(s);
  const ir::ExprRewriter f = [&](const ExprPtr& e) { return opt(e); };
  for (auto& init : module.global_inits) init = ir::rewrite(init, f);
  for (auto& fn : module.functions) ir::rewrite(fn->body, f);
  if (s.pow2 + s.squares + s.float_operands + s.exact_pairs + s.low_words == 0) return true;

  // Bring rules_used up to date: add what is now called, drop what the rewrites replaced when
  // nothing calls it any more (neither the code nor a generated helper).
  std::set<std::pair<std::string, int>> called;
  const ir::ExprVisitor collect = [&](const ExprPtr& e) { collect_call(e, called); };
  for (const auto& init : module.global_inits) ir::visit(init, collect);
  for (const auto& fn : module.functions) ir::visit(fn->body, collect);
  static const std::set<std::string> replaceable{"df_mul", "df_div", "df_mul_f", "df_add", "df_sub", "df_from_float"};
  std::string helper_text;
  std::set<std::pair<std::string, int>> helper_calls;  // in helpers' expressions, not yet spelled
  const ir::ExprVisitor collect_helper = [&](const ExprPtr& e) { collect_call(e, helper_calls); };
  for (const auto& [name, helper] : ctx.helpers) {
    helper_text += helper.head + helper.tail;
    if (helper.expression) ir::visit(helper.expression, collect_helper);
  }
  // A call `name(` in the helpers' text, not the tail of a longer name (df_mul in df_mul_pow2( is not
  // a call of df_mul; xdf_mul( is not either).
  const auto in_helpers = [&](const std::string& name) {
    for (const auto& [called_name, width] : helper_calls)
      if (called_name == name) return true;
    const std::string call = name + "(";
    for (size_t at = helper_text.find(call); at != std::string::npos; at = helper_text.find(call, at + 1))
      if (at == 0 || !frontend::is_word_char(helper_text[at - 1])) return true;
    return false;
  };
  std::vector<rules::RuleRef> kept;
  for (const auto& r : ctx.rules_used)
    if (!replaceable.count(r.name) || called.count({r.name, r.width}) || in_helpers(r.name)) kept.push_back(r);
  ctx.rules_used = std::move(kept);
  static const std::set<std::string> added{"df_mul_pow2", "df_sqr", "df_mul_f2", "df_add_f", "df_two_sum",
                                           "df_two_prod", "df_neg", "df_from_float"};
  for (const auto& [name, width] : called)
    if (added.count(name) && width >= 1 && width <= 4) ctx.use_rule(name, width);
  return true;
}

}  // namespace doublet::passes
