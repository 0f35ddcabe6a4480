// share_exact_calls (mode exact): every call of one operation in a run of straight-line statements
// goes through one call site, so the driver inlines the operation once instead of once per use
// (docs/performance.md, "Mode exact: one call site per operation").
//
// Drivers inline every function. A mode-exact operation is a few hundred integer instructions, and
// lavapipe's LLVM spends tens of milliseconds on each inlined copy, so a loop body of 64 double
// operations compiled for 0.6 s on lavapipe and 2 s on Mesa GLES. Here a run of statements holding
// several calls of the same operation (`ex_add` on two df_dvec3, `ex_mul` on two df_double, a user's
// function without side effects, ...) becomes a loop that executes the run one call at a time:
//
//   d = ex_mul(a, b);              for (int ex_pc1 = 0; ex_pc1 < 2; ++ex_pc1) {
//   e = ex_mul(d, ex_add(d, c));     switch (ex_pc1) {
//   f = ex_to_float(e);              case 0: ex_k1_1_a0 = a; ex_k1_1_a1 = b; ex_op = 1; break;
//                                    case 1: ex_c1_1 = ex_k1_1_r; d = ex_c1_1;
//                                            ex_k1_1_a0 = d; ex_k1_1_a1 = ex_add(d, c); ex_op = 1; break;
//                                    }
//                                    if (ex_op == 1) ex_k1_1_r = ex_mul(ex_k1_1_a0, ex_k1_1_a1);
//                                    (else if (ex_op == 2) ... for a second shared operation)
//                                  }
//                                  ex_c1_2 = ex_k1_1_r; e = ex_c1_2; f = ex_to_float(e);
//
// (ex_op and the ex_k*/ex_c* variables are declared at the top of the function. ex_add, called once
// in the run, stays where it is: one copy either way.)
//
// Each case is the code up to the next call, which stores the call's operands; the call runs after
// the switch; the next case starts by copying its result. The same operations run in the same order
// on the same operands, so the bits are the same (tests/exact). Only calls evaluated whatever the
// values are moved (not the second operand of &&, || or ?:), and only from statements whose
// evaluation writes nothing but their own target; a statement that writes elsewhere (an atomic, a
// store through a call), synchronises (barrier, EmitVertex), depends on the invocations running
// together (derivatives, subgroup operations) or jumps ends the run and stays as it is; where it is
// a call whose arguments have no effects (barrier(), a store through a helper, a user's function
// that emits a vertex), its arguments are the run's last code and the call follows the loop
// (call_with_effects). Matrices and
// arrays are not shared (small_value), and element-wise add/sub/mul/div in several widths share one
// site over df_dvec4 operands (generic_key), as do an addition and a subtraction (ex_each_addsub).
// dot, length, distance and normalize of variables are written out as the additions, products,
// square roots and divisions their rules perform (expand), which then share those sites.
// Declarations in the run are moved before the loop (their initialisers stay in place as
// assignments), where no other variable of the function has their name.
#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using ir::Stmt;
using ir::StmtPtr;
using EKind = ir::Expr::Kind;
using SKind = ir::Stmt::Kind;

// The statement `target = value;`.
StmtPtr assign(const ir::VarPtr& target, const ExprPtr& value) {
  return ir::make_statement(ir::make_assign(ir::make_sym(target), value));
}

// The type a slot holding `e`'s value is declared with: after lowering, some nodes still carry the
// double type they had (lower-doubles rewrites what it must print); a double scalar or vector is a
// df_double / df_dvecN then. Void: none.
ir::Type value_type(const ir::Type& t) {
  if (t.base == ir::Base::Double && !t.is_matrix() && !t.is_array()) return df_type(t.vec);
  return t;
}

