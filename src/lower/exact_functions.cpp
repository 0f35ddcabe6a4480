// Exact functions in a float-float shader: see exact_functions.hpp and docs/modes.md.
#include "lower/exact_functions.hpp"

#include <algorithm>
#include <cctype>

#include "ir/walk.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

bool is_word_type_name(std::string_view id) {
  return id == "df_double" || id.rfind("df_dvec", 0) == 0 || id.rfind("df_dmat", 0) == 0;
}

// The exact part's name for a df_ identifier (rename_exact_runtime); others unchanged.
std::string exact_name(const std::string& id) {
  if (id.rfind("df_", 0) != 0) return id;
  return (is_word_type_name(id) ? "ex_" : "ff_") + id.substr(3);
}

ir::Type exact_type(ir::Type t) {
  if (t.base == ir::Base::Struct && is_word_type_name(t.name)) t.name = "ex_" + t.name.substr(3);
  return t;
}

bool involves_doubles(const ir::Function& f) {
  if (f.return_type.contains_double()) return true;
  return std::any_of(f.params.begin(), f.params.end(), [](const ir::VarPtr& p) { return p->type.contains_double(); });
}

// What an exact function may take and give: a double scalar or vector (not a matrix, array or struct).
bool convertible(const ir::Type& t) { return t.is_double() && !t.is_matrix() && !t.is_array(); }

class Extractor {
 public:
  Extractor(ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  // The refusals that keep the conversions at the calls the only meeting of the two representations.
  bool check(const ir::Function& f) {
    const std::string head = "exact function '" + f.name + "': ";
    if (f.name == "main") return refuse(f.loc, head + "main cannot be exact alone: use --mode exact for the whole shader");
    if (std::count_if(module_.functions.begin(), module_.functions.end(),
                      [&](const ir::FunctionPtr& g) { return g->name == f.name; }) > 1)
      return refuse(f.loc, head + "an overloaded function cannot be exact; rename the overload");
    if (f.return_type.contains_double() && !convertible(f.return_type))
      return refuse(f.loc, head + "it returns a " + ir::type_name(f.return_type) +
                               "; an exact function returns a double or a double vector");
    for (const auto& p : f.params) {
      if (!p->type.contains_double()) continue;
      if (!convertible(p->type))
        return refuse(p->loc, head + "parameter '" + p->name + "' is a " + ir::type_name(p->type) +
                                  "; an exact function takes doubles and double vectors");
      if (p->storage != ir::Storage::ParamIn)
        return refuse(p->loc, head + "parameter '" + p->name + "' is out/inout; an exact function takes its doubles "
                                     "as in parameters and returns its result");
    }
    bool ok = true;
    ir::visit(f.body, [&](const ExprPtr& e) {
      if (!ok) return;
      if (e->kind == Kind::Sym && e->var && !ir::is_function_local(e->var->storage) && e->var->type.contains_double())
        ok = refuse(e->loc, head + "it uses the double global '" + e->var->name + "', which the float-float code "
                                    "holds as hi and lo; pass it as a parameter");
      if (e->kind == Kind::Call)
        for (const auto& g : module_.functions)
          if (g->name == e->name && !ctx_.exact_functions.count(g.get()) && involves_doubles(*g))
            ok = refuse(e->loc, head + "it calls '" + g->name + "', which takes or returns doubles and is not exact; "
                                        "make it exact too");
    });
    return ok;
  }

  // A copy of `f` with a fresh body: what the shader's lowering sees of an exact function.
  static ir::FunctionPtr stub_of(const ir::Function& f) {
    auto stub = std::make_shared<ir::Function>();
    stub->name = f.name;
    stub->return_type = f.return_type;
    stub->loc = f.loc;
    for (const auto& p : f.params) stub->params.push_back(std::make_shared<ir::Var>(*p));
    stub->body = ir::Stmt::make(ir::Stmt::Kind::Block, f.loc);
    return stub;
  }

 private:
  bool refuse(ir::Loc loc, const std::string& message) {
    ctx_.error(loc, message);
    return false;
  }

  ir::Module& module_;
  Context& ctx_;
};

// Every type the exact part's IR names, and its calls of generated helpers, under the exact part's names.
void rename_exact_ir(ir::Function& f) {
  f.return_type = exact_type(f.return_type);
  for (auto& p : f.params) p->type = exact_type(p->type);
  std::function<void(const ir::StmtPtr&)> statement = [&](const ir::StmtPtr& s) {
    if (!s) return;
    if (s->var) s->var->type = exact_type(s->var->type);
    for (const auto& b : s->body) statement(b);
  };
  statement(f.body);
  ir::visit(f.body, [](const ExprPtr& e) {
    e->type = exact_type(e->type);
    if (e->var) e->var->type = exact_type(e->var->type);
    if (e->kind == Kind::Call) e->name = exact_name(e->name);
  });
}

ExprPtr call(const std::string& name, const ir::Type& type, const ExprPtr& arg) {
  return ir::make_node(Kind::Call, name, type, {arg}, arg->loc);
}

}  // namespace

