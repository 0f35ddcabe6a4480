// lower_doubles: rewrites every double-typed value and operation into the
// float-float runtime (rules/*.glsl). A double literal is split exactly into
// hi = float(x), lo = float(x - hi) at compile time.
#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <set>

#include "doublet/split.hpp"
#include "frontend/text_scan.hpp"
#include "ir/walk.hpp"
#include "lower/block_layout.hpp"
#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"
#include "lower/matrix_helpers_exact.hpp"

namespace doublet::passes {

void Context::error(ir::Loc loc, const std::string& message) {
  diagnostics.push_back({ir::file_of(loc, config.file_name), loc.line, loc.column, Severity::Error, message});
  failed = true;
}
void Context::warning(ir::Loc loc, const std::string& message) {
  diagnostics.push_back({ir::file_of(loc, config.file_name), loc.line, loc.column, Severity::Warning, message});
}
void Context::use_rule(const std::string& name, int width) {
  rules::RuleRef ref{name, width};
  if (std::find(rules_used.begin(), rules_used.end(), ref) == rules_used.end()) rules_used.push_back(ref);
  use_width(width);
}
void Context::use_width(int width) {
  if (std::find(widths_used.begin(), widths_used.end(), width) == widths_used.end()) widths_used.push_back(width);
}
void Context::use_matrix(int cols, int rows) {
  std::pair<int, int> shape{cols, rows};
  if (std::find(matrices_used.begin(), matrices_used.end(), shape) == matrices_used.end()) matrices_used.push_back(shape);
}
void Context::add_helper(const std::string& name, const std::string& definition) {
  add_helper(name, definition, nullptr, "");
}
void Context::add_helper(const std::string& name, const std::string& head, const ir::ExprPtr& expression,
                         const std::string& tail) {
  if (helpers.count(name)) return;
  helpers[name] = Helper{head, expression, tail};
  helper_order.push_back(name);
}

bool Context::runtime_call_writes_arguments(const ir::Expr& call) const {
  const std::vector<ir::Storage> params = runtime_parameters(call);
  return std::any_of(params.begin(), params.end(), ir::is_out_parameter);
}

std::vector<ir::Storage> Context::runtime_parameters(const ir::Expr& call) const {
  auto storage = [](std::string_view qualifier) {
    return qualifier == "out" ? ir::Storage::ParamOut : qualifier == "inout" ? ir::Storage::ParamInOut : ir::Storage::ParamIn;
  };
  std::vector<ir::Storage> params;
  auto h = helpers.find(call.name);
  if (h == helpers.end()) {
    for (const auto& q : rules::RuleLibrary::builtin().parameter_qualifiers(call.name)) params.push_back(storage(q));
    return params;
  }
  // The head's parameter list: "T NAME(inout df_dvec3 v, int i, df_double x) {..."
  const std::string& head = h->second.head;
  const size_t open = head.find(call.name + "(");
  if (open == std::string::npos) return params;
  const size_t from = open + call.name.size() + 1, close = head.find(')', from);
  std::string_view list(head.data() + from, close - from);
  while (!list.empty()) {
    const size_t comma = list.find(',');
    std::string_view param = list.substr(0, comma);
    while (!param.empty() && param.front() == ' ') param.remove_prefix(1);
    params.push_back(storage(param.substr(0, param.find(' '))));
    list = comma == std::string_view::npos ? std::string_view() : list.substr(comma + 1);
  }
  return params;
}

bool is_runtime_call(const ir::Expr& e) {
  return e.kind == ir::Expr::Kind::Call && (e.name.rfind("df_", 0) == 0 || e.name.rfind("ex_", 0) == 0);
}

void rewrite_functions_with_temporaries(ir::Module& module, std::vector<ir::StmtPtr>& declarations,
                                        const std::function<void(const ir::StmtPtr& body)>& rewrite) {
  for (const auto& f : module.functions) {
    declarations.clear();
    rewrite(f->body);
    auto& body = f->body->body;
    body.insert(body.begin(), declarations.begin(), declarations.end());
  }
}

bool has_leading_expression(const ir::StmtPtr& s) {
  if (!s || !s->expr) return false;
  const auto k = s->kind;
  return k == ir::Stmt::Kind::Expr || k == ir::Stmt::Kind::Decl || k == ir::Stmt::Kind::Return ||
         k == ir::Stmt::Kind::If || k == ir::Stmt::Kind::Switch;
}

ir::VarPtr declare_temporary(const std::string& name, const ir::Type& type, ir::Loc loc,
                             std::vector<ir::StmtPtr>& declarations) {
  auto tmp = std::make_shared<ir::Var>();
  tmp->name = name;
  tmp->type = type;
  tmp->declared_type = type;
  tmp->storage = ir::Storage::Local;
  tmp->loc = loc;
  auto decl = ir::Stmt::make(ir::Stmt::Kind::Decl, loc);
  decl->var = tmp;
  declarations.push_back(decl);
  return tmp;
}

std::string df_type_name(int width) { return width == 1 ? "df_double" : "df_dvec" + std::to_string(width); }

ir::Type df_type(int width) {
  ir::Type t;
  t.base = ir::Base::Struct;
  t.name = df_type_name(width);
  return t;
}

bool is_df(const ir::Type& t) {
  return t.base == ir::Base::Struct && !t.is_array() && (t.name == "df_double" || t.name.rfind("df_dvec", 0) == 0);
}

int df_width(const ir::Type& t) {
  if (t.name == "df_double") return 1;
  if (!t.name.empty() && t.name.back() >= '2' && t.name.back() <= '4') return t.name.back() - '0';
  return t.vec;  // not a float-float struct (an unnamed type's name has no last character to read)
}

ir::ExprPtr df_splat(Context& context, const ir::ExprPtr& scalar, int width) {
  if (width == 1) return scalar;
  const std::string name = "df_splat_" + df_type_name(width).substr(3);
  const std::string word = (context.config.binary64_words() ? "uvec" : "vec") + std::to_string(width);
  context.add_helper(name, df_type_name(width) + " " + name + "(df_double s) {\n  return " + df_type_name(width) + "(" +
                               word + "(s.hi), " + word + "(s.lo));\n}\n");
  return ir::make_node(ir::Expr::Kind::Call, name, df_type(width), {scalar}, scalar->loc);
}

ir::ExprPtr df_select_pure(const Context& context, const ir::ExprPtr& base, const std::string& letters, ir::Loc loc) {
  const int width = static_cast<int>(letters.size()), source = df_width(base->type);
  const ir::Base word = context.config.binary64_words() ? ir::Base::Uint : ir::Base::Float;
  const auto part = [&](const char* half) {
    auto words = ir::make_node(ir::Expr::Kind::Member, half, ir::scalar_type(word, source), {base}, base->loc);
    return ir::make_node(ir::Expr::Kind::Member, letters, ir::scalar_type(word, width), {words}, base->loc);
  };
  return ir::make_node(ir::Expr::Kind::Construct, "", df_type(width), {part("hi"), part("lo")}, loc);
}

namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

std::string float_type_name(int width) { return width == 1 ? "float" : "vec" + std::to_string(width); }
std::string uint_type_name(int width) { return width == 1 ? "uint" : "uvec" + std::to_string(width); }

using ir::is_pure;

ExprPtr member(const ExprPtr& base, const std::string& name, ir::Type type) {
  auto e = Expr::make(Kind::Member, std::move(type), base->loc);
  e->name = name;
  e->args = {base};
  return e;
}

ExprPtr float_const(float v, ir::Loc loc) {
  auto e = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Float), loc);
  ir::Scalar s;
  s.base = ir::Base::Float;
  s.d = v;
  e->values = {s};
  return e;
}

