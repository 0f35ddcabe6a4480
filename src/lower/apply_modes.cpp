// apply_modes: see apply_modes.hpp and docs/modes.md.
#include "lower/apply_modes.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

#include "ir/walk.hpp"

namespace doublet::passes {
namespace {

using ir::Base;
using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

bool is_real(const ir::Type& t) { return t.base == Base::Float || t.base == Base::Double; }

bool same_shape(const ir::Type& a, const ir::Type& b) {
  return a.base == b.base && a.vec == b.vec && a.cols == b.cols && a.array_dims == b.array_dims && a.name == b.name;
}

using ir::clone;
using ir::is_pure;
bool is_arithmetic(const std::string& op) { return op == "+" || op == "-" || op == "*" || op == "/"; }
bool is_comparison(const std::string& op) {
  return op == "<" || op == ">" || op == "<=" || op == ">=" || op == "==" || op == "!=";
}

// df64-int is a property of the emitted runtime (its TwoSum/TwoProd), shared by every
// float-float operation of the shader, so it cannot be chosen per declaration.
constexpr const char* kDf64IntWholeShader =
    "mode df64-int applies to the whole shader only (--mode df64-int): it replaces the runtime's error-free "
    "transformations, which every float-float operation shares";

// Mode exact per declaration: a function's body in binary64 words (lower/exact_functions.cpp).
constexpr const char* kExactFunctionsOnly =
    "mode exact applies to a whole shader (--mode exact) or to functions (--mode-for FUNCTION=exact, or the pragma "
    "before a function), not to a variable: its doubles would need both representations";

// Float arithmetic in fp32 and rte; float-float in df64-fast and df64.
Base arithmetic_base(Mode m) { return m == Mode::Fp32 || m == Mode::Rte ? Base::Float : Base::Double; }

class ModeApplier {
 public:
  // rte-exact's arithmetic is rte's (its storage, binary64 words, is lower_doubles' business).
  ModeApplier(ir::Module& m, Context& c)
      : module_(m), ctx_(c), global_(c.config.mode == Mode::RteExact ? Mode::Rte : c.config.mode) {}

  bool resolve(const std::vector<frontend::ModePragma>& pragmas) {
    index_declarations();
    for (const auto& p : pragmas) apply_pragma(p);
    for (const auto& [name, mode] : ctx_.config.mode_for) apply_name(name, mode);
    return !ctx_.failed;
  }

  void run() {
    for (const auto& f : module_.functions) {
      if (function_mode(f.get()) == Mode::Df64Fast) ctx_.fast_functions.insert(f.get());
      if (function_mode(f.get()) == Mode::Exact) ctx_.exact_functions.insert(f.get());
    }
    ctx_.fast_global_inits = global_ == Mode::Df64Fast;
    if (!any_float_mode()) return;  // all float-float: nothing to retype, output unchanged

    for (const auto& g : module_.globals) demote_if_fp32(*g);
    for (const auto& f : module_.functions) {
      if (function_mode(f.get()) == Mode::Fp32 && f->return_type.base == Base::Double)
        f->return_type = f->return_type.with_base(Base::Float);
      for (const auto& p : f->params) demote_if_fp32(*p);
      for (ir::Var* local : locals_[f.get()]) demote_if_fp32(*local);
    }
    check_overloads();
    arithmetic_ = global_;
    for (size_t i = 0; i < module_.globals.size(); ++i)
      if (module_.global_inits[i])
        module_.global_inits[i] = convert_to(fix(module_.global_inits[i]), module_.globals[i]->type);
    for (const auto& f : module_.functions) {
      current_ = f.get();
      arithmetic_ = function_mode(f.get());
      fix_statement(f->body);
    }
  }

 private:
  // ---- which mode applies where ---------------------------------------------------------
  struct Declaration {
    ir::Loc loc;
    ir::Var* var = nullptr;          // a global or local variable
    ir::Function* function = nullptr;
  };

  void index_declarations() {
    for (const auto& g : module_.globals)
      if (!g->block && g->loc.line > 0) declarations_.push_back({g->loc, g.get(), nullptr});
    for (const auto& f : module_.functions) {
      if (f->loc.line > 0) declarations_.push_back({f->loc, nullptr, f.get()});
      for (const auto& p : f->params) owner_[p.get()] = f.get();
      collect_locals(f->body, f.get());
    }
    std::stable_sort(declarations_.begin(), declarations_.end(), [](const Declaration& a, const Declaration& b) {
      return a.loc.line != b.loc.line ? a.loc.line < b.loc.line : a.loc.column < b.loc.column;
    });
  }