bool extract_exact_functions(ir::Module& module, Context& ctx, std::unique_ptr<ExactPart>& part) {
  if (ctx.exact_functions.empty()) return true;
  const ir::Loc first = (*ctx.exact_functions.begin())->loc;
  if (!ctx.config.facts->uint_and_bit_ops) {
    ctx.error(first, "mode exact needs 32-bit integers (uint and bit operations), which GLSL ES 1.00 lacks: use "
                     "--target es300 or later");
    return false;
  }
  if (target::facts(ctx.config.output).wgsl) {
    ctx.error(first, "exact functions in a float-float shader are not lowered for wgsl yet: use --mode exact for the "
                     "whole shader, or a GLSL target");
    return false;
  }
  Extractor extractor(module, ctx);
  for (const auto& f : module.functions)
    if (ctx.exact_functions.count(f.get()) && !extractor.check(*f)) return false;

  part = std::make_unique<ExactPart>();
  part->config = ctx.config;
  part->config.representation = pipeline::Representation::Binary64Words;
  part->config.mode = part->config.requested_mode = Mode::Exact;
  part->config.guard = rules::GuardStyle::None;
  part->config.integer_eft = false;
  part->config.optimize = false;
  part->ctx = std::make_unique<Context>(Context{part->config, ctx.diagnostics, ctx.source});
  part->module.stage = module.stage;
  part->module.source_version = module.source_version;
  part->module.source_es = module.source_es;
  for (auto& f : module.functions) {
    if (!ctx.exact_functions.count(f.get())) continue;
    ir::FunctionPtr stub = Extractor::stub_of(*f);
    part->module.functions.push_back(f);
    part->stubs[stub.get()] = f;
    f = stub;
  }
  // The same passes as the shader's functions get before lower-doubles, in binary64 words.
  if (!out_argument_temporaries(part->module, *part->ctx) || !lower_doubles(part->module, *part->ctx)) return false;
  for (auto& f : part->module.functions) rename_exact_ir(*f);
  return !ctx.failed;
}

bool join_exact_functions(ir::Module& module, Context& ctx, ExactPart& part) {
  std::map<std::string, const ir::Function*> exact_by_name;  // the lowered exact functions
  for (auto& f : module.functions) {
    auto it = part.stubs.find(f.get());
    if (it == part.stubs.end()) continue;
    f = it->second;
    exact_by_name[f->name] = f.get();
  }
  // Calls from the float-float code: arguments to binary64, the result back to a float-float pair.
  for (auto& f : module.functions) {
    if (exact_by_name.count(f->name)) continue;
    ir::rewrite(f->body, [&](const ExprPtr& e) -> ExprPtr {
      if (e->kind != Kind::Call || !exact_by_name.count(e->name)) return nullptr;
      const ir::Function& callee = *exact_by_name.at(e->name);
      for (size_t i = 0; i < e->args.size() && i < callee.params.size(); ++i)
        if (is_df(e->args[i]->type)) {
          part.converted_widths.insert(df_width(e->args[i]->type));
          e->args[i] = call("df_to_exact", callee.params[i]->type, e->args[i]);
        }
      if (!is_df(e->type)) return nullptr;
      const ir::Type pair = e->type;
      part.converted_widths.insert(df_width(pair));
      e->type = callee.return_type;
      return call("df_from_exact", pair, e);
    });
  }
  if (part.converted_widths.empty()) return !ctx.failed;  // no call passes a double: no conversion
  ctx.use_width(1);  // the vectors convert component by component
  for (int w : part.converted_widths) ctx.use_width(w);
  for (const std::string& rule : {"ex_from_ff", "ex_to_ff", "ex_bits", "ex_from_bits"}) part.ctx->use_rule(rule, 1);
  return !ctx.failed;
}

std::string rename_exact_runtime(std::string_view text) {
  auto ident_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < text.size();) {
    if ((std::isalpha(static_cast<unsigned char>(text[i])) || text[i] == '_') && (i == 0 || !ident_char(text[i - 1]))) {
      size_t j = i;
      while (j < text.size() && ident_char(text[j])) ++j;
      out += exact_name(std::string(text.substr(i, j - i)));
      i = j;
      continue;
    }
    out += text[i++];
  }
  return out;
}

std::string exact_conversions(const ExactPart& part) {
  if (part.converted_widths.empty()) return "";
  std::string out =
      "\n// The calls of exact functions (docs/modes.md, \"Exact functions\"): a float-float pair to the binary64\n"
      "// nearest hi + lo, and a binary64 value to its nearest pair.\n";
  std::set<int> widths = part.converted_widths;
  widths.insert(1);  // the vectors convert component by component
  for (int w : widths) {
    const std::string n = w == 1 ? "double" : "dvec" + std::to_string(w);
    const std::string df = "df_" + n, ex = "ex_" + n;
    if (w == 1) {
      out += ex + " df_to_exact(" + df + " a) {\n  return ex_from_bits(ex_from_ff(ff_double(a.hi, a.lo)));\n}\n";
      out += df + " df_from_exact(" + ex + " a) {\n  ff_double f = ex_to_ff(ex_bits(a));\n  return " + df +
             "(f.hi, f.lo);\n}\n";
      continue;
    }
    const std::string u = "uvec" + std::to_string(w), v = "vec" + std::to_string(w);
    std::string to_hi, to_lo, from_hi, from_lo, to_parts, from_parts;
    for (int k = 0; k < w; ++k) {
      const std::string c = std::string(1, "xyzw"[k]), x = "x" + std::to_string(k);
      to_parts += "  ex_double " + x + " = df_to_exact(df_double(a.hi." + c + ", a.lo." + c + "));\n";
      from_parts += "  df_double " + x + " = df_from_exact(ex_double(a.hi." + c + ", a.lo." + c + "));\n";
      to_hi += (k ? ", " : "") + x + ".hi";
      to_lo += (k ? ", " : "") + x + ".lo";
    }
    out += ex + " df_to_exact(" + df + " a) {\n" + to_parts + "  return " + ex + "(" + u + "(" + to_hi + "), " + u + "(" +
           to_lo + "));\n}\n";
    out += df + " df_from_exact(" + ex + " a) {\n" + from_parts + "  return " + df + "(" + v + "(" + to_hi + "), " + v +
           "(" + to_lo + "));\n}\n";
  }
  return out;
}

}  // namespace doublet::passes