class DoubleLowering {
 public:
  DoubleLowering(ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  void run() {
    for (auto& t : module_.structs)
      for (auto& f : *t.fields) f.type = lower_type(f.type, {});
    fast_ = ctx_.fast_global_inits;
    for (size_t i = 0; i < module_.globals.size(); ++i) {
      auto& g = module_.globals[i];
      if (exact() && is_interface(g->storage) && holds_double_matrix(g->type) && !exact_matrix_interface(*g)) continue;
      if (g->type.base == ir::Base::Block && holds_doubles(g->type)) lower_block(*g);
      lower_var(*g);
      if (module_.global_inits[i]) module_.global_inits[i] = lower(module_.global_inits[i]);
    }
    for (auto& f : module_.functions) {
      fast_ = ctx_.fast_functions.count(f.get()) > 0;
      f->return_type = lower_type(f->return_type, f->loc);
      for (auto& p : f->params) lower_var(*p);
      lower_statement(f->body);
    }
  }

 private:
  // ---- representation --------------------------------------------------------
  // Mode exact keeps the df_* structs and their hi/lo members, but the members are uint words of
  // the binary64 bit pattern and every rule df_X is rules/exact.glsl's ex_X: the lowering itself
  // (swizzles, components, splats, interfaces) is the same for both representations.
  bool exact() const { return ctx_.config.binary64_words(); }
  bool rte_exact() const { return ctx_.config.mode == Mode::RteExact; }
  std::string runtime_name(const std::string& name) const {
    return exact() && name.rfind("df_", 0) == 0 ? "ex_" + name.substr(3) : name;
  }
  std::string word_type_name(int width) const { return exact() ? uint_type_name(width) : float_type_name(width); }

  static bool is_interface(ir::Storage s) {
    return s == ir::Storage::In || s == ir::Storage::Out || s == ir::Storage::Uniform || s == ir::Storage::Buffer;
  }
  // A dmat, or a struct holding one (whose fields may already be lowered to df_dmat* by run()).
  static bool holds_double_matrix(const ir::Type& t) {
    if ((t.base == ir::Base::Double && t.is_matrix()) || matrix::is_matrix(t)) return true;
    if (t.fields)
      for (const auto& f : *t.fields)
        if (holds_double_matrix(f.type)) return true;
    return false;
  }

  // Mode exact carries a double matrix across the interface as a loose uniform (uvec4 words) or as
  // a column-major member of a uniform/storage block (split_interfaces.cpp, exact_blocks.cpp);
  // everything else is diagnosed here. False when `g` was diagnosed.
  bool exact_matrix_interface(const ir::Var& g) {
    auto refuse = [&](const std::string& what, const std::string& why) {
      ctx_.error(g.loc, "a double matrix in an interface ('" + what + "') " + why);
      return false;
    };
    if (g.type.base == ir::Base::Block && g.type.fields) {
      if (g.storage != ir::Storage::Uniform && g.storage != ir::Storage::Buffer) {
        for (const auto& f : *g.type.fields)
          if (holds_double_matrix(f.type))
            return refuse(f.name, "is supported by --mode exact only in uniform and storage blocks and as a loose "
                                  "uniform: pass its columns as dvecN members and build the matrix in the shader");
        return true;
      }
      // Members and the members of struct members (exact_blocks.cpp: a struct's twin holds its
      // matrices' column words as a block does).
      // `row_major`: the layout the enclosing block or struct member gives.
      std::function<bool(const std::vector<ir::Field>&, bool)> check = [&](const std::vector<ir::Field>& fields,
                                                                          bool row_major) {
        for (const auto& f : fields) {
          if (!holds_double_matrix(f.type)) continue;
          const bool row = f.layout.matrix == "row_major" || (f.layout.matrix.empty() && row_major);
          if (f.type.base == ir::Base::Struct && f.type.fields) {
            if (f.type.array_dims.size() > 1)
              return refuse(f.name, "in a multi-dimensional array of structs is not supported by --mode exact");
            if (!check(*f.type.fields, row)) return false;
            continue;
          }
          if (row)
            return refuse(f.name, "with layout(row_major) is not supported by --mode exact: declare it column_major "
                                  "(the default) and transpose the host's data");
          if (f.type.array_dims.size() > 1)
            return refuse(f.name, "in a multi-dimensional array is not supported by --mode exact");
        }
        return true;
      };
      return check(*g.type.fields, g.layout.matrix == "row_major");
    }
    if (g.storage == ir::Storage::Uniform && g.type.base == ir::Base::Double) {
      if (g.type.array_dims.size() > 1 || (g.type.is_array() && g.type.array_dims[0] <= 0))
        return refuse(g.name, "in a multi-dimensional or unsized uniform array is not supported by --mode exact");
      return true;
    }
    if (g.storage == ir::Storage::Uniform)
      return refuse(g.name, "inside a struct uniform is not supported by --mode exact yet: declare the matrix as a "
                            "uniform of its own");
    return refuse(g.name, std::string("as a") + (g.storage == ir::Storage::In ? "n input" : "n output") +
                              " is not supported by --mode exact: pass its columns as dvecN " +
                              (g.storage == ir::Storage::In ? "inputs" : "outputs") +
                              " (one location each) and build the matrix with dmatN(c0, c1, ...)");
  }

  // ---- types ---------------------------------------------------------------
  ir::Type lower_type(const ir::Type& t, ir::Loc loc) {
    if (t.base != ir::Base::Double) return t;
    if (t.is_matrix()) {
      if (t.cols != t.vec && ctx_.config.target == Target::Es100 && reported_.insert(ir::type_name(t)).second)
        ctx_.error(loc, ir::type_name(t) + " is not available on es100: GLSL ES 1.00 has only square matrices; use "
                        "dmat" + std::to_string(std::max(t.cols, t.vec)) + " or target es300 or later");
      ir::Type out = matrix::type(t.cols, t.vec);
      out.array_dims = t.array_dims;
      ctx_.use_matrix(t.cols, t.vec);
      ctx_.use_width(t.vec);
      return out;
    }
    ir::Type out = df_type(t.vec);
    out.array_dims = t.array_dims;
    ctx_.use_width(t.vec);
    return out;
  }

  void lower_var(ir::Var& v) { v.type = lower_type(v.type, v.loc); }

  // A block's double members become df_* struct members in place (hi and lo side by side); their
  // offsets change, so explicit member offsets are dropped, an explicit std140/std430 packing is
  // emitted for uniform and storage blocks (shared/packed layouts could not be described; in/out
  // blocks take no packing), and split_interfaces reports the new layout in the manifest.
  void lower_block(ir::Var& block) {
    // A copy: declared_type keeps the user's members for the manifest.
    block.type.fields = std::make_shared<std::vector<ir::Field>>(*block.type.fields);
    const bool memory_block = block.storage == ir::Storage::Uniform || block.storage == ir::Storage::Buffer;
    if (memory_block && block.layout.packing != "std140" && block.layout.packing != "std430")
      block.layout.packing = block.storage == ir::Storage::Buffer ? "std430" : "std140";
    for (auto& f : *block.type.fields) {
      f.type = lower_type(f.type, block.loc);
      f.layout.offset = -1;
    }
  }

  // In source order: a for-loop's init declares the variable its condition and step read, so it
  // is lowered first (otherwise the condition would still see the variable as a double).
  void lower_statement(const ir::StmtPtr& s) {
    if (!s) return;
    const bool for_loop = s->kind == ir::Stmt::Kind::Loop && s->test_first;
    if (for_loop) lower_statement(s->body[0]);
    if (s->kind == ir::Stmt::Kind::Decl) lower_var(*s->var);
    if (s->expr) s->expr = lower(s->expr);
    if (s->step) s->step = lower(s->step);
    for (size_t i = for_loop ? 1 : 0; i < s->body.size(); ++i) lower_statement(s->body[i]);
  }

  // ---- helpers ---------------------------------------------------------------
  ExprPtr rule(const std::string& df_name, int width, ir::Type type, std::vector<ExprPtr> args, ir::Loc loc) {
    const std::string name = runtime_name(df_name);
    if (width < 1 || width > 4)  // an operand that was never lowered; said here, where the position is known
      ctx_.error(loc, "doublet could not lower the operands of this double operation (" + name +
                          "); please report this with the input");
    ctx_.use_rule(name, width);
    ctx_.rule_first_use.emplace(name, loc);
    return ir::make_node(Kind::Call, name, std::move(type), std::move(args), loc);
  }

  ExprPtr splat(const ExprPtr& scalar, int width) { return df_splat(ctx_, scalar, width); }

  // Component selection (swizzle letters) of a df vector, as a new df value.
  ExprPtr select(const ExprPtr& base, const std::string& letters, ir::Loc loc) {
    int width = static_cast<int>(letters.size());
    int src = df_width(base->type);
    if (is_pure(base)) return df_select_pure(ctx_, base, letters, loc);
    std::string name = "df_swizzle_" + df_type_name(src).substr(3) + "_" + letters;
    ctx_.add_helper(name, df_type_name(width) + " " + name + "(" + df_type_name(src) + " v) {\n  return " +
                              df_type_name(width) + "(v.hi." + letters + ", v.lo." + letters + ");\n}\n");
    return ir::make_node(Kind::Call, name, df_type(width), {base}, loc);
  }

  // Converts any scalar/vector value to the df type of the same width.
  ExprPtr to_df(const ExprPtr& e) {
    if (is_df(e->type)) return e;
    int width = e->type.vec;
    const char* rule_name = nullptr;
    switch (e->type.base) {
      case ir::Base::Float: rule_name = "df_from_float"; break;
      case ir::Base::Int: rule_name = "df_from_int"; break;
      case ir::Base::Uint: rule_name = "df_from_uint"; break;
      case ir::Base::Bool: rule_name = "df_from_bool"; break;
      case ir::Base::Int64:
      case ir::Base::Uint64: return int64_conversion(e, e->type.base, true);
      default:
        ctx_.error(e->loc, "cannot convert " + ir::type_name(e->type) + " to a double type");
        return e;
    }
    return rule(rule_name, width, df_type(width), {e}, e->loc);
  }

  // Conversions between 64-bit integers (GL_ARB_gpu_shader_int64, desktop 4.x) and doubles, as
  // generated helpers (the rule files are written for every target, which int64_t is not):
  //   float-float: double(i) is (hi, lo) = (float(i), float(i - int64_t(hi))), the difference exact
  //     in 64-bit integer arithmetic (int64_t(hi) rebuilt from hi's bits); the pair is within 2^-48
  //     of i, as any double rounded to df.
  //     int64_t(x) is int64_t(t.hi) + int64_t(t.lo) of t = trunc(x), both parts integers.
  //   exact: the integer's magnitude rounded once to binary64 (ex_norm_round_pack, as double(uint)
  //     does); the conversion back truncates the magnitude (ex_trunc_magnitude, |x| < 2^64).
  ExprPtr int64_conversion(const ExprPtr& e, ir::Base integer, bool to_double) {
    const int width = to_double ? e->type.vec : df_width(e->type);
    const bool is_signed = integer == ir::Base::Int64;
    const std::string scalar = is_signed ? "int64_t" : "uint64_t", df = df_type_name(width);
    const std::string one = std::string(to_double ? "df_from_" : "df_to_") + (is_signed ? "int64" : "uint64");
    if (exact()) {
      ctx_.use_rule(to_double ? "ex_from_uint" : "ex_to_uint", 1);  // brings ex_norm_round_pack, ex_trunc_magnitude
    } else if (!to_double) {
      ctx_.use_rule(runtime_name("df_trunc"), 1);
    }
    ctx_.use_width(1);
    ctx_.use_width(width);
    std::string body;
    if (to_double && exact()) {
      body = "df_double " + one + "(" + scalar + " i) {\n" +
             (is_signed ? "  uint64_t m = i < 0l ? 0ul - uint64_t(i) : uint64_t(i);\n" : "  uint64_t m = i;\n") +
             "  if (m == 0ul) return ex_from_bits(uvec2(0u));\n"
             "  return ex_from_bits(ex_norm_round_pack(" + (is_signed ? "i < 0l" : "false") + ", 1084, unpackUint2x32(m)));\n}\n";
    } else if (to_double) {
      // back = the integer hi is, from hi's bits: Mesa folds int64_t(float(i)) back to i (which would
      // make lo 0). Past 2^63 (2^64 unsigned) it wraps, and the wrapped difference is still right.
      body = "df_double " + one + "(" + scalar + " i) {\n  float hi = float(i);\n"
             "  uint b = floatBitsToUint(hi);\n  int e = int((b >> 23) & 0xFFu) - 150;\n"
             "  " + scalar + " m = " + scalar + "((b & 0x7FFFFFu) | 0x800000u);\n"
             "  " + scalar + " back = e >= 0 ? m << e : m >> min(-e, 63);\n" +
             (is_signed ? "  if ((b >> 31) != 0u) back = -back;\n" : "") +
             "  return df_double(hi, float(int64_t(i - back)));\n}\n";
    } else if (exact()) {
      body = scalar + " " + one + "(df_double a) {\n  uvec2 w = ex_bits(a);\n" +
             (is_signed ? "  int64_t m = int64_t(packUint2x32(ex_trunc_magnitude(w)));\n  return w.y >= 0x80000000u ? -m : m;\n"
                        : "  return packUint2x32(ex_trunc_magnitude(w));\n") + "}\n";
    } else {
      body = scalar + " " + one + "(df_double x) {\n  df_double t = df_trunc(x);\n  return " + scalar +
             (is_signed ? "(t.hi) + int64_t(t.lo);\n" : "(t.hi) + uint64_t(int64_t(t.lo));\n") + "}\n";
    }
    ctx_.add_helper(one, body);
    const ir::Type result = to_double ? df_type(width) : ir::scalar_type(integer, width);
    if (width == 1) return ir::make_node(Kind::Call, one, result, {e}, e->loc);
    const std::string name = one + "_" + std::to_string(width);
    add_int64_component_helper(name, integer, width, to_double, [&](const std::string& component) {
      return one + "(" + component + ")";
    });
    return ir::make_node(Kind::Call, name, result, {e}, e->loc);
  }

  // A helper `name` between a 64-bit integer vector and a df vector of `width`, made of a scalar
  // expression per component: `scalar_of` gets the component (`v.x`, or `df_double(v.hi.x,
  // v.lo.x)` from a df vector) and spells the scalar conversion of it.
  void add_int64_component_helper(const std::string& name, ir::Base integer, int width, bool to_double,
                                  const std::function<std::string(const std::string&)>& scalar_of) {
    static const char* kLetters = "xyzw";
    const std::string df = df_type_name(width), vec = ir::type_name(ir::scalar_type(integer, width));
    std::string text = (to_double ? df : vec) + " " + name + "(" + (to_double ? vec : df) + " v) {\n", hi, lo, parts;
    for (int k = 0; k < width; ++k) {
      const std::string c = width == 1 ? "" : std::string(".") + kLetters[k], r = "r" + std::to_string(k);
      if (to_double) {
        text += "  df_double " + r + " = " + scalar_of("v" + c) + ";\n";
        hi += (k ? ", " : "") + r + ".hi";
        lo += (k ? ", " : "") + r + ".lo";
      } else {
        parts += (k ? ", " : "") + scalar_of("df_double(v.hi" + c + ", v.lo" + c + ")");
      }
    }
    const std::string word = word_type_name(width);
    text += !to_double ? "  return " + vec + "(" + parts + ");\n}\n"
            : width == 1 ? "  return r0;\n}\n"
                         : "  return " + df + "(" + word + "(" + hi + "), " + word + "(" + lo + "));\n}\n";
    ctx_.add_helper(name, text);
  }

  // The 64-bit integer bit casts (GL_ARB_gpu_shader_int64) go through the binary64 words the
  // 2x32 packing functions already lower: int64BitsToDouble(i) = packDouble2x32(unpackUint2x32(i)),
  // doubleBitsToInt64(d) = packUint2x32(unpackDouble2x32(d)), per component, in a helper.
  ExprPtr lower_int64_bit_casts(const ExprPtr& e) {
    const std::string& n = e->name;
    const bool to_double = n == "int64BitsToDouble" || n == "uint64BitsToDouble";
    if (!to_double && n != "doubleBitsToInt64" && n != "doubleBitsToUint64") return nullptr;
    if (ctx_.config.mode == Mode::Fp32 || ctx_.config.mode == Mode::Rte) {
      ctx_.error(e->loc, n + " has no meaning when doubles are demoted to float (--mode " +
                             std::string(to_string(ctx_.config.mode)) + ")");
      return e;
    }
    const int width = to_double ? e->args[0]->type.vec : df_width(e->args[0]->type);
    const std::string pack = runtime_name("df_pack_double2x32"), unpack = runtime_name("df_unpack_double2x32");
    ctx_.use_rule(to_double ? pack : unpack, 1);
    ctx_.use_width(1);
    ctx_.use_width(width);
    const ir::Base integer = n == "int64BitsToDouble" || n == "doubleBitsToInt64" ? ir::Base::Int64 : ir::Base::Uint64;
    const std::string scalar = integer == ir::Base::Int64 ? "int64_t" : "uint64_t";
    const std::string name = "df_" + n + "_" + std::to_string(width);
    add_int64_component_helper(name, integer, width, to_double, [&](const std::string& component) {
      return to_double ? pack + "(unpackUint2x32(uint64_t(" + component + ")))"
                       : scalar + "(packUint2x32(" + unpack + "(" + component + ")))";
    });
    return ir::make_node(Kind::Call, name, to_double ? df_type(width) : ir::scalar_type(integer, width), {e->args[0]}, e->loc);
  }

  // Converts a df value to scalar/vector type `base` of the same width.
  ExprPtr from_df(const ExprPtr& e, ir::Base base) {
    int width = df_width(e->type);
    const char* rule_name = nullptr;
    switch (base) {
      case ir::Base::Float: rule_name = "df_to_float"; break;
      case ir::Base::Int: rule_name = "df_to_int"; break;
      case ir::Base::Uint: rule_name = "df_to_uint"; break;
      case ir::Base::Bool: rule_name = "df_to_bool"; break;
      case ir::Base::Int64:
      case ir::Base::Uint64: return int64_conversion(e, base, false);
      default:
        ctx_.error(e->loc, "cannot convert a double to this type");
        return e;
    }
    return rule(rule_name, width, ir::scalar_type(base, width), {e}, e->loc);
  }

  // ---- expressions ---------------------------------------------------------
  ExprPtr lower(const ExprPtr& e) {
    if (is_assignment(e) || is_step(e)) e->args[0] = compose_swizzles(e->args[0]);
    if (is_matrix_lvalue_write(e)) return lower_matrix_write(e);
    if (is_component_lvalue_write(e)) return lower_component_write(e);
    if (e->kind == Kind::Binary && ir::is_compound_arithmetic(e->op) && e->args[0]->type.is_double()) return lower_compound(e);
    if (is_step(e) && e->args[0]->type.is_double()) {
      if (e->args[0]->type.is_matrix() || (e->args[0]->kind == Kind::Index && e->args[0]->args[0]->type.is_matrix())) {
        ctx_.error(e->loc, "++/-- on a double matrix or matrix column is not supported; use += 1.0lf");
        return e;
      }
      return lower_step(e);
    }
    if (ExprPtr d = rte_exact_difference(e)) return d;
    const bool was_double = e->type.base == ir::Base::Double;
    for (auto& a : e->args) a = lower(a);
    e->type = lower_type(e->type, e->loc);
    switch (e->kind) {
      case Kind::Sym:
        if (e->var->block) lower_var(*e->var);  // a member of an anonymous block
        e->type = e->var->type;
        return e;
      case Kind::Const: return was_double ? split_constant(e) : e;
      case Kind::Unary:
        if (was_double && e->op == "-" && matrix::is_matrix(e->type))
          return ir::make_node(Kind::Call, matrix::negate(ctx_, matrix::cols(e->type), matrix::rows(e->type)), e->type, e->args,
                      e->loc);
        if (was_double && e->op == "-") return rule("df_neg", df_width(e->type), e->type, e->args, e->loc);
        return e;
      case Kind::Binary: return lower_binary(e);
      case Kind::Builtin: return lower_builtin(e);
      case Kind::Construct: return lower_construct(e, was_double);
      case Kind::Member:
        if (is_df(e->args[0]->type)) return select(e->args[0], e->name, e->loc);
        return e;
      case Kind::Index:
        if (is_df(e->args[0]->type)) return component(e->args[0], e->args[1], e->loc);
        if (matrix::is_matrix(e->args[0]->type)) return matrix_column(e->args[0], e->args[1], e->loc);
        return e;
      case Kind::Call:
        check_out_arguments(e);
        return e;
      default: return e;
    }
  }

  // rte-exact: float(a - b) of two doubles (what apply_modes makes of an rte difference) is one
  // rule, the exact difference rounded once to float (rules/rte_exact.glsl); null otherwise.
  ExprPtr rte_exact_difference(const ExprPtr& e) {
    if (!rte_exact() || e->kind != Kind::Construct || e->type.base != ir::Base::Float || e->type.is_array() ||
        e->type.is_matrix() || e->args.size() != 1)
      return nullptr;
    const ExprPtr& d = e->args[0];
    if (d->kind != Kind::Binary || d->op != "-" || d->type.vec != e->type.vec || d->type.is_matrix() ||
        !d->args[0]->type.is_double() || !d->args[1]->type.is_double() || d->args[0]->type.is_matrix() ||
        d->args[1]->type.is_matrix())
      return nullptr;
    ExprPtr a = to_df(lower(d->args[0])), b = to_df(lower(d->args[1]));
    const int width = std::max(df_width(a->type), df_width(b->type));
    if (df_width(a->type) < width) a = splat(a, width);
    if (df_width(b->type) < width) b = splat(b, width);
    return rule("df_sub_to_float", width, ir::scalar_type(ir::Base::Float, width), {a, b}, e->loc);
  }

  // Whether the numeric literal written at `loc` (in the main source) is itself finite: then an
  // infinite constant there was folded from an expression such as 1.0 / 0.0, which native fp64
  // computes as the same infinity, and (+-Inf, 0) carries it exactly.
  bool literal_at_is_finite(ir::Loc loc) {
    if (loc.file || loc.column <= 0) return false;
    if (!source_lines_) source_lines_.emplace(ctx_.source);
    const std::string_view row = source_lines_->line(loc.line);
    if (static_cast<size_t>(loc.column) > row.size()) return false;
    const std::string token(row.substr(static_cast<size_t>(loc.column - 1)));
    if (!frontend::is_digit(token[0]) && token[0] != '.') return false;
    return std::isfinite(std::strtod(token.c_str(), nullptr));
  }

  // A double constant float-float cannot hold is diagnosed, never silently Inf or 0.
  void check_range(double x, SplitStatus status, ir::Loc loc) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    if (std::isinf(x) && literal_at_is_finite(loc)) return;  // a deliberate infinity (1.0 / 0.0)
    if (std::isinf(x)) {
      ctx_.error(loc, std::string("the double constant overflows even double precision (") + text + ")");
    } else if (status == SplitStatus::Overflow) {
      ctx_.error(loc, std::string("the double constant ") + text +
                          " is outside float-float range (|x| > 3.4e38): it would become infinity");
    } else if (status == SplitStatus::Underflow) {
      std::string message = std::string("the double constant ") + text +
                            " is below float-float range (|x| < 1.2e-38): it becomes " +
                            (static_cast<float>(x) == 0.0f ? "0" : "a subnormal float with little precision left");
      if (ctx_.config.constant_range_errors) ctx_.error(loc, message);
      else ctx_.warning(loc, message);
    }
  }