  void collect_locals(const ir::StmtPtr& s, ir::Function* f) {
    if (!s) return;
    if (s->kind == ir::Stmt::Kind::Decl && s->var && !owner_.count(s->var.get())) {
      owner_[s->var.get()] = f;
      locals_[f].push_back(s->var.get());
      if (s->var->loc.line > 0) declarations_.push_back({s->var->loc, s->var.get(), nullptr});
    }
    for (const auto& b : s->body) collect_locals(b, f);
  }

  // The globals named on a line, searched once per line however many pragmas precede it.
  const std::vector<ir::Var*>& globals_named_on(int line, const std::string& text) {
    auto [it, added] = globals_on_line_.try_emplace(line);
    if (added)
      for (const auto& g : module_.globals)
        if (!g->block && has_word(text, g->name)) it->second.push_back(g.get());
    return it->second;
  }

  static bool has_word(const std::string& text, const std::string& word) {
    auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (size_t pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) {
      size_t after = pos + word.size();
      if ((pos == 0 || !is_word(text[pos - 1])) && (after >= text.size() || !is_word(text[after]))) return true;
    }
    return false;
  }

  // The declaration on the pragma's next code line: at top level a function (glslang places
  // it on its name's line) or every global named on that line (a global's recorded place may
  // be its first use); inside a function the local declared there.
  void apply_pragma(const frontend::ModePragma& p) {
    std::string spelled = "'#pragma doublet mode(" + std::string(to_string(p.mode)) + ")'";
    std::vector<ir::Var*> vars;
    ir::Function* function = nullptr;
    if (p.next_line > 0) {
      // declarations_ is sorted by line: only that line's entries, not all of them per pragma.
      auto d = std::lower_bound(declarations_.begin(), declarations_.end(), p.next_line,
                                [](const Declaration& x, int line) { return x.loc.line < line; });
      for (; d != declarations_.end() && d->loc.line == p.next_line; ++d) {
        if (p.top_level && d->function && !function) function = d->function;
        if (!p.top_level && d->var && owner_.count(d->var) && vars.empty()) vars.push_back(d->var);
      }
      if (p.top_level && !function) vars = globals_named_on(p.next_line, *p.next_text);
    }
    if (!function && vars.empty()) {
      ctx_.diagnostics.push_back({ctx_.config.file_name, p.line, p.column, Severity::Warning,
                                  spelled + " is not followed by a declaration; it has no effect"});
      return;
    }
    if (p.mode == Mode::Exact && !function) {
      error_at(p.line, p.column, kExactFunctionsOnly);
      return;
    }
    if (p.mode == Mode::Exact && !exact_allowed(p.line, p.column)) return;
    if (p.mode == Mode::Native || p.mode == Mode::RteExact) {
      error_at(p.line, p.column, "mode " + std::string(to_string(p.mode)) + " applies to the whole shader only (--mode " +
                                     std::string(to_string(p.mode)) + "), not to one declaration");
      return;
    }
    if (p.mode == Mode::Df64Int) {
      error_at(p.line, p.column, kDf64IntWholeShader);
      return;
    }
    if (function) {
      // Every overload defined on that line (there is one).
      function_modes_[function] = p.mode;
    }
    for (ir::Var* v : vars) var_modes_[v] = p.mode;
  }