// Built-ins whose result depends on which invocations run them together (derivatives, implicit-LOD
// texture sampling, subgroup operations, interpolation at a sample): the loop's control flow is
// uniform, but a statement that uses one stays out of it all the same (WGSL's uniformity analysis
// need not prove the loop uniform).
bool needs_convergence(const std::string& name) {
  for (const char* prefix : {"dFd", "fwidth", "subgroup", "interpolateAt", "texture"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}


// Operands and results of a shared operation are live across the loop's iterations (the driver
// cannot tell which case set them); a matrix's 32 words or an array make the loop spill more than
// the shared copy saves (cad_viewer.vert compiled 1.4x slower with its dmat4 products shared).
bool small_value(const ir::Type& t) { return !t.is_array() && !t.is_matrix() && t.name.find("mat") == std::string::npos; }

// A type a local variable can hold and be assigned (no sampler or image: those are only uniforms or
// parameters; no block).
bool assignable(const ir::Type& t) {
  if (t.base == ir::Base::Opaque || t.base == ir::Base::Block) return false;
  if (t.base == ir::Base::Struct && t.fields)
    for (const ir::Field& f : *t.fields)
      if (!assignable(f.type)) return false;
  return true;
}

// What an operand or result slot may hold: a value (not void), lowered (no double left), small,
// assignable.
bool slot_type(const ir::Type& t) {
  const ir::Type v = value_type(t);
  return v.base != ir::Base::Void && v.base != ir::Base::Double && small_value(t) && assignable(t);
}

// The operations worth one copy: the long integer code of mode exact's arithmetic (rules/exact.glsl),
// named by their stem. Conversions, rounding, loads, stores, negation, comparisons and selections
// are short: sharing a dvec3's conversion to float made lighting_blocks.vert compile slower (334 ->
// 388 ms), its loop holding the rest of the shader.
bool costly_runtime_operation(const std::string& name) {
  static const std::set<std::string> stems = {
      "add",  "sub",   "mul",  "div",  "fma",   "sqrt", "inversesqrt", "length", "distance", "dot",
      "normalize", "cross", "reflect", "refract", "faceforward", "exp", "exp2", "log", "log2", "pow",
      "sin",  "cos",   "tan",  "asin", "acos",  "atan", "sinh", "cosh", "tanh", "asinh", "acosh",
      "atanh", "mod"};
  if (name.rfind("ex_", 0) != 0) return false;
  const size_t end = name.find('_', 3);
  return stems.count(name.substr(3, end == std::string::npos ? std::string::npos : end - 3)) > 0;
}

class CallSharer {
 public:
  CallSharer(ir::Module& module, Context& context) : module_(module), ctx_(context) {}

  void run() {
    for (const auto& f : module_.functions) {
      temporaries_.clear();
      op_ = nullptr;
      collect_names(*f);
      block_lists(f->body);
      auto& body = f->body->body;
      body.insert(body.begin(), temporaries_.begin(), temporaries_.end());
    }
  }

 private:
  struct Operation {  // one shared call site: the callee, its operand and result variables
    ExprPtr call;     // a call of it (name, kind, type)
    std::vector<ir::VarPtr> operands;
    ir::VarPtr result;
    ir::VarPtr width;  // generic (ex_each_OP): the width of the current call's operands
    ir::VarPtr negate;  // ex_each_addsub: 1 where the current call is a subtraction
    int number = 0;
  };

  // Mode exact's composite built-ins, written out as the operations their rules perform, in the
  // same order on the same operands (rules/exact.glsl), so that those share sites with the run's
  // other calls: dot(a, b) is ((b.x a.x + b.y a.y) + ...) (each product and sum passing on its
  // first operand's NaN: ex_mul_first(a, b) is ex_mul(b, a), ex_add_first(s, p) is ex_add(p, s)),
  // length(a) is sqrt(dot(a, a)) (sqrt(a * a) for a double), normalize(a) is a / length(a),
  // distance(a, b) is length(a - b). An operand read twice must be a variable, member or constant
  // index. Only where the run evaluates the call whatever the values are (unconditional operands).
  ExprPtr expand(const ExprPtr& e) {
    const size_t n = ir::unconditional_operands(*e);
    for (size_t i = 0; i < n && i < e->args.size(); ++i) e->args[i] = expand(e->args[i]);
    if (e->kind != EKind::Call || e->args.empty() || !is_df(value_type(e->args[0]->type))) return e;
    const ExprPtr& a = e->args[0];
    const int width = df_width(value_type(a->type));
    const ir::Loc loc = e->loc;
    if (e->name == "ex_distance" && e->args.size() == 2) {
      auto difference = runtime_call("ex_sub", width, df_type(width), {a, e->args[1]}, loc);
      return expand(runtime_call("ex_length", width, e->type, {difference}, loc));
    }
    if (e->args.size() == 1 && ir::is_pure(a)) {
      if (e->name == "ex_normalize") {
        auto length = expand(runtime_call("ex_length", width, df_type(1), {ir::clone(a)}, loc));
        return runtime_call("ex_div", width, e->type, {a, df_splat(ctx_, length, width)}, loc);
      }
      if (e->name == "ex_length") {
        auto square = width == 1 ? runtime_call("ex_mul", 1, df_type(1), {a, ir::clone(a)}, loc)
                                 : expand(runtime_call("ex_dot", width, df_type(1), {a, ir::clone(a)}, loc));
        return runtime_call("ex_sqrt", 1, e->type, {square}, loc);
      }
    }
    if (e->name == "ex_dot" && e->args.size() == 2 && width > 1 && ir::is_pure(a) && ir::is_pure(e->args[1])) {
      const auto product = [&](int k) {
        return runtime_call("ex_mul", 1, df_type(1), {component(e->args[1], k), component(a, k)}, loc);
      };
      ExprPtr sum = product(0);
      for (int k = 1; k < width; ++k) sum = runtime_call("ex_add", 1, df_type(1), {product(k), sum}, loc);
      return sum;
    }
    return e;
  }

  // Component k of a pure df_dvecN as a df_double.
  ExprPtr component(const ExprPtr& v, int k) const { return df_select_pure(ctx_, ir::clone(v), std::string(1, "xyzw"[k]), v->loc); }

  // The expression of `s` a run rewrites: a declaration's initialiser, a return's value, an
  // assignment's value, an expression statement.
  static ExprPtr* run_expression(const StmtPtr& s) {
    if (!s->expr) return nullptr;
    if (s->kind == SKind::Decl || s->kind == SKind::Return) return &s->expr;
    if (s->kind != SKind::Expr) return nullptr;
    if (s->expr->kind == EKind::Binary && s->expr->op == "=") return &s->expr->args[1];
    return &s->expr;
  }

  ExprPtr runtime_call(const std::string& name, int width, const ir::Type& type, std::vector<ExprPtr> args, ir::Loc loc) {
    ctx_.use_rule(name, width);
    return ir::make_node(EKind::Call, name, type, std::move(args), loc);
  }

  // Every statement list of a body, innermost first.
  void block_lists(const StmtPtr& s) {
    if (!s) return;
    for (const auto& b : s->body) block_lists(b);
    if (s->kind == SKind::Block) share_in(s->body);
  }

  void collect_names(const ir::Function& f) {
    names_.clear();
    for (const auto& g : module_.globals) names_[g->name].insert(g.get());
    for (const auto& p : f.params)
      if (p) names_[p->name].insert(p.get());
    ir::visit_statements(f.body, [&](const StmtPtr& s) {
      if (s->kind == SKind::Decl && s->var) names_[s->var->name].insert(s->var.get());
    });
  }

  // The user's function `call` names, when it exists once under that name and signature.
  const ir::Function* user_callee(const Expr& call) const {
    const auto found = ir::overloads(module_, call, [](const ir::Var& param, const ir::Expr& arg) {
      return ir::type_name(param.type) == ir::type_name(value_type(arg.type)) &&
             param.type.array_dims == arg.type.array_dims;
    });
    return found.size() == 1 ? found.front() : nullptr;
  }

  // A user's function that writes only its own locals and calls only such functions: calling it
  // once per iteration of the loop, in the order of the original calls, computes the same.
  bool pure_function(const ir::Function& f) {
    if (auto known = pure_.find(&f); known != pure_.end()) return known->second;
    pure_[&f] = false;  // (GLSL has no recursion; this only ends a malformed cycle)
    bool pure = f.return_type.base != ir::Base::Void && f.name != "main";
    for (const auto& p : f.params) pure = pure && p && !ir::is_out_parameter(p->storage);
    ir::visit_statements(f.body, [&](const StmtPtr& s) {
      if (s->kind == SKind::Discard) pure = false;
      for (const ExprPtr& e : {s->expr, s->step}) pure = pure && (!e || !has_effects(e, /*locals_count=*/false));
    });
    pure_[&f] = pure;
    return pure;
  }

  bool local_target(const ExprPtr& target) const {
    const ir::Var* root = ir::root_variable(target);
    return root && (root->storage == ir::Storage::Local || root->storage == ir::Storage::ParamIn);
  }


  // A call that writes nothing the caller sees: a rule or helper of the runtime without out
  // parameters, or a pure user function.
  bool calls_without_effects(const Expr& call) {
    if (is_runtime_call(call)) return !ctx_.runtime_call_writes_arguments(call);
    const ir::Function* f = user_callee(call);
    return f && pure_function(*f);
  }

  bool shareable(const Expr& e) {
    if (e.kind != EKind::Call || !slot_type(e.type)) return false;
    for (const auto& a : e.args)
      if (!slot_type(a->type)) return false;
    if (is_runtime_call(e)) return costly_runtime_operation(e.name) && !ctx_.runtime_call_writes_arguments(e);
    const ir::Function* f = user_callee(e);
    return f && pure_function(*f);
  }

  // Evaluating `e` writes something (with locals_count false: something but the function's own
  // locals), calls what may, synchronises or depends on the invocations running together.
  bool has_effects(const ExprPtr& e, bool locals_count = true) {
    bool effects = false;
    ir::visit(e, [&](const ExprPtr& x) {
      if (effects) return;
      if ((x->kind == EKind::Binary && ir::is_assignment_operator(x->op)) || ir::is_increment(*x))
        effects = locals_count || !local_target(x->args[0]);
      else if (x->kind == EKind::Builtin)
        effects = ir::builtin_has_side_effects(x->name) || needs_convergence(x->name);
      else if (x->kind == EKind::Call)
        effects = !calls_without_effects(*x);
    });
    return effects;
  }

  // The shareable calls a run always evaluates: by signature, and the widths of each element-wise
  // operation (its generic key).
  struct Tally {
    size_t calls = 0;
    std::map<std::string, int> signatures, generics;
    std::map<std::string, std::set<int>> widths;
    std::map<std::string, std::set<std::string>> names;  // of a generic key's calls (ex_add, ex_sub)
    // A generic key's calls share one site: they come in two widths or more, or as both ex_add and ex_sub.
    bool shares_generic(const std::string& key) const {
      auto w = widths.find(key);
      auto n = names.find(key);
      return (w != widths.end() && w->second.size() > 1) || (n != names.end() && n->second.size() > 1);
    }
  };

  // Writing the run's composites out pays where their operations then share a site with other
  // calls: the run also calls an operation they perform, or composites of two kinds. A run of
  // one composite alone keeps its calls, shared by signature: written out, each of its products
  // and sums would be a trip of the loop (dot3 1.45x and length3 2.1x the run time,
  // docs/performance.md, "Mode exact: composites written out").
  static bool expansion_pays(const Tally& run) {
    static const std::set<std::string> composites = {"ex_dot", "ex_length", "ex_distance", "ex_normalize"};
    static const std::set<std::string> performed = {"ex_add", "ex_sub", "ex_mul", "ex_div", "ex_sqrt"};
    std::set<std::string> kinds;
    bool shares = false;
    for (const auto& [signature, count] : run.signatures) {
      const std::string name = signature.substr(0, signature.find('('));
      if (composites.count(name)) kinds.insert(signature);
      shares = shares || performed.count(name);
    }
    return !kinds.empty() && (shares || kinds.size() > 1);
  }

  void count_calls(const ExprPtr& e, Tally& tally) {
    const size_t n = ir::unconditional_operands(*e);
    for (size_t i = 0; i < n && i < e->args.size(); ++i) count_calls(e->args[i], tally);
    if (!shareable(*e)) return;
    ++tally.calls;
    ++tally.signatures[signature(*e)];
    if (const std::string g = generic_key(*e); !g.empty()) {
      ++tally.generics[g];
      tally.widths[g].insert(df_width(value_type(e->type)));
      tally.names[g].insert(e->name);
    }
  }

  // "ex_mul(*)" for ex_mul and ex_div on df_double or df_dvecN operands of the result's width
  // (element-wise), "ex_addsub(*)" for ex_add and ex_sub, else empty. Within a run where such an
  // operation comes in two widths or more (or as both an addition and a subtraction), its calls
  // share one site over df_dvec4 slots (the helper ex_each_OP loops over the components): one copy
  // of the scalar operation for every width.
  static std::string generic_key(const Expr& call) {
    static const std::set<std::string> elementwise = {"ex_add", "ex_sub", "ex_mul", "ex_div"};
    if (call.kind != EKind::Call || !elementwise.count(call.name)) return "";
    const ir::Type result = value_type(call.type);
    if (!is_df(result)) return "";
    for (const auto& a : call.args)
      if (ir::type_name(value_type(a->type)) != ir::type_name(result)) return "";
    return (call.name == "ex_add" || call.name == "ex_sub" ? std::string("ex_addsub") : call.name) + "(*)";
  }

  // The key a call shares its site under in the current run.
  std::string key_of(const Expr& call) const {
    const std::string g = generic_key(call);
    if (!g.empty() && run_tally_.shares_generic(g)) return g;
    return signature(call);
  }

  int count_of(const std::string& key) const {
    const auto& m = key.find("(*)") != std::string::npos ? run_tally_.generics : run_tally_.signatures;
    auto found = m.find(key);
    return found == m.end() ? 0 : found->second;
  }

  static std::string signature(const Expr& call) {
    std::string s = call.name + "(";
    for (const auto& a : call.args) s += ir::type_name(value_type(a->type)) + ir::array_suffix(a->type) + ",";
    return s + ")";
  }

  // What a statement is to a run: code without shareable calls (Plain), code with some (Calls), or
  // what ends the run (Barrier: it writes more than its own target, jumps, or its declaration
  // cannot move before the loop). Counts its calls into `counts`.
  enum class Role { Plain, Calls, Barrier };
  Role role(const StmtPtr& s, Tally& counts) {
    if (s->kind == SKind::Decl) {
      if (!s->var || s->var->storage != ir::Storage::Local) return Role::Barrier;
      if (names_[s->var->name].size() != 1) return Role::Barrier;
      if (!s->expr) return Role::Plain;
      if (has_effects(s->expr)) return Role::Barrier;
      const size_t before = counts.calls;
      count_calls(s->expr, counts);
      return counts.calls > before ? Role::Calls : Role::Plain;
    }
    if (s->kind == SKind::Return) {  // ends the run (share_in): its value is the run's last code
      if (!s->expr) return Role::Barrier;
      if (has_effects(s->expr)) return Role::Barrier;
      const size_t before = counts.calls;
      count_calls(s->expr, counts);
      return counts.calls > before ? Role::Calls : Role::Plain;
    }
    if (s->kind != SKind::Expr || !s->expr) return Role::Barrier;
    const ExprPtr& e = s->expr;
    const bool assignment = e->kind == EKind::Binary && e->op == "=";
    const ExprPtr& value = assignment ? e->args[1] : e;
    if (assignment ? (has_effects(e->args[0]) || has_effects(value)) : has_effects(value) && !call_with_effects(s))
      return Role::Barrier;
    const size_t before = counts.calls;
    count_calls(value, counts);
    return counts.calls > before ? Role::Calls : Role::Plain;
  }

  // `f(x, y);` where only the call itself has effects (a user's function that writes outputs or
  // emits a vertex, an image store, an atomic): its arguments are evaluated before it, so they may
  // be the run's last code, and the call follows the loop; nothing after it joins the run.
  bool call_with_effects(const StmtPtr& s) {
    if (s->kind != SKind::Expr || !s->expr) return false;
    const Expr& e = *s->expr;
    if (e.kind != EKind::Call && !(e.kind == EKind::Builtin && !needs_convergence(e.name))) return false;
    return std::none_of(e.args.begin(), e.args.end(), [&](const ExprPtr& a) { return has_effects(a); }) &&
           has_effects(s->expr);
  }

  // `a = x, b = f(a);` as a statement (mode exact's stores into blocks) is `a = x; b = f(a);`: split,
  // so that a run may go on through it.
  static void split_commas(std::vector<StmtPtr>& list) {
    std::vector<StmtPtr> split;
    for (const StmtPtr& s : list) {
      const bool sequence = s->kind == SKind::Expr && s->expr && s->expr->kind == EKind::Comma &&
                            std::all_of(s->expr->args.begin(), s->expr->args.end(), [](const ExprPtr& a) {
                              return a->kind == EKind::Binary && a->op == "=";
                            });
      if (!sequence) {
        split.push_back(s);
        continue;
      }
      for (const ExprPtr& a : s->expr->args) {
        split.push_back(ir::make_statement(a));
        split.back()->loc = s->loc;
      }
    }
    list = std::move(split);
  }

  void share_in(std::vector<StmtPtr>& list) {
    split_commas(list);
    std::vector<StmtPtr> out;
    size_t i = 0;
    while (i < list.size()) {
      // A run: statements that are Plain or Calls; it is rewritten from its first to its last Calls.
      Tally counts;
      size_t first = list.size(), last = 0, j = i;
      bool ended = false;  // the statement that ended the run is its last (a return, call_with_effects)
      for (; j < list.size(); ++j) {
        const Role r = role(list[j], counts);
        if (r == Role::Barrier) break;
        if (r == Role::Calls) {
          first = std::min(first, j);
          last = j;
        }
        if (list[j]->kind == SKind::Return || call_with_effects(list[j])) {
          ended = true;
          ++j;
          break;
        }
      }
      if (expansion_pays(counts)) {  // the same statements, their composites written out
        counts = Tally{};
        for (size_t k = i; k < j; ++k) {
          if (ExprPtr* e = run_expression(list[k])) *e = expand(*e);
          role(list[k], counts);
        }
      }
      const auto repeated = [](const auto& m) {
        return std::any_of(m.begin(), m.end(), [](const auto& c) { return c.second > 1; });
      };
      const bool worth = repeated(counts.signatures) ||
                         std::any_of(counts.generics.begin(), counts.generics.end(),
                                     [&](const auto& g) { return counts.shares_generic(g.first); });
      if (first < list.size() && worth) {
        out.insert(out.end(), list.begin() + i, list.begin() + first);
        run_tally_ = counts;
        rewrite_run(std::vector<StmtPtr>(list.begin() + first, list.begin() + last + 1), out);
        out.insert(out.end(), list.begin() + last + 1, list.begin() + j);
      } else {
        out.insert(out.end(), list.begin() + i, list.begin() + j);
      }
      if (j < list.size() && !ended) {  // the statement that ended the run
        out.push_back(list[j]);
        ++j;
      }
      i = j;
    }
    list = std::move(out);
  }

  ir::VarPtr temporary(const std::string& name, const ir::Type& type) {
    return declare_temporary(name, type, {}, temporaries_);
  }

  Operation& operation_for(const Expr& call) {
    const std::string key = key_of(call);
    auto found = operations_.find(key);
    if (found != operations_.end()) return found->second;
    Operation op;
    op.number = static_cast<int>(operations_.size()) + 1;
    const std::string stem = "ex_k" + std::to_string(run_number_) + "_" + std::to_string(op.number);
    const bool generic = key != signature(call);
    op.call = generic ? ir::make_node(call.kind, each_helper(call), df_type(4), {}, call.loc)
                      : ir::make_node(call.kind, call.name, value_type(call.type), {}, call.loc);
    for (size_t a = 0; a < call.args.size(); ++a)
      op.operands.push_back(temporary(stem + "_a" + std::to_string(a), generic ? df_type(4) : value_type(call.args[a]->type)));
    op.result = temporary(stem + "_r", op.call->type);
    if (generic) op.width = temporary(stem + "_w", ir::scalar_type(ir::Base::Int));
    if (generic && key == "ex_addsub(*)") op.negate = temporary(stem + "_n", ir::scalar_type(ir::Base::Int));
    return operations_.emplace(key, std::move(op)).first->second;
  }

  // ex_each_OP(a, b, w): the width-1 OP on components w-1 .. 0 of two df_dvec4 (the index counts
  // down, as mode exact's per-component loops do: docs/performance.md).
  std::string each_helper(const Expr& call) {
    if (call.name == "ex_add" || call.name == "ex_sub") return addsub_helper();
    const std::string name = "ex_each_" + call.name.substr(3);
    ctx_.use_rule(call.name, 1);
    return component_loop(name, "", "",
                          "    df_double c = " + call.name + "(df_double(a.hi[i], a.lo[i]), df_double(b.hi[i], b.lo[i]));\n"
                          "    r.hi[i] = c.hi;\n"
                          "    r.lo[i] = c.lo;\n");
  }

  // ex_each_addsub(a, b, w, n): a + b, or a - b where n is 1, on components w-1 .. 0. A subtraction
  // is the addition of b with its sign flipped, except for which NaN it passes on: ex_sub_bits's
  // (rules/exact.glsl), selected where n is 1 and an operand is a NaN. One ex_add_bits for both.
  std::string addsub_helper() {
    ctx_.use_rule("ex_sub", 1);  // ex_sub_bits: ex_add_bits, ex_either_nan, ex_pick_nan, ex_sel64
    return component_loop("ex_each_addsub", ", int n", "  uint sign = uint(n) << 31;\n",
                          "    uvec2 x = uvec2(a.lo[i], a.hi[i]);\n"
                          "    uvec2 y = uvec2(b.lo[i], b.hi[i]);\n"
                          "    uvec2 s = ex_add_bits(x, uvec2(y.x, y.y ^ sign));\n"
                          "    s = ex_sel64(all(bvec2(n == 1, ex_either_nan(x, y))), ex_pick_nan(x, y), s);\n"
                          "    r.hi[i] = s.y;\n"
                          "    r.lo[i] = s.x;\n");
  }

  // `df_dvec4 NAME(df_dvec4 a, df_dvec4 b, int w PARAMS)`: r = a, then `body` for component i of
  // w-1 .. 0 (the index counts down, as mode exact's per-component loops do), after `setup`.
  std::string component_loop(const std::string& name, const std::string& params, const std::string& setup,
                             const std::string& body) {
    ctx_.use_width(1);
    ctx_.use_width(4);
    ctx_.add_helper(name, "df_dvec4 " + name + "(df_dvec4 a, df_dvec4 b, int w" + params + ") {\n"
                          "  df_dvec4 r = a;\n" + setup +
                          "  for (int k = 0; k < w; ++k) {\n"
                          "    int i = w - 1 - k;\n" + body +
                          "  }\n"
                          "  return r;\n"
                          "}\n");
    return name;
  }

  // A df_double / df_dvecN value as a df_dvec4 (zeros above), and back.
  ExprPtr widened(const ExprPtr& value, int width) {
    if (width == 4) return value;
    const std::string from = df_type_name(width), name = "ex_widen_" + from.substr(3);
    const std::string zeros = width == 1 ? ", 0u, 0u, 0u" : width == 2 ? ", 0u, 0u" : ", 0u";
    ctx_.add_helper(name, "df_dvec4 " + name + "(" + from + " x) {\n  return df_dvec4(uvec4(x.hi" + zeros +
                              "), uvec4(x.lo" + zeros + "));\n}\n");
    return ir::make_node(EKind::Call, name, df_type(4), {value}, value->loc);
  }

  ExprPtr narrowed(const ExprPtr& value, int width) {
    if (width == 4) return value;
    const std::string to = df_type_name(width), name = "ex_narrow_" + to.substr(3);
    const std::string part = width == 1 ? ".x" : width == 2 ? ".xy" : ".xyz";
    ctx_.add_helper(name, to + " " + name + "(df_dvec4 x) {\n  return " + to + "(x.hi" + part + ", x.lo" + part + ");\n}\n");
    return ir::make_node(EKind::Call, name, df_type(width), {value}, value->loc);
  }

  // Moves the shareable calls out of `e` (post-order, as evaluated): each ends the current case with
  // its operands stored; the next case starts with its result in a temporary, which replaces it.
  ExprPtr lift(const ExprPtr& e) {
    const size_t n = ir::unconditional_operands(*e);
    for (size_t i = 0; i < n && i < e->args.size(); ++i) e->args[i] = lift(e->args[i]);
    if (!shareable(*e) || count_of(key_of(*e)) < 2) return e;  // one call: one copy either way
    Operation& op = operation_for(*e);
    const int width = op.width ? df_width(value_type(e->type)) : 0;
    for (size_t a = 0; a < e->args.size(); ++a)
      cases_.back().push_back(assign(op.operands[a], op.width ? widened(e->args[a], width) : e->args[a]));
    if (op.width) cases_.back().push_back(assign(op.width, ir::make_int(width)));
    if (op.negate) cases_.back().push_back(assign(op.negate, ir::make_int(e->name == "ex_sub" ? 1 : 0)));
    cases_.back().push_back(assign(op_, ir::make_int(op.number)));
    const ir::Type type = op.width ? df_type(width) : op.call->type;
    auto result = temporary("ex_c" + std::to_string(run_number_) + "_" + std::to_string(cases_.size()), type);
    cases_.push_back({assign(result, op.width ? narrowed(ir::make_sym(op.result), width) : ir::make_sym(op.result))});
    return ir::make_sym(result);
  }

  void rewrite_run(const std::vector<StmtPtr>& run, std::vector<StmtPtr>& out) {
    ++run_number_;
    operations_.clear();
    cases_.assign(1, {});
    if (!op_) op_ = temporary("ex_op", ir::scalar_type(ir::Base::Int));
    for (const StmtPtr& s : run) {
      if (s->kind == SKind::Decl) {
        auto decl = Stmt::make(SKind::Decl, s->loc);
        decl->var = s->var;
        out.push_back(decl);
        if (s->expr) {
          ExprPtr value = lift(s->expr);  // (adds cases: cases_.back() only after it)
          cases_.back().push_back(assign(s->var, value));
        }
      } else if (s->kind == SKind::Return) {
        s->expr = lift(s->expr);
        cases_.back().push_back(s);
      } else if (s->expr->kind == EKind::Binary && s->expr->op == "=") {
        s->expr->args[1] = lift(s->expr->args[1]);
        cases_.back().push_back(s);
      } else {
        s->expr = lift(s->expr);
        cases_.back().push_back(s);
      }
    }
    // The loop: one case per call, the call after the switch; the code after the last call follows it.
    auto pc = std::make_shared<ir::Var>();
    pc->name = "ex_pc" + std::to_string(run_number_);
    pc->type = pc->declared_type = ir::scalar_type(ir::Base::Int);
    auto init = Stmt::make(SKind::Decl);
    init->var = pc;
    init->expr = ir::make_int(0);
    auto labelled = Stmt::make(SKind::Block);
    for (size_t c = 0; c + 1 < cases_.size(); ++c) {
      auto label = Stmt::make(SKind::Case);
      label->expr = ir::make_int(static_cast<int>(c));
      labelled->body.push_back(label);
      labelled->body.insert(labelled->body.end(), cases_[c].begin(), cases_[c].end());
      labelled->body.push_back(Stmt::make(SKind::Break));
    }
    auto choose = Stmt::make(SKind::Switch);
    choose->expr = ir::make_sym(pc);
    choose->body = {labelled};
    StmtPtr dispatch;  // if (ex_op == 1) r1 = f1(...); else if (ex_op == 2) ...
    std::vector<const Operation*> ordered;
    for (const auto& [key, op] : operations_) ordered.push_back(&op);
    std::sort(ordered.begin(), ordered.end(), [](const Operation* a, const Operation* b) { return a->number > b->number; });
    for (const Operation* op : ordered) {
      auto call = ir::make_node(op->call->kind, op->call->name, op->call->type, {}, op->call->loc);
      for (const auto& v : op->operands) call->args.push_back(ir::make_sym(v));
      if (op->width) call->args.push_back(ir::make_sym(op->width));
      if (op->negate) call->args.push_back(ir::make_sym(op->negate));
      auto branch = Stmt::make(SKind::If);
      branch->expr = ir::make_binary("==", ir::scalar_type(ir::Base::Bool), ir::make_sym(op_), ir::make_int(op->number));
      auto then = Stmt::make(SKind::Block);
      then->body = {assign(op->result, call)};
      branch->body = {then};
      if (dispatch) branch->body.push_back(dispatch);
      dispatch = branch;
    }
    auto body = Stmt::make(SKind::Block);
    body->body = {choose, dispatch};
    auto loop = Stmt::make(SKind::Loop);
    const int last = static_cast<int>(cases_.size() - 1);
    loop->expr = ir::make_binary("<", ir::scalar_type(ir::Base::Bool), ir::make_sym(pc), ir::make_int(last));
    auto step = ir::make_node(EKind::Unary, "", pc->type, {ir::make_sym(pc)}, {});
    step->op = "++x";
    loop->step = step;
    loop->body = {init, body};
    out.push_back(loop);
    out.insert(out.end(), cases_.back().begin(), cases_.back().end());
  }

  ir::Module& module_;
  Context& ctx_;
  std::vector<StmtPtr> temporaries_;
  std::map<std::string, std::set<const ir::Var*>> names_;
  std::map<const ir::Function*, bool> pure_;
  std::map<std::string, Operation> operations_;
  Tally run_tally_;  // the current run's shareable calls
  std::vector<std::vector<StmtPtr>> cases_;
  ir::VarPtr op_;
  int run_number_ = 0;
};

}  // namespace

bool share_exact_calls(ir::Module& module, Context& context) {
  CallSharer(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