  ExprPtr split_constant(const ExprPtr& e) {
    ir::Type elem_type = e->type;
    elem_type.array_dims.clear();
    const bool is_matrix = matrix::is_matrix(elem_type);
    int width = is_matrix ? matrix::cols(elem_type) * matrix::rows(elem_type) : df_width(elem_type);
    auto element = [&](size_t start) {
      ir::Scalar hi, lo;
      hi.base = lo.base = exact() ? ir::Base::Uint : ir::Base::Float;
      std::vector<ir::Scalar> his, los;
      for (int i = 0; i < width; ++i) {
        double x = e->values[start + static_cast<size_t>(i)].d;
        if (exact()) {  // the binary64 pattern's words: every double is representable
          uint64_t pattern;
          std::memcpy(&pattern, &x, sizeof pattern);
          hi.i = static_cast<long long>(pattern >> 32);
          lo.i = static_cast<long long>(pattern & 0xFFFFFFFFu);
          his.push_back(hi);
          los.push_back(lo);
          continue;
        }
        FloatPair pair;
        check_range(x, split_checked(x, pair), e->loc);
        hi.d = pair.hi;
        lo.d = pair.lo;
        his.push_back(hi);
        los.push_back(lo);
      }
      if (exact() && is_matrix) {  // no uint matrices: the columns as df_dvecR constants, joined by a helper
        const int c = matrix::cols(elem_type), r = matrix::rows(elem_type);
        std::vector<ExprPtr> columns;
        for (int j = 0; j < c; ++j) {
          auto h = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Uint, r), e->loc);
          auto l = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Uint, r), e->loc);
          h->values.assign(his.begin() + j * r, his.begin() + (j + 1) * r);
          l->values.assign(los.begin() + j * r, los.begin() + (j + 1) * r);
          columns.push_back(ir::make_node(Kind::Construct, "", df_type(r), {h, l}, e->loc));
        }
        return ir::make_node(Kind::Call, matrix::exact::from_components(ctx_, c, r, std::vector<int>(size_t(c), r)),
                             elem_type, columns, e->loc);
      }
      ir::Type word_type = is_matrix ? float_matrix(matrix::cols(elem_type), matrix::rows(elem_type))
                                     : ir::scalar_type(exact() ? ir::Base::Uint : ir::Base::Float, width);
      auto h = Expr::make(Kind::Const, word_type, e->loc);
      h->values = his;
      auto l = Expr::make(Kind::Const, word_type, e->loc);
      l->values = los;
      return ir::make_node(Kind::Construct, "", is_matrix ? elem_type : df_type(width), {h, l}, e->loc);
    };
    if (!e->type.is_array()) return element(0);
    auto arr = Expr::make(Kind::Construct, e->type, e->loc);
    for (size_t i = 0; i < e->values.size(); i += static_cast<size_t>(width)) arr->args.push_back(element(i));
    return arr;
  }

  static bool is_assignment(const ExprPtr& e) {
    return (e->kind == Kind::Binary && (e->op == "=" || ir::is_compound_arithmetic(e->op)));
  }

  static bool is_step(const ExprPtr& e) {
    return e->kind == Kind::Unary && (e->op.find("++") != std::string::npos || e->op.find("--") != std::string::npos);
  }

  // The components `e` selects from a double vector ("xz" for v.xz, "y" for v[1]); empty when
  // `e` is not a swizzle or constant index of a double vector.
  static std::string swizzle_letters(const ExprPtr& e) {
    if (e->kind != Kind::Member && e->kind != Kind::Index) return "";
    const ir::Type& base = e->args[0]->type;
    if (!base.is_double() || base.is_array() || base.is_matrix() || base.vec < 2) return "";
    if (e->kind == Kind::Member) return e->name;
    const ExprPtr& index = e->args[1];
    if (index->kind != Kind::Const || index->values.size() != 1 || index->values[0].i < 0 || index->values[0].i > 3)
      return "";
    return std::string(1, "xyzw"[index->values[0].i]);
  }

  // v.xz.y → v.z, v.zyx.xy → v.zy: an l-value that swizzles a swizzle of a double vector becomes
  // one swizzle of the vector itself, which the component writes can update in place.
  static ExprPtr compose_swizzles(const ExprPtr& lhs) {
    const std::string outer = swizzle_letters(lhs);
    if (outer.empty()) return lhs;
    ExprPtr base = compose_swizzles(lhs->args[0]);
    const std::string inner = swizzle_letters(base);
    if (inner.empty()) return lhs;
    std::string letters;
    for (char c : outer) letters += inner[std::string("xyzw").find(c)];
    auto composed = Expr::make(Kind::Member, lhs->type, lhs->loc);
    composed->name = letters;
    composed->args = {base->args[0]};
    return composed;
  }

  // `v.xz = e`, `v[i] += e`: a write to part of a double vector.
  static bool is_component_lvalue(const ExprPtr& lhs) {
    if (lhs->kind != Kind::Member && lhs->kind != Kind::Index) return false;
    const auto& base = lhs->args[0]->type;
    return base.is_double() && !base.is_array() && !base.is_matrix() && base.vec > 1;
  }
  static bool is_component_lvalue_write(const ExprPtr& e) {
    return is_assignment(e) && is_component_lvalue(e->args[0]);
  }

  ExprPtr arithmetic(const std::string& op, ExprPtr a, ExprPtr b, ir::Loc loc) {
    if (matrix::is_matrix(a->type) || matrix::is_matrix(b->type)) return matrix_arithmetic(op, a, b, loc);
    int wa = df_width(a->type), wb = df_width(b->type);
    int width = std::max(wa, wb);
    if (wa < width) a = splat(a, width);
    if (wb < width) b = splat(b, width);
    static const std::map<std::string, std::string> names{{"+", "df_add"}, {"-", "df_sub"}, {"*", "df_mul"}, {"/", "df_div"}};
    auto it = names.find(op);
    if (it == names.end()) {
      ctx_.error(loc, "operator '" + op + "' is not defined on doubles");
      return a;
    }
    return rule(fast_ ? it->second + "_fast" : it->second, width, df_type(width), {a, b}, loc);
  }

  ExprPtr lower_component_write(const ExprPtr& e) {
    ExprPtr lhs = e->args[0];
    if (!swizzle_letters(lhs->args[0]).empty()) {  // v.xz[i]: compose_swizzles took the constant indices
      ctx_.error(e->loc, "writing a swizzle of a double vector through a variable index (v.xz[i]) cannot be lowered "
                         "for " + ctx_.config.target_name() +
                         ": index the vector itself (v[i]) or use a temporary");
      return e;
    }
    if (e->op != "=" && ir::has_side_effects(lhs)) {  // the compound form reads the vector, then writes it
      ctx_.error(e->loc, "compound assignment to a component of a double vector reached through an expression with "
                         "side effects (a call, ++, an assignment) cannot be lowered for " +
                         ctx_.config.target_name() +
                         ": copy the vector to a temporary, update it and store it back");
      return e;
    }
    ExprPtr base = lower(lhs->args[0]);
    ExprPtr index = lhs->kind == Kind::Index ? lower(lhs->args[1]) : nullptr;
    ExprPtr rhs = lower(e->args[1]);
    int src = df_width(base->type);
    int width = lhs->kind == Kind::Member ? static_cast<int>(lhs->name.size()) : 1;
    if (e->op != "=") {
      ExprPtr current = index ? component(ir::clone(base), ir::clone(index), lhs->loc)
                              : select(ir::clone(base), lhs->name, lhs->loc);
      rhs = arithmetic(e->op.substr(0, 1), current, rhs, e->loc);
    }
    if (!is_df(rhs->type)) rhs = to_df(rhs);
    if (df_width(rhs->type) < width) rhs = splat(rhs, width);
    std::string src_name = df_type_name(src), dst_name = df_type_name(width);
    if (lhs->kind == Kind::Member) {
      std::string name = "df_assign_" + src_name.substr(3) + "_" + lhs->name;
      ctx_.add_helper(name, dst_name + " " + name + "(inout " + src_name + " v, " + dst_name + " x) {\n  v.hi." +
                                lhs->name + " = x.hi;\n  v.lo." + lhs->name + " = x.lo;\n  return x;\n}\n");
      return ir::make_node(Kind::Call, name, df_type(width), {base, rhs}, e->loc);
    }
    std::string name = "df_assign_component_" + src_name.substr(3);
    ctx_.add_helper(name, "df_double " + name + "(inout " + src_name +
                              " v, int i, df_double x) {\n  v.hi[i] = x.hi;\n  v.lo[i] = x.lo;\n  return x;\n}\n");
    return ir::make_node(Kind::Call, name, df_type(1), {base, int_index(index), rhs}, e->loc);
  }

  // x op= y  →  x = df_op(x, y), which reads x twice: fine unless evaluating x has side effects
  // (a[i++] += y, a[f()] += y); then x goes once, as an inout argument, to a generated helper.
  ExprPtr lower_compound(const ExprPtr& e) {
    const bool evaluate_once = ir::has_side_effects(e->args[0]);
    ExprPtr target = lower(e->args[0]);
    ExprPtr value = lower(e->args[1]);
    if (!is_df(value->type) && !matrix::is_matrix(value->type)) value = to_df(value);
    const std::string op = e->op.substr(0, 1);
    if (evaluate_once) return compound_helper_call(op, target, value, e->loc);
    return ir::make_binary("=", target->type, target, arithmetic(op, ir::clone(target), value, e->loc));
  }

  // `T df_add_assign_T_U(inout T x, U y) { x = df_add(x, y); return x; }` for the operator and
  // the lowered types of target and value; the body is the same arithmetic() call as the inline form.
  ExprPtr compound_helper_call(const std::string& op, const ExprPtr& target, const ExprPtr& value, ir::Loc loc) {
    auto parameter = [](const char* name, const ir::Type& type) {
      auto v = std::make_shared<ir::Var>();
      v->name = name;
      v->type = type;
      return ir::make_sym(v);
    };
    ExprPtr updated = arithmetic(op, parameter("x", target->type), parameter("y", value->type), loc);
    static const std::map<std::string, std::string> words{{"+", "add"}, {"-", "sub"}, {"*", "mul"}, {"/", "div"}};
    const std::string x_type = ir::type_name(target->type), y_type = ir::type_name(value->type);
    std::string name = "df_" + words.at(op) + "_assign_" + x_type.substr(3) + "_" + y_type.substr(3) + (fast_ ? "_fast" : "");
    ctx_.add_helper(name, x_type + " " + name + "(inout " + x_type + " x, " + y_type + " y) {\n  x = ", updated,
                    ";\n  return x;\n}\n");
    return ir::make_node(Kind::Call, name, target->type, {target, value}, loc);
  }

  ExprPtr lower_step(const ExprPtr& e) {
    // ++x, x--, ...: a generated inout helper keeps x evaluated once.
    if (is_component_lvalue(e->args[0])) {
      if (e->op == "++x" || e->op == "--x") {
        auto compound = Expr::make(Kind::Binary, e->type, e->loc);
        compound->op = e->op == "++x" ? "+=" : "-=";
        auto one = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Double), e->loc);
        ir::Scalar s;
        s.base = ir::Base::Double;
        s.d = 1.0;
        one->values = {s};
        compound->args = {e->args[0], one};
        return lower(compound);
      }
      ctx_.error(e->loc, "post-increment/decrement of one component of a double vector is not supported; use +=");
      return e;
    }
    ExprPtr target = lower(e->args[0]);
    int width = df_width(target->type);
    bool pre = e->op[0] == e->op[1];
    bool inc = e->op.find("++") != std::string::npos;
    std::string type = df_type_name(width), f = word_type_name(width);
    std::string name = std::string("df_") + (pre ? "pre_" : "post_") + (inc ? "increment" : "decrement") + "_" + type.substr(3);
    const std::string op = runtime_name(inc ? "df_add" : "df_sub");
    ctx_.use_rule(op, width);
    const std::string one_hi = exact() ? "0x3FF00000u" : "1.0", zero = exact() ? "0u" : "0.0";  // 1.0 = 0x3FF00000 00000000
    std::string one = width == 1 ? type + "(" + one_hi + ", " + zero + ")" : type + "(" + f + "(" + one_hi + "), " + f + "(" + zero + "))";
    std::string update = "  x = " + op + "(x, " + one + ");\n";
    ctx_.add_helper(name, type + " " + name + "(inout " + type + " x) {\n" +
                              (pre ? update + "  return x;\n" : "  " + type + " old = x;\n" + update + "  return old;\n") +
                              "}\n");
    return ir::make_node(Kind::Call, name, target->type, {target}, e->loc);
  }

  // The component helpers take an `int` index; GLSL has no implicit uint → int.
  static ExprPtr int_index(const ExprPtr& index) {
    if (index->type.base != ir::Base::Uint) return index;
    return ir::make_node(Kind::Construct, "", ir::scalar_type(ir::Base::Int), {index}, index->loc);
  }

  ExprPtr component(const ExprPtr& base, const ExprPtr& index, ir::Loc loc) {
    if (index->kind == Kind::Const && !index->values.empty()) {
      static const char* letters = "xyzw";
      return select(base, std::string(1, letters[index->values[0].i & 3]), loc);
    }
    int src = df_width(base->type);
    std::string name = "df_component_" + df_type_name(src).substr(3);
    ctx_.add_helper(name, "df_double " + name + "(" + df_type_name(src) +
                              " v, int i) {\n  return df_double(v.hi[i], v.lo[i]);\n}\n");
    return ir::make_node(Kind::Call, name, df_type(1), {base, int_index(index)}, loc);
  }

  ExprPtr lower_binary(const ExprPtr& e) {
    if (e->args.size() != 2) return e;
    const ExprPtr& a = e->args[0];
    const ExprPtr& b = e->args[1];
    const bool matrices = matrix::is_matrix(a->type) || matrix::is_matrix(b->type);
    if (!is_df(a->type) && !is_df(b->type) && !matrices) return e;
    const std::string& op = e->op;
    if (op == "=") return e;
    if (matrices && (op == "==" || op == "!="))
      return ir::make_node(Kind::Call, matrix::equal(ctx_, matrix::cols(a->type), matrix::rows(a->type), op == "!="),
                  ir::scalar_type(ir::Base::Bool), {a, b}, e->loc);
    if (op == "+" || op == "-" || op == "*" || op == "/") return arithmetic(op, a, b, e->loc);
    static const std::map<std::string, std::string> compare{{"<", "df_lt"}, {"<=", "df_le"}, {">", "df_gt"},
                                                             {">=", "df_ge"}, {"==", "df_equal"}, {"!=", "df_not_equal"}};
    if (auto it = compare.find(op); it != compare.end())
      return rule(it->second, df_width(a->type), ir::scalar_type(ir::Base::Bool), {a, b}, e->loc);
    ctx_.error(e->loc, "operator '" + op + "' is not supported on doubles");
    return e;
  }

  ExprPtr lower_builtin(const ExprPtr& e) {
    // `.length()` of a (runtime-sized) array of doubles counts elements, whatever they became.
    if (ir::is_array_length(*e)) return e;
    if (e->name == "packDouble2x32") return rule("df_pack_double2x32", 1, df_type(1), e->args, e->loc);
    if (ExprPtr bits = lower_int64_bit_casts(e)) return bits;
    bool any_df = std::any_of(e->args.begin(), e->args.end(),
                              [](const ExprPtr& a) { return is_df(a->type) || matrix::is_matrix(a->type); });
    if (!any_df) return e;
    const std::string& n = e->name;
    if (n.rfind("subgroup", 0) == 0) return lower_subgroup(e);
    if (ExprPtr m = lower_matrix_builtin(e)) return m;
    return lower_common_builtin(e);
  }

  // Subgroup operations on a double (GL_KHR_shader_subgroup_*): the ones that move a value between
  // invocations move both words, through a generated helper (the value is evaluated once):
  //   df_dvec3 df_subgroupShuffle_3(df_dvec3 v, uint id)
  //     { return df_dvec3(subgroupShuffle(v.hi, id), subgroupShuffle(v.lo, id)); }
  // In mode exact the words are the binary64 bits, so the move is exact there too. The reductions
  // and scans (subgroupAdd, ...) need the pair arithmetic in a tree of shuffles: refused by name.
  ExprPtr lower_subgroup(const ExprPtr& e) {
    static const std::set<std::string> kMoves = {
        "subgroupBroadcast", "subgroupBroadcastFirst", "subgroupShuffle", "subgroupShuffleXor",
        "subgroupShuffleUp", "subgroupShuffleDown", "subgroupQuadBroadcast", "subgroupQuadSwapHorizontal",
        "subgroupQuadSwapVertical", "subgroupQuadSwapDiagonal"};
    const std::string& n = e->name;
    const ExprPtr& value = e->args[0];
    const bool all_equal = n == "subgroupAllEqual" && !exact();  // words: +0 and -0 would differ
    if (!kMoves.count(n) && !all_equal && is_df(value->type))
      if (ExprPtr reduced = lower_subgroup_reduction(e)) return reduced;
    if ((!kMoves.count(n) && !all_equal) || !is_df(value->type)) {
      ctx_.error(e->loc, n + " is not lowered on doubles" + (exact() && n == "subgroupAllEqual" ? " in mode exact" : "") +
                             ": doublet lowers the subgroup operations that move a value (subgroupBroadcast, "
                             "subgroupShuffle, ...), the reductions and scans of Add, Mul, Min and Max, and "
                             "subgroupAllEqual outside mode exact");
      return e;
    }
    const int width = df_width(value->type);
    const std::string df = df_type_name(width);
    std::string name = "df_" + n + "_" + std::to_string(width), params = df + " v", extra;
    std::vector<ExprPtr> args = {value};
    // subgroupBroadcast's and subgroupQuadBroadcast's id must be a constant expression: it is
    // written into the helper (df_subgroupBroadcast_3_5u), not passed.
    const bool constant_id = n == "subgroupBroadcast" || n == "subgroupQuadBroadcast";
    for (size_t i = 1; i < e->args.size(); ++i) {
      const ExprPtr& a = e->args[i];
      if (constant_id) {
        if (a->kind != Kind::Const || a->values.size() != 1) {
          ctx_.error(a->loc, n + ": the invocation id must be a constant expression");
          return e;
        }
        const std::string literal = std::to_string(a->values[0].i) + (a->type.base == ir::Base::Uint ? "u" : "");
        extra += ", " + literal;
        name += "_" + literal;
        continue;
      }
      const std::string p = "a" + std::to_string(i);
      params += ", " + ir::type_name(a->type) + " " + p;
      extra += ", " + p;
      name += "_" + ir::type_name(a->type);
      args.push_back(a);
    }
    ctx_.use_width(width);
    if (all_equal) {
      ctx_.add_helper(name, "bool " + name + "(" + params + ") {\n  return all(bvec2(" + n + "(v.hi" + extra + "), " + n +
                                "(v.lo" + extra + ")));\n}\n");
      return ir::make_node(Kind::Call, name, ir::scalar_type(ir::Base::Bool), args, e->loc);
    }
    ctx_.add_helper(name, df + " " + name + "(" + params + ") {\n  return " + df + "(" + n + "(v.hi" + extra + "), " + n +
                              "(v.lo" + extra + "));\n}\n");
    return ir::make_node(Kind::Call, name, df_type(width), args, e->loc);
  }

  // Reductions and scans on a double (subgroupAdd, subgroupInclusiveMul, subgroupExclusiveMin,
  // subgroupClusteredMax, ...): one loop over the subgroup's lanes in id order, each active lane's
  // value moved by two shuffles (both words) and combined with the double operation of the mode
  // (df_add, ex_add, ...). Every lane of a reduction combines the same values in the same order,
  // so all get the same result; the error bound of the order is in docs/accuracy.md ("Subgroup
  // reductions"). The shuffles run in control flow that is uniform over the active lanes (the
  // ballot of active lanes is the same in each), so no lane reads an inactive one; a scan only
  // masks which values it combines. Cost: gl_SubgroupSize iterations, against log2 of it for the
  // driver's own tree on floats: the order, not the speed, is what the lowering fixes.
  ExprPtr lower_subgroup_reduction(const ExprPtr& e) {
    const std::string& n = e->name;
    std::string rest = n.substr(std::string("subgroup").size()), kind;
    for (const char* k : {"Inclusive", "Exclusive", "Clustered"})
      if (rest.rfind(k, 0) == 0) kind = k, rest = rest.substr(std::string(k).size());
    static const std::map<std::string, std::string> kOps = {
        {"Add", "df_add"}, {"Mul", "df_mul"}, {"Min", "df_min"}, {"Max", "df_max"}};
    auto op = kOps.find(rest);
    if (op == kOps.end()) return nullptr;
    const int width = df_width(e->args[0]->type);
    const std::string df = df_type_name(width), word = word_type_name(width), combine = runtime_name(op->second);
    std::string name = "df_" + n + "_" + std::to_string(width), taken = "true";
    if (kind == "Inclusive") taken = "j <= self";
    if (kind == "Exclusive") taken = "j < self";
    if (kind == "Clustered") {
      const ExprPtr& size = e->args[1];
      if (size->kind != Kind::Const || size->values.size() != 1) {
        ctx_.error(size->loc, n + ": the cluster size must be a constant expression");
        return e;
      }
      const std::string literal = std::to_string(size->values[0].i) + "u";
      name += "_" + literal;
      taken = "j / " + literal + " == self / " + literal;
    }
    ctx_.use_width(width);
    ctx_.use_rule(combine, width);
    ctx_.rule_first_use.emplace(combine, e->loc);
    for (const char* x : {"GL_KHR_shader_subgroup_ballot", "GL_KHR_shader_subgroup_shuffle"}) ctx_.extensions.insert(x);
    // Only an exclusive scan's first lane returns the identity: IEEE's for the operation, as the
    // GL_KHR_shader_subgroup_arithmetic specification lists it (0, 1, +Inf, -Inf).
    const std::map<std::string, std::string> identity_hi =
        exact() ? std::map<std::string, std::string>{{"Add", "0u"}, {"Mul", "0x3FF00000u"}, {"Min", "0x7FF00000u"}, {"Max", "0xFFF00000u"}}
                : std::map<std::string, std::string>{{"Add", "0.0"}, {"Mul", "1.0"}, {"Min", "uintBitsToFloat(0x7F800000u)"},
                                                     {"Max", "uintBitsToFloat(0xFF800000u)"}};
    const std::string& hi = identity_hi.at(rest);
    const std::string identity = df + "(" + word + "(" + hi + "), " + word + "(" + (exact() ? "0u" : "0.0") + "))";
    ctx_.add_helper(name, df + " " + name + "(" + df + " v) {\n"
                              "  uvec4 lanes = subgroupBallot(true);\n"
                              "  uint self = gl_SubgroupInvocationID;\n"
                              "  " + df + " r = " + identity + ";\n"
                              "  bool started = false;\n"
                              "  for (uint j = 0u; j < gl_SubgroupSize; ++j) {\n"
                              "    if (!subgroupBallotBitExtract(lanes, j)) continue;\n"
                              "    " + df + " x = " + df + "(subgroupShuffle(v.hi, j), subgroupShuffle(v.lo, j));\n"
                              "    if (" + taken + ") {\n"
                              "      r = started ? " + combine + "(r, x) : x;\n"
                              "      started = true;\n"
                              "    }\n"
                              "  }\n"
                              "  return r;\n"
                              "}\n");
    return ir::make_node(Kind::Call, name, df_type(width), {e->args[0]}, e->loc);
  }

  // Built-ins of GLSL 4.60 sections 8.3-8.7 on doubles: each is one rule of rules/*.glsl at the
  // width of its widest double argument; double scalars are splatted to that width (mix(x, y, a),
  // step(edge, x), clamp(x, lo, hi) with scalar bounds, ...).
  ExprPtr lower_common_builtin(const ExprPtr& e) {
    struct Builtin {
      const char* rule;
      enum Result { Same, Scalar, Bools } result;
    };
    static const std::map<std::string, Builtin> table{
        {"abs", {"df_abs", Builtin::Same}},          {"sqrt", {"df_sqrt", Builtin::Same}},
        {"inversesqrt", {"df_inversesqrt", Builtin::Same}}, {"sign", {"df_sign", Builtin::Same}},
        {"floor", {"df_floor", Builtin::Same}},      {"ceil", {"df_ceil", Builtin::Same}},
        {"trunc", {"df_trunc", Builtin::Same}},      {"round", {"df_round", Builtin::Same}},
        {"roundEven", {"df_round_even", Builtin::Same}}, {"fract", {"df_fract", Builtin::Same}},
        {"mod", {"df_mod", Builtin::Same}},          {"modf", {"df_modf", Builtin::Same}},
        {"min", {"df_min", Builtin::Same}},          {"max", {"df_max", Builtin::Same}},
        {"clamp", {"df_clamp", Builtin::Same}},      {"mix", {"df_mix", Builtin::Same}},
        {"step", {"df_step", Builtin::Same}},        {"smoothstep", {"df_smoothstep", Builtin::Same}},
        {"fma", {"df_fma", Builtin::Same}},          {"ldexp", {"df_ldexp", Builtin::Same}},
        {"frexp", {"df_frexp", Builtin::Same}},      {"cross", {"df_cross", Builtin::Same}},
        {"normalize", {"df_normalize", Builtin::Same}}, {"faceforward", {"df_faceforward", Builtin::Same}},
        {"reflect", {"df_reflect", Builtin::Same}},  {"refract", {"df_refract", Builtin::Same}},
        {"dot", {"df_dot", Builtin::Scalar}},        {"length", {"df_length", Builtin::Scalar}},
        {"distance", {"df_distance", Builtin::Scalar}}, {"isnan", {"df_isnan", Builtin::Bools}},
        {"isinf", {"df_isinf", Builtin::Bools}},     {"lessThan", {"df_less_than", Builtin::Bools}},
        {"lessThanEqual", {"df_less_than_equal", Builtin::Bools}},
        {"greaterThan", {"df_greater_than", Builtin::Bools}},
        {"greaterThanEqual", {"df_greater_than_equal", Builtin::Bools}},
        {"equal", {"df_equal_components", Builtin::Bools}}, {"notEqual", {"df_not_equal_components", Builtin::Bools}},
        // The transcendental extension (frontend/transcendentals.hpp, rules/transcendental.glsl).
        {"exp", {"df_exp", Builtin::Same}},          {"exp2", {"df_exp2", Builtin::Same}},
        {"log", {"df_log", Builtin::Same}},          {"log2", {"df_log2", Builtin::Same}},
        {"pow", {"df_pow", Builtin::Same}},          {"sin", {"df_sin", Builtin::Same}},
        {"cos", {"df_cos", Builtin::Same}},          {"tan", {"df_tan", Builtin::Same}},
        {"asin", {"df_asin", Builtin::Same}},        {"acos", {"df_acos", Builtin::Same}},
        {"atan", {"df_atan", Builtin::Same}},        {"sinh", {"df_sinh", Builtin::Same}},
        {"cosh", {"df_cosh", Builtin::Same}},        {"tanh", {"df_tanh", Builtin::Same}},
    };
    const std::string& n = e->name;
    if (n == "unpackDouble2x32")
      return rule("df_unpack_double2x32", 1, ir::scalar_type(ir::Base::Uint, 2), e->args, e->loc);
    if (n.rfind("atomic", 0) == 0) {
      ctx_.error(e->loc, "atomic operations on doubles (" + n + ") cannot be lowered for " +
                             ctx_.config.target_name() +
                             ": a double becomes two floats (hi, lo) that no atomic can update together; accumulate "
                             "per invocation and reduce afterwards, or use an integer fixed-point atomicAdd");
      return e;
    }
    auto it = table.find(n);
    if (it == table.end()) {
      ctx_.error(e->loc, "built-in function '" + n + "' is not defined on doubles in GLSL 4.60; doublet cannot lower it");
      return e;
    }
    if (ir::builtin_writes_second_argument(*e) && !is_pure(e->args[1])) {
      ctx_.error(e->args[1]->loc, "the out argument of " + n + " must be a whole double variable here, not one "
                                  "component of a double vector; use a temporary");
      return e;
    }
    std::string rule_name = it->second.rule;
    std::vector<ExprPtr> args = e->args;
    // Which arguments are doubles (others pass through: mix's bool selector, ldexp's and
    // frexp's int exponent, modf's out argument is a double lvalue and stays as it is).
    int width = 1;
    for (const auto& a : args)
      if (is_df(a->type)) width = std::max(width, df_width(a->type));
    if (n == "mix" && args[2]->type.base == ir::Base::Bool) rule_name = "df_mix_bool";
    // normalize(x) = x / |x| is sign(x) for float-float; mode exact repeats native's x / sqrt(x * x).
    if (n == "normalize" && width == 1 && !exact()) rule_name = "df_sign";
    if (n == "atan" && args.size() == 2) rule_name = "df_atan2";
    for (auto& a : args) {
      if (a->type.base == ir::Base::Bool || a->type.base == ir::Base::Int) continue;
      if (!is_df(a->type)) a = to_df(a);
      if (n == "refract" && &a == &args[2]) continue;  // eta stays a scalar
      if (df_width(a->type) < width) a = splat(a, width);
    }
    ir::Type result = df_type(width);
    if (it->second.result == Builtin::Scalar) result = df_type(1);
    if (it->second.result == Builtin::Bools) result = ir::scalar_type(ir::Base::Bool, width);
    return rule(rule_name, width, result, args, e->loc);
  }

  ExprPtr lower_construct(const ExprPtr& e, bool was_double) {
    if (was_double && matrix::is_matrix(e->type)) return construct_matrix(e);
    if (e->type.is_matrix() && e->args.size() == 1 && matrix::is_matrix(e->args[0]->type)) {
      // mat4(dmat4), mat3(dmat4): round each element to float, then resize as GLSL does.
      const ExprPtr& a = e->args[0];
      int c = matrix::cols(a->type), r = matrix::rows(a->type);
      auto converted = ir::make_node(Kind::Call, matrix::to_float(ctx_, c, r), float_matrix(c, r), {a}, e->loc);
      if (c == e->type.cols && r == e->type.vec) return converted;
      e->args = {converted};
      return e;
    }
    // Arrays and user structs take their elements and members whole (a dmat2 member included).
    if (e->type.is_array() || (e->type.base == ir::Base::Struct && !is_df(e->type))) return e;
    for (const auto& a : e->args)
      if (matrix::is_matrix(a->type)) {
        ctx_.error(a->loc, "building a scalar or vector from the components of a double matrix is not supported; "
                           "index its columns (m[j]) instead");
        return e;
      }
    if (was_double) {
      int width = df_width(e->type);
      std::vector<ExprPtr> parts;
      for (const auto& a : e->args) {
        if (a->type.is_matrix()) {
          ctx_.error(a->loc, "constructing a double vector from a matrix is not supported yet");
          return e;
        }
        parts.push_back(to_df(a));
      }
      if (parts.size() == 1) {
        int have = df_width(parts[0]->type);
        if (have == width) return parts[0];
        if (have == 1) return splat(parts[0], width);
        return select(parts[0], std::string("xyzw").substr(0, static_cast<size_t>(width)), e->loc);
      }
      return concatenate(parts, width, e->loc);
    }
    bool any_df = std::any_of(e->args.begin(), e->args.end(), [](const ExprPtr& a) { return is_df(a->type); });
    if (!any_df) return e;
    for (auto& a : e->args)
      if (is_df(a->type)) a = from_df(a, e->type.base);
    if (e->args.size() == 1 && e->args[0]->type.vec == e->type.vec && !e->type.is_matrix()) return e->args[0];
    return e;
  }

  // dvec3(double, dvec2) and friends: one generated helper per argument shape.
  ExprPtr concatenate(const std::vector<ExprPtr>& parts, int width, ir::Loc loc) {
    std::string name = "df_make_" + df_type_name(width).substr(3);
    std::string params, hi, lo;
    int taken = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
      int w = df_width(parts[i]->type);
      name += "_" + std::to_string(w);
      std::string p = "a" + std::to_string(i);
      params += (i ? ", " : "") + df_type_name(w) + " " + p;
      for (int c = 0; c < w && taken < width; ++c, ++taken) {
        std::string suffix = w == 1 ? "" : std::string(".") + "xyzw"[c];
        hi += (taken ? ", " : "") + p + ".hi" + suffix;
        lo += (taken ? ", " : "") + p + ".lo" + suffix;
      }
    }
    std::string f = word_type_name(width);
    ctx_.add_helper(name, df_type_name(width) + " " + name + "(" + params + ") {\n  return " + df_type_name(width) + "(" +
                              f + "(" + hi + "), " + f + "(" + lo + "));\n}\n");
    return ir::make_node(Kind::Call, name, df_type(width), parts, loc);
  }

  void check_out_arguments(const ExprPtr& e) {
    for (const auto& f : module_.functions) {
      if (f->name != e->name || f->params.size() != e->args.size()) continue;
      for (size_t i = 0; i < f->params.size(); ++i) {
        bool writes = ir::is_out_parameter(f->params[i]->storage);
        if (writes && is_df(f->params[i]->type) && e->args[i]->kind == Kind::Construct)
          ctx_.error(e->args[i]->loc, "passing one component of a double vector as an out/inout argument is not "
                                      "supported; use a temporary");
      }
    }
  }

  // ---- matrices (helpers generated by matrix_helpers.cpp) -----------------------------
  static ir::Type float_matrix(int cols, int rows) {
    ir::Type t = ir::scalar_type(ir::Base::Float, rows);
    t.cols = cols;
    return t;
  }

  ExprPtr matrix_column(const ExprPtr& m, const ExprPtr& j, ir::Loc loc) {
    int c = matrix::cols(m->type), r = matrix::rows(m->type);
    ctx_.use_width(r);
    if (is_pure(m) && j->kind == Kind::Const) {
      auto word = [&](const char* w) {  // mode exact: the words are arrays of uvecR columns
        ir::Type words = float_matrix(c, r), column = ir::scalar_type(ir::Base::Float, r);
        if (exact()) {
          column = ir::scalar_type(ir::Base::Uint, r);
          words = column;
          words.array_dims = {c};
        }
        auto index = Expr::make(Kind::Index, column, loc);
        index->args = {member(m, w, words), j};
        return index;
      };
      return ir::make_node(Kind::Construct, "", df_type(r), {word("hi"), word("lo")}, loc);
    }
    return ir::make_node(Kind::Call, matrix::column(ctx_, c, r), df_type(r), {m, int_index(j)}, loc);
  }

  static bool is_double_matrix(const ir::Type& t) { return t.is_double() && t.is_matrix() && !t.is_array(); }

  // m[j] = v, m[j][i] = x, their op= forms, and m[j].xy = ... (diagnosed).
  static bool is_matrix_lvalue_write(const ExprPtr& e) {
    if (!is_assignment(e)) return false;
    const ExprPtr& lhs = e->args[0];
    if (lhs->kind != Kind::Index && lhs->kind != Kind::Member) return false;
    const ExprPtr& base = lhs->args[0];
    if (lhs->kind == Kind::Index && is_double_matrix(base->type)) return true;
    return base->kind == Kind::Index && is_double_matrix(base->args[0]->type);
  }

  ExprPtr lower_matrix_write(const ExprPtr& e) {
    const ExprPtr& lhs = e->args[0];
    if (lhs->kind == Kind::Member) {
      ctx_.error(e->loc, "writing a swizzle of a double matrix column is not supported; assign the column m[j] or "
                         "single elements m[j][i]");
      return e;
    }
    const bool element = !is_double_matrix(lhs->args[0]->type);
    const bool side_effects = ir::has_side_effects(lhs);  // before lower() rewrites lhs in place
    ExprPtr m = lower(element ? lhs->args[0]->args[0] : lhs->args[0]);
    ExprPtr j = lower(element ? lhs->args[0]->args[1] : lhs->args[1]);
    ExprPtr i = element ? lower(lhs->args[1]) : nullptr;
    ExprPtr rhs = lower(e->args[1]);
    int c = matrix::cols(m->type), r = matrix::rows(m->type);
    if (e->op != "=") {
      if (side_effects)
        ctx_.error(e->loc, "compound assignment into a double matrix through an expression with side effects is not "
                           "supported; use a temporary");
      ExprPtr current = matrix_column(ir::clone(m), ir::clone(j), lhs->loc);
      if (element) current = component(current, ir::clone(i), lhs->loc);
      rhs = arithmetic(e->op.substr(0, 1), current, rhs, e->loc);
    }
    if (!is_df(rhs->type)) rhs = to_df(rhs);
    // The helpers take int indices; a uint index (gl_GlobalInvocationID arithmetic) is converted.
    if (element)
      return ir::make_node(Kind::Call, matrix::assign_element(ctx_, c, r), df_type(1), {m, int_index(j), int_index(i), rhs},
                           e->loc);
    if (df_width(rhs->type) < r) rhs = splat(rhs, r);
    return ir::make_node(Kind::Call, matrix::assign_column(ctx_, c, r), df_type(r), {m, int_index(j), rhs}, e->loc);
  }

  ExprPtr matrix_arithmetic(const std::string& op, ExprPtr a, ExprPtr b, ir::Loc loc) {
    const bool ma = matrix::is_matrix(a->type), mb = matrix::is_matrix(b->type);
    if (!ma && !is_df(a->type)) a = to_df(a);
    if (!mb && !is_df(b->type)) b = to_df(b);
    if (op == "*" && ma && mb) {
      int inner = matrix::cols(a->type), r = matrix::rows(a->type), c = matrix::cols(b->type);
      return ir::make_node(Kind::Call, matrix::times_matrix(ctx_, inner, r, c), matrix::type(c, r), {a, b}, loc);
    }
    if (op == "*" && ma && df_width(b->type) > 1) {
      int c = matrix::cols(a->type), r = matrix::rows(a->type);
      return ir::make_node(Kind::Call, matrix::times_vector(ctx_, c, r), df_type(r), {a, b}, loc);
    }
    if (op == "*" && mb && df_width(a->type) > 1) {
      int c = matrix::cols(b->type), r = matrix::rows(b->type);
      return ir::make_node(Kind::Call, matrix::vector_times(ctx_, c, r), df_type(c), {a, b}, loc);
    }
    static const std::map<std::string, std::string> names{{"+", "df_add"}, {"-", "df_sub"}, {"*", "df_mul"}, {"/", "df_div"}};
    auto it = names.find(op);
    if (it == names.end()) {
      ctx_.error(loc, "operator '" + op + "' is not defined on double matrices");
      return a;
    }
    const ir::Type& shape = ma ? a->type : b->type;
    int c = matrix::cols(shape), r = matrix::rows(shape);
    using Operand = matrix::Operand;
    std::string name = matrix::elementwise(ctx_, it->second, c, r, ma ? Operand::Matrix : Operand::Scalar,
                                           mb ? Operand::Matrix : Operand::Scalar);
    return ir::make_node(Kind::Call, name, matrix::type(c, r), {a, b}, loc);
  }

  // Null when `e` is not a matrix built-in.
  ExprPtr lower_matrix_builtin(const ExprPtr& e) {
    const std::string& n = e->name;
    const auto& args = e->args;
    if (n == "matrixCompMult" && matrix::is_matrix(args[0]->type)) {
      int c = matrix::cols(args[0]->type), r = matrix::rows(args[0]->type);
      using Operand = matrix::Operand;
      return ir::make_node(Kind::Call, matrix::elementwise(ctx_, "df_mul", c, r, Operand::Matrix, Operand::Matrix),
                  matrix::type(c, r), args, e->loc);
    }
    if (n == "transpose") {
      int c = matrix::cols(args[0]->type), r = matrix::rows(args[0]->type);
      return ir::make_node(Kind::Call, matrix::transpose(ctx_, c, r), matrix::type(r, c), args, e->loc);
    }
    if (n == "determinant")
      return ir::make_node(Kind::Call, matrix::determinant(ctx_, matrix::cols(args[0]->type)), df_type(1), args, e->loc);
    if (n == "inverse") {
      int size = matrix::cols(args[0]->type);
      return ir::make_node(Kind::Call, matrix::inverse(ctx_, size), matrix::type(size, size), args, e->loc);
    }
    if (n == "outerProduct") {
      int r = df_width(args[0]->type), c = df_width(args[1]->type);
      return ir::make_node(Kind::Call, matrix::outer_product(ctx_, c, r), matrix::type(c, r), args, e->loc);
    }
    return nullptr;
  }

  ExprPtr construct_matrix(const ExprPtr& e) {
    int c = matrix::cols(e->type), r = matrix::rows(e->type);
    if (e->args.size() == 1) {
      const ExprPtr& a = e->args[0];
      if (matrix::is_matrix(a->type)) {
        if (matrix::cols(a->type) == c && matrix::rows(a->type) == r) return a;
        return ir::make_node(Kind::Call, matrix::resize(ctx_, matrix::cols(a->type), matrix::rows(a->type), c, r), e->type, {a},
                    e->loc);
      }
      if (a->type.is_matrix()) {  // dmat4(mat4): hi is the float matrix, lo is zero
        ExprPtr hi = a;
        if (a->type.cols != c || a->type.vec != r) hi = ir::make_node(Kind::Construct, "", float_matrix(c, r), {a}, e->loc);
        if (exact()) return ir::make_node(Kind::Call, matrix::exact::from_float(ctx_, c, r), e->type, {hi}, e->loc);
        auto zero = ir::make_node(Kind::Construct, "", float_matrix(c, r), {float_const(0.0f, e->loc)}, e->loc);
        return ir::make_node(Kind::Construct, "", e->type, {hi, zero}, e->loc);
      }
      if (a->type.vec == 1 || (is_df(a->type) && df_width(a->type) == 1))
        return ir::make_node(Kind::Call, matrix::diagonal(ctx_, c, r), e->type, {to_df(a)}, e->loc);
    }
    std::vector<ExprPtr> parts;
    std::vector<int> widths;
    for (const auto& a : e->args) {
      if (a->type.is_matrix() || matrix::is_matrix(a->type)) {
        ctx_.error(a->loc, "a matrix argument must be a matrix constructor's only argument");
        return e;
      }
      parts.push_back(to_df(a));
      widths.push_back(df_width(parts.back()->type));
    }
    return ir::make_node(Kind::Call, matrix::from_components(ctx_, c, r, widths), e->type, parts, e->loc);
  }

  ir::Module& module_;
  Context& ctx_;
  std::set<std::string> reported_;  // unsupported types already diagnosed
  bool fast_ = false;  // the current function's arithmetic is df64-fast (rules/fast.glsl)
  std::optional<frontend::LineIndex> source_lines_;  // built on the first infinite constant
};

}  // namespace

bool lower_doubles(ir::Module& module, Context& context) {
  DoubleLowering(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