  void apply_name(const std::string& name, Mode mode) {
    if (mode == Mode::Exact) {
      const bool function = std::any_of(module_.functions.begin(), module_.functions.end(),
                                        [&](const ir::FunctionPtr& f) { return f->name == name; });
      if (!function) {
        error_at(0, 0, "--mode-for " + name + "=exact: " + kExactFunctionsOnly);
        return;
      }
      if (!exact_allowed(0, 0)) return;
    }
    if (mode == Mode::Native || mode == Mode::RteExact) {
      const std::string m(to_string(mode));
      error_at(0, 0, "--mode-for " + name + "=" + m + ": mode " + m + " applies to the whole shader only (--mode " + m + ")");
      return;
    }
    if (mode == Mode::Df64Int) {
      error_at(0, 0, "--mode-for " + name + "=df64-int: " + kDf64IntWholeShader);
      return;
    }
    bool found = false;
    size_t dot = name.find('.');
    if (dot == std::string::npos) {
      for (const auto& g : module_.globals)
        if (g->name == name && !g->block) var_modes_[g.get()] = mode, found = true;
      for (const auto& f : module_.functions)
        if (f->name == name) function_modes_[f.get()] = mode, found = true;
    } else {
      std::string function = name.substr(0, dot), local = name.substr(dot + 1);
      for (const auto& f : module_.functions) {
        if (f->name != function) continue;
        for (const auto& p : f->params)
          if (p->name == local) var_modes_[p.get()] = mode, found = true;
        for (ir::Var* v : locals_[f.get()])
          if (v->name == local) var_modes_[v] = mode, found = true;
      }
    }
    if (!found)
      error_at(0, 0, "--mode-for " + name + "=" + std::string(to_string(mode)) + ": the shader declares no " +
                         (dot == std::string::npos ? "global variable or function '" + name + "'"
                                                   : "parameter or local variable '" + name + "'"));
  }

  // Per function, exact needs a float-float shader around it (the conversions at its calls are
  // between float-float and binary64 words).
  bool exact_allowed(int line, int column) {
    const Mode m = ctx_.config.requested_mode;
    if (m == Mode::Df64 || m == Mode::Df64Fast || m == Mode::Df64Int) return true;
    error_at(line, column, "mode exact for one function needs the shader in a float-float mode (df64, df64-fast or "
                           "df64-int), not --mode " + std::string(to_string(m)));
    return false;
  }

  void error_at(int line, int column, const std::string& message) {
    ctx_.diagnostics.push_back({ctx_.config.file_name, line, column, Severity::Error, message});
    ctx_.failed = true;
  }

  Mode function_mode(const ir::Function* f) const {
    auto it = function_modes_.find(f);
    return it == function_modes_.end() ? global_ : it->second;
  }

  // A local or parameter follows its function unless named itself; a global the global mode.
  Mode storage_mode(const ir::Var* v) const {
    if (auto it = var_modes_.find(v); it != var_modes_.end()) return it->second;
    if (auto it = owner_.find(v); it != owner_.end()) return function_mode(it->second);
    return global_;
  }

  bool any_float_mode() const {
    auto is_float = [](Mode m) { return m == Mode::Fp32 || m == Mode::Rte; };
    if (is_float(global_)) return true;
    for (const auto& [v, m] : var_modes_)
      if (is_float(m)) return true;
    for (const auto& [f, m] : function_modes_)
      if (is_float(m)) return true;
    return false;
  }

  // Struct members and block members keep the struct's/block's storage (one type, shared by
  // every variable of it), so only variables of a double scalar/vector/matrix type (or arrays
  // of them) are demoted.
  void demote_if_fp32(ir::Var& v) {
    if (v.block || v.type.base != Base::Double || storage_mode(&v) != Mode::Fp32) return;
    v.type = v.type.with_base(Base::Float);
  }

  // f(double) demoted to f(float) next to an existing f(float): two bodies for one signature.
  void check_overloads() {
    const auto& fs = module_.functions;
    std::unordered_map<std::string_view, std::vector<size_t>> by_name;  // overloads only: not all pairs
    for (size_t i = 0; i < fs.size(); ++i) {
      std::vector<size_t>& earlier = by_name[fs[i]->name];
      for (size_t j : earlier) {
        if (fs[i]->params.size() != fs[j]->params.size()) continue;
        bool same = true;
        for (size_t k = 0; k < fs[i]->params.size(); ++k)
          same &= same_shape(fs[i]->params[k]->type, fs[j]->params[k]->type);
        if (same)
          ctx_.error(fs[i]->loc, "with its mode, this overload of '" + fs[i]->name + "' has the same parameter "
                                 "types as the one on line " + std::to_string(fs[j]->loc.line) +
                                 " (fp32 stores doubles as floats); give one of them a float-float mode");
      }
      earlier.push_back(i);
    }
  }

  // ---- conversions ------------------------------------------------------------------------
  ExprPtr convert(const ExprPtr& e, Base base) {
    if (!is_real(e->type) || e->type.base == base) return e;
    if (e->kind == Kind::Const) {
      auto c = std::make_shared<Expr>(*e);
      c->type = e->type.with_base(base);
      for (auto& v : c->values) {
        v.base = base;
        if (base != Base::Float) continue;
        float f = static_cast<float>(v.d);
        if (std::isinf(f) && !std::isinf(v.d)) {
          char text[32];
          std::snprintf(text, sizeof text, "%.17g", v.d);
          ctx_.error(e->loc, std::string("the double constant ") + text +
                                 " is outside float range (|x| > 3.4e38): in float arithmetic (mode fp32 or rte) "
                                 "it would become infinity");
        }
        v.d = f;
      }
      return c;
    }
    if (e->type.is_array()) {
      if (e->kind == Kind::Construct) {
        for (auto& a : e->args) a = convert(a, base);
        e->type = e->type.with_base(base);
        return e;
      }
      ctx_.error(e->loc, "an array of " + ir::type_name(e->type) + " meets an array of " +
                             ir::type_name(e->type.with_base(base)) + " of another precision mode; arrays are not "
                             "converted as a whole: copy them element by element, or give both the same mode");
      return e;
    }
    auto c = Expr::make(Kind::Construct, e->type.with_base(base), e->loc);
    c->args = {e};
    return c;
  }

  ExprPtr convert_to(const ExprPtr& e, const ir::Type& destination) {
    if (!is_real(destination)) return e;
    return convert(e, destination.base);
  }

  // ---- expressions (post-order; types of children are their original ones until fixed) ----
  ExprPtr fix(const ExprPtr& e) {
    if (!e) return e;
    const ir::Type original = e->type;
    bool double_operand = false;
    for (const auto& a : e->args) double_operand |= a->type.base == Base::Double;
    const bool involves_double = original.base == Base::Double || double_operand;
    switch (e->kind) {
      case Kind::Sym:
        e->type = e->var->type;
        return e;
      case Kind::Const: return e;  // converted by whoever consumes it
      case Kind::Unary:
        e->args[0] = fix(e->args[0]);
        if (e->op == "-" && original.base == Base::Double) {
          if (arithmetic_ == Mode::Fp32) e->args[0] = convert(e->args[0], Base::Float);
          e->type = original.with_base(e->args[0]->type.base);  // negation is exact in either precision
        } else if (is_real(original)) {
          e->type = e->args[0]->type;  // ++x, x--: the variable's own precision
        }
        return e;
      case Kind::Binary: return fix_binary(e, original, involves_double);
      case Kind::Ternary: {
        for (auto& a : e->args) a = fix(a);
        if (is_real(original)) {
          if (e->args[1]->type.base != e->args[2]->type.base) {
            Base b = arithmetic_base(arithmetic_);
            e->args[1] = convert(e->args[1], b);
            e->args[2] = convert(e->args[2], b);
          }
          e->type = e->args[1]->type;
        }
        return e;
      }
      case Kind::Call: return fix_call(e);
      case Kind::Builtin: return fix_builtin(e, original, involves_double);
      case Kind::Construct: return fix_construct(e, original);
      case Kind::Member:
      case Kind::Index:
        for (auto& a : e->args) a = fix(a);
        if (is_real(e->args[0]->type) && is_real(original)) e->type = original.with_base(e->args[0]->type.base);
        return e;
      case Kind::Comma:
        for (auto& a : e->args) a = fix(a);
        if (!e->args.empty()) e->type = e->args.back()->type;
        return e;
    }
    return e;
  }

  ExprPtr fix_binary(const ExprPtr& e, const ir::Type& original, bool involves_double) {
    const std::string op = e->op;
    e->args[0] = fix(e->args[0]);
    e->args[1] = fix(e->args[1]);
    ExprPtr& a = e->args[0];
    ExprPtr& b = e->args[1];
    if (op == "=") {
      b = convert_to(b, a->type);  // widening (lo = 0) into hi/lo, or the one demotion to float
      e->type = a->type;
      return e;
    }
    if (!involves_double) return e;
    const Base arithmetic = arithmetic_base(arithmetic_);
    if (ir::is_compound_arithmetic(op)) {
      if (a->type.base == arithmetic || !is_real(a->type)) {
        b = convert(b, arithmetic);
        e->type = a->type;
        return e;
      }
      if (!is_pure(a)) {  // x is evaluated once: compute in x's own precision
        b = convert(b, a->type.base);
        e->type = a->type;
        return e;
      }
      // x op= y  →  x = T(x op y), the operation in the function's arithmetic.
      auto value = Expr::make(Kind::Binary, a->type.with_base(arithmetic), e->loc);
      value->op = op.substr(0, 1);
      value->args = {convert(clone(a), arithmetic), convert(b, arithmetic)};
      e->op = "=";
      b = convert(value, a->type.base);
      e->type = a->type;
      return e;
    }
    if (is_arithmetic(op)) {
      // rte: the difference of two double (hi/lo) values is the exact float-float df_sub, rounded
      // to float once (relative-to-eye); every other operation is float.
      const bool exact_difference = arithmetic_ == Mode::Rte && op == "-" && a->type.base == Base::Double &&
                                    b->type.base == Base::Double;
      const Base base = exact_difference ? Base::Double : arithmetic;
      a = convert(a, base);
      b = convert(b, base);
      e->type = original.with_base(base);
      return exact_difference ? convert(e, Base::Float) : e;
    }
    if (is_comparison(op) && is_real(a->type) && is_real(b->type) && a->type.base != b->type.base) {
      Base base = arithmetic;
      a = convert(a, base);
      b = convert(b, base);
    } else if (is_comparison(op) && arithmetic == Base::Float && is_real(a->type)) {
      a = convert(a, Base::Float);
      b = convert(b, Base::Float);
    }
    return e;
  }

  const ir::Function* callee(const std::string& name, const std::vector<ir::Type>& arg_types) const {
    const ir::Function* fallback = nullptr;
    for (const auto& f : module_.functions) {
      if (f->name != name || f->params.size() != arg_types.size()) continue;
      if (!fallback) fallback = f.get();
      bool exact = true;
      for (size_t i = 0; i < arg_types.size(); ++i) {
        const ir::Type& p = f->params[i]->declared_type;
        const ir::Type& a = arg_types[i];
        exact &= p.base == a.base && p.vec == a.vec && p.cols == a.cols && p.array_dims == a.array_dims;
      }
      if (exact) return f.get();
    }
    return fallback;
  }

  ExprPtr fix_call(const ExprPtr& e) {
    std::vector<ir::Type> arg_types;
    for (const auto& a : e->args) arg_types.push_back(a->type);
    for (auto& a : e->args) a = fix(a);
    const ir::Function* f = callee(e->name, arg_types);
    if (!f) return e;
    for (size_t i = 0; i < e->args.size(); ++i) {
      const ir::Var& p = *f->params[i];
      bool writes = ir::is_out_parameter(p.storage);
      if (!writes) {
        e->args[i] = convert_to(e->args[i], p.type);
      } else if (is_real(p.type) && e->args[i]->type.base != p.type.base) {
        ctx_.error(e->args[i]->loc, "argument " + std::to_string(i + 1) + " of '" + f->name + "' is an out/inout " +
                                        ir::type_name(p.type) + " parameter but the variable passed is stored as " +
                                        ir::type_name(e->args[i]->type) + " (another precision mode); pass a "
                                        "temporary of the parameter's mode");
      }
    }
    e->type = f->return_type;
    return e;
  }

  // Float built-ins the target lacks (GLSL ES 1.00 has no trunc, transpose, ...; frexp and ldexp
  // need ES 3.10 or desktop 4.00). There float code calls the float-float rule instead.
  bool has_float_builtin(const std::string& name) const {
    static const std::set<std::string> missing_es100{"trunc", "round", "roundEven", "modf", "isnan", "isinf",
                                                     "transpose", "determinant", "inverse", "outerProduct",
                                                     "frexp", "ldexp"};
    const Target t = ctx_.config.target;
    if (t == Target::Es100) return !missing_es100.count(name);
    if (!ctx_.config.facts->frexp_ldexp) return name != "frexp" && name != "ldexp";
    return true;
  }

  ExprPtr fix_builtin(const ExprPtr& e, const ir::Type& original, bool involves_double) {
    for (auto& a : e->args) a = fix(a);
    if (!involves_double) return e;
    const std::string& n = e->name;
    if (n == "packDouble2x32" || n.rfind("atomic", 0) == 0) return e;  // a double result; consumers convert
    if (n == "unpackDouble2x32") {
      e->args[0] = convert(e->args[0], Base::Double);
      return e;
    }
    Base base = arithmetic_base(arithmetic_);
    const bool bool_mix = n == "mix" && e->args.size() == 3 && e->args[2]->type.base == Base::Bool;
    if (base == Base::Float && (!has_float_builtin(n) || (bool_mix && ctx_.config.target == Target::Es100)))
      base = Base::Double;  // the float-float rule, its result rounded where it is used
    size_t out_argument = e->args.size();
    if (n == "modf" && e->args.size() == 2) {  // modf(x, out i): computed in i's precision
      out_argument = 1;
      base = e->args[1]->type.base;
      if (base == Base::Float && !has_float_builtin(n)) {
        ctx_.error(e->loc, "modf has no float version on " + ctx_.config.target_name() +
                               ": give its out argument a float-float mode (rte, df64-fast or df64)");
        return e;
      }
    }
    for (size_t i = 0; i < e->args.size(); ++i)
      if (i != out_argument) e->args[i] = convert(e->args[i], base);
    if (original.base == Base::Double) e->type = original.with_base(base);
    if (n == "fma" && base == Base::Float && e->args.size() == 3) {
      // Float fma needs ES 3.20 or gpu_shader5; a float product and sum is what fp32 promises.
      auto product = Expr::make(Kind::Binary, e->type, e->loc);
      product->op = "*";
      product->args = {e->args[0], e->args[1]};
      auto sum = Expr::make(Kind::Binary, e->type, e->loc);
      sum->op = "+";
      sum->args = {product, e->args[2]};
      return sum;
    }
    return e;
  }

  ExprPtr fix_construct(const ExprPtr& e, const ir::Type& original) {
    for (auto& a : e->args) a = fix(a);
    if (original.base == Base::Struct && original.fields && !original.is_array()) {
      const auto& fields = *original.fields;
      if (fields.size() == e->args.size())
        for (size_t i = 0; i < fields.size(); ++i) e->args[i] = convert_to(e->args[i], fields[i].type);
      return e;
    }
    const bool float_arithmetic = arithmetic_ == Mode::Fp32 || arithmetic_ == Mode::Rte;
    if (original.base == Base::Double) {
      // Building a double value is data movement: fp32 builds it in float; rte, df64-fast and
      // df64 keep hi/lo (a float argument is widened with lo = 0).
      Base base = arithmetic_ == Mode::Fp32 ? Base::Float : Base::Double;
      for (auto& a : e->args) a = convert(a, base);
      e->type = original.with_base(base);
    }
    // float(x) of an x that is float already (fp32/rte code): drop the no-op constructor.
    if (float_arithmetic && e->args.size() == 1 && !original.is_array() && same_shape(e->args[0]->type, e->type))
      return e->args[0];
    return e;
  }

  void fix_statement(const ir::StmtPtr& s) {
    if (!s) return;
    if (s->expr) {
      s->expr = fix(s->expr);
      if (s->kind == ir::Stmt::Kind::Decl) s->expr = convert_to(s->expr, s->var->type);
      if (s->kind == ir::Stmt::Kind::Return) s->expr = convert_to(s->expr, current_->return_type);
    }
    if (s->step) s->step = fix(s->step);
    for (const auto& b : s->body) fix_statement(b);
  }

  ir::Module& module_;
  Context& ctx_;
  const Mode global_;
  Mode arithmetic_ = Mode::Df64;
  const ir::Function* current_ = nullptr;
  std::vector<Declaration> declarations_;
  std::map<int, std::vector<ir::Var*>> globals_on_line_;  // globals_named_on()
  std::map<const ir::Var*, ir::Function*> owner_;
  std::map<const ir::Function*, std::vector<ir::Var*>> locals_;
  std::map<const ir::Var*, Mode> var_modes_;
  std::map<const ir::Function*, Mode> function_modes_;
};

}  // namespace

bool apply_modes(ir::Module& module, Context& context, const std::vector<frontend::ModePragma>& pragmas) {
  ModeApplier applier(module, context);
  if (!applier.resolve(pragmas)) return false;
  applier.run();
  return !context.failed;
}

}  // namespace doublet::passes
