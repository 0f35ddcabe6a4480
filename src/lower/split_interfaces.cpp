// split_interfaces: a double `in`/`out`/`uniform` X becomes two variables of the
// same-shaped float type, X_hi then X_lo. X itself stays as a private df_*
// global: inputs are joined into it at the start of main, outputs are split
// out of it before every return from main. Runs after lower_doubles.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <tuple>

#include "ir/walk.hpp"
#include "lower/block_layout.hpp"
#include "lower/exact_interface.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

std::string storage_name(ir::Storage s, ir::StageKind stage, bool es100) {
  switch (s) {
    case ir::Storage::In: return es100 ? (stage == ir::StageKind::Vertex ? "attribute" : "varying") : "in";
    case ir::Storage::Out: return es100 ? "varying" : "out";
    case ir::Storage::Uniform: return "uniform";
    case ir::Storage::Buffer: return "buffer";
    default: return "";
  }
}

ExprPtr member(const ExprPtr& base, const std::string& name, const ir::Type& type) {
  auto e = Expr::make(Kind::Member, type);
  e->name = name;
  e->args = {base};
  return e;
}

ir::StmtPtr assign(const ExprPtr& lhs, const ExprPtr& rhs) { return ir::make_statement(ir::make_assign(lhs, rhs)); }

// Element accessors for every array element (unrolled; arrays are sized).
void for_each_element(const ExprPtr& e, const std::function<void(const ExprPtr&)>& f) {
  if (!e->type.is_array()) return f(e);
  for (int i = 0; i < e->type.array_dims[0]; ++i) for_each_element(ir::make_index(e, i), f);
}

// GL uniform names of every leaf of a (lowered) struct uniform: "s.a.hi", "s.b[1].lo", "s.m.hi".
void uniform_leaves(const ir::Type& t, const std::string& name, std::vector<std::string>& out) {
  if (t.is_array()) {
    for (int i = 0; i < t.array_dims[0]; ++i) uniform_leaves(t.element(), name + "[" + std::to_string(i) + "]", out);
    return;
  }
  if (t.base == ir::Base::Struct && t.name.rfind("df_d", 0) == 0) {
    out.push_back(name + ".hi");
    out.push_back(name + ".lo");
    return;
  }
  if (t.base == ir::Base::Struct && t.fields) {
    for (const auto& f : *t.fields) uniform_leaves(f.type, name + "." + f.name, out);
    return;
  }
  out.push_back(name);
}

struct Split {
  ir::VarPtr original, hi, lo;
  ir::Storage storage;  // the original's storage class
};

// Mode exact: the word variables of one double interface variable (exact_interface.hpp).
struct WordSplit {
  ir::VarPtr original;
  std::vector<ir::VarPtr> parts;
  ir::Storage storage;
  int width = 1;
};

// Puts `copy_out` before every statement below `s` that `before` selects.
void add_copy_out_before(const ir::StmtPtr& s, const std::vector<ir::StmtPtr>& copy_out,
                         const std::function<bool(const ir::Stmt&)>& before) {
  for (auto& child : s->body) {
    if (!child) continue;
    if (before(*child)) {
      auto block = ir::Stmt::make(ir::Stmt::Kind::Block, child->loc);
      block->body = copy_out;
      block->body.push_back(child);
      child = block;
    } else {
      add_copy_out_before(child, copy_out, before);
    }
  }
}

// Outputs are split out before every return from main.
void add_copy_out(const ir::StmtPtr& s, const std::vector<ir::StmtPtr>& copy_out) {
  add_copy_out_before(s, copy_out, [](const ir::Stmt& st) { return st.kind == ir::Stmt::Kind::Return; });
}

// `array[gl_InvocationID]`.
ExprPtr index_by_invocation(const ExprPtr& array) {
  auto id = std::make_shared<ir::Var>();
  id->name = "gl_InvocationID";
  id->type = ir::scalar_type(ir::Base::Int);
  id->declared_type = id->type;
  id->storage = ir::Storage::BuiltIn;
  auto e = Expr::make(Kind::Index, array->type.element());
  e->args = {array, ir::make_sym(id)};
  return e;
}

// A tessellation control shader's per-vertex double outputs live in private copies until main's
// end, where each invocation stores its own vertex (index_by_invocation). That is right only when
// the shader reads and writes its own vertex alone: anything else is refused by name. Per-patch
// outputs, which any invocation may write, are written through instead (PatchOutput).
bool tessellation_control_outputs_are_own(const ir::Module& module, const std::vector<Split>& splits,
                                          const std::vector<WordSplit>& word_splits, Context& ctx) {
  if (module.stage != ir::StageKind::TessControl) return true;
  std::set<const ir::Var*> outputs;
  auto note = [&](const ir::VarPtr& v, ir::Storage storage) {
    if (storage == ir::Storage::Out && !v->patch) outputs.insert(v.get());
  };
  for (const auto& s : splits) note(s.original, s.storage);
  for (const auto& s : word_splits) note(s.original, s.storage);
  for (const auto& f : module.functions)
    ir::visit(f->body, [&](const ExprPtr& e) {
      for (size_t k = 0; k < e->args.size(); ++k) {
        const ExprPtr& a = e->args[k];
        if (!a || a->kind != Kind::Sym || !outputs.count(a->var.get())) continue;
        const bool own = e->kind == Kind::Index && k == 0 && e->args[1]->kind == Kind::Sym &&
                         e->args[1]->var->name == "gl_InvocationID";
        if (!own)
          ctx.error(e->loc, "the double output '" + a->var->name + "' of a tessellation control shader is used "
                            "other than as " + a->var->name + "[gl_InvocationID]; doublet lowers only an invocation's "
                            "own vertex of a per-vertex double output");
      }
    });
  return !ctx.failed;
}

// A per-patch double output of a tessellation control shader: any invocation may write it, and
// after barrier() every invocation reads what was written. So its split variables are stored
// right after each statement that writes the private copy (copy_out: only that variable, so that
// no invocation stores a stale value over another's write), and the private copy is joined again
// from them at main's start and after every barrier() (copy_in).
struct PatchOutput {
  const ir::Var* var = nullptr;
  std::vector<ir::StmtPtr> copy_in, copy_out;
};

// Whether `e` may write `v`: an assignment or increment of it (or of a part of it), or an out
// argument of a call (the shader's functions by their parameters, the runtime's helpers by theirs).
bool writes_variable(const ExprPtr& e, const ir::Var* v, const ir::Module& module, const Context& ctx) {
  if (!e) return false;
  bool found = false;
  ir::visit(e, [&](const ExprPtr& x) {
    if (found) return;
    if ((x->kind == Kind::Binary && ir::is_assignment_operator(x->op)) || ir::is_increment(*x)) {
      found = ir::root_variable(x->args[0]) == v;
      return;
    }
    if (x->kind != Kind::Call) return;
    const std::vector<ir::Storage> runtime = is_runtime_call(*x) ? ctx.runtime_parameters(*x) : std::vector<ir::Storage>();
    for (size_t i = 0; i < x->args.size() && !found; ++i) {
      if (ir::root_variable(x->args[i]) != v) continue;
      if (is_runtime_call(*x)) {
        found = i < runtime.size() && ir::is_out_parameter(runtime[i]);
        continue;
      }
      for (const auto& f : module.functions)
        if (f->name == x->name && i < f->params.size() &&
            ir::is_out_parameter(f->params[i]->storage))
          found = true;
    }
  });
  return found;
}

// Puts `p.copy_out` after every statement below `s` that writes p's variable. A write in a
// condition, a loop's header or a return has no statement to follow: refused by name.
void add_copy_out_after_writes(const ir::StmtPtr& s, const PatchOutput& p, const ir::Module& module, Context& ctx) {
  if (!s) return;
  using SK = ir::Stmt::Kind;
  auto refuse = [&](ir::Loc loc) {
    ctx.error(loc, "the per-patch double output '" + p.var->name + "' is written inside a condition, a loop's "
                   "header or a return; doublet stores a per-patch output after the statement that writes it: "
                   "write it in a statement of its own");
  };
  if (s->kind != SK::Expr && s->kind != SK::Decl && (writes_variable(s->expr, p.var, module, ctx) ||
                                                     writes_variable(s->step, p.var, module, ctx)))
    refuse(s->loc);
  if (s->kind == SK::Loop && !s->body.empty() && s->body[0] &&
      writes_variable(s->body[0]->expr, p.var, module, ctx))
    refuse(s->body[0]->loc);
  for (size_t k = 0; k < s->body.size(); ++k) {
    ir::StmtPtr& child = s->body[k];
    if (!child) continue;
    if (s->kind == SK::Loop && k == 0) continue;  // the loop's init, checked above
    const bool statement = child->kind == SK::Expr || child->kind == SK::Decl;
    if (!statement || !writes_variable(child->expr, p.var, module, ctx)) {
      add_copy_out_after_writes(child, p, module, ctx);
    } else if (s->kind == SK::Block) {  // in place: a declaration keeps its scope
      s->body.insert(s->body.begin() + static_cast<long>(k) + 1, p.copy_out.begin(), p.copy_out.end());
      k += p.copy_out.size();
    } else {  // the single statement of an if or a loop
      auto block = ir::Stmt::make(SK::Block, child->loc);
      block->body.push_back(child);
      block->body.insert(block->body.end(), p.copy_out.begin(), p.copy_out.end());
      child = block;
    }
  }
}

// Puts `copy_in` after every barrier() below `s`.
void add_copy_in_after_barriers(const ir::StmtPtr& s, const std::vector<ir::StmtPtr>& copy_in) {
  if (!s) return;
  for (size_t k = 0; k < s->body.size(); ++k) {
    const ir::StmtPtr& child = s->body[k];
    if (!child) continue;
    const bool barrier = child->kind == ir::Stmt::Kind::Expr && child->expr && child->expr->kind == Kind::Builtin &&
                         child->expr->name == "barrier";
    if (barrier && s->kind == ir::Stmt::Kind::Block) {
      s->body.insert(s->body.begin() + static_cast<long>(k) + 1, copy_in.begin(), copy_in.end());
      k += copy_in.size();
    } else {
      add_copy_in_after_barriers(child, copy_in);
    }
  }
}

// Geometry: the outputs are the values at each EmitVertex()/EmitStreamVertex(n), so the split
// goes before every such call statement, in any function (the outputs are globals).
void add_copy_out_before_emits(const ir::StmtPtr& s, const std::vector<ir::StmtPtr>& copy_out) {
  add_copy_out_before(s, copy_out, [](const ir::Stmt& st) {
    return st.kind == ir::Stmt::Kind::Expr && st.expr && st.expr->kind == Kind::Builtin &&
           (st.expr->name == "EmitVertex" || st.expr->name == "EmitStreamVertex");
  });
}

// Diagnoses a generated name that GLSL reserves ("__") or that the shader already uses.
// `remedy` ends the message when renaming the generated name is up to an option.
void check_generated_name(const ir::Var& v, const std::string& generated, bool first, Context& ctx,
                          std::set<std::string>& names, const std::string& remedy = " or change --hi-suffix/--lo-suffix") {
  if (generated.find("__") != std::string::npos) {
    if (first && v.name.find("__") != std::string::npos)
      ctx.error(v.loc, "'" + v.name + "' contains '__', which GLSL reserves, and so would its split names ('" +
                           generated + "'); rename it");
    else if (v.name.find("__") == std::string::npos)
      ctx.error(v.loc, "splitting '" + v.name + "' makes '" + generated + "', which contains '__' (GLSL reserves it); "
                       "choose a --hi-suffix/--lo-suffix without '__'");
  } else if (names.count(generated)) {
    ctx.error(v.loc, "splitting '" + v.name + "' needs the name '" + generated +
                         "', which the shader already uses; rename it" + remedy);
  }
  names.insert(generated);
}

// The locations user declarations hold, per storage class ([first, first + count) each, a
// dvec3/4 counted as two), and the next location past all of them.
struct HeldLocations {
  std::map<ir::Storage, std::vector<std::tuple<const ir::Var*, int, int>>> held;
  std::map<ir::Storage, int> next;
  bool held_by_other(const ir::Var* v, int first, int count) const {
    auto it = held.find(v->storage);
    if (it == held.end()) return false;
    for (const auto& [w, from, n] : it->second)
      if (w != v && first < from + n && from < first + count) return true;
    return false;
  }
};

// Mode exact: `v` becomes its word variables (exact_interface.hpp); v stays as the private df_*
// value, renamed NAME_value when the first word variable takes its name.
WordSplit split_into_words(const ir::VarPtr& v, ir::StageKind stage, Context& ctx, std::set<std::string>& names,
                           InterfaceVariable& entry, HeldLocations& locations) {
  WordSplit s;
  s.original = v;
  s.storage = v->storage;
  s.width = v->declared_type.vec;
  const std::vector<std::string> suffixes = exact_io::part_suffixes(s.width);
  const int elements = v->declared_type.is_array() ? v->declared_type.array_dims[0] : 1;
  const bool varying = exact_io::between_stages(v->storage, stage);
  for (size_t k = 0; k < suffixes.size(); ++k) {
    auto part = std::make_shared<ir::Var>(*v);
    part->name = suffixes[k].empty() ? v->name : ir::join_identifier(v->name, suffixes[k]);
    part->type = exact_io::part_type(s.width, static_cast<int>(k));
    part->type.array_dims = v->declared_type.array_dims;
    part->declared_type = part->type;
    if (varying && !v->patch) part->interp = ir::Interp::Flat;  // integer varyings must be flat (GLSL; patch ones take no qualifier)
    // One location per element and part: a dvec3/dvec4's two parts fill the two locations it had
    // (SPIR-V's count), unless another declaration holds the second (OpenGL counts a vertex
    // input's dvec3 as one location): then the next free one past every declaration.
    if (v->layout.location >= 0) {
      part->layout.location = v->layout.location + static_cast<int>(k) * elements;
      if (k > 0 && locations.held_by_other(v.get(), part->layout.location, elements)) {
        part->layout.location = locations.next[v->storage];
        locations.next[v->storage] += elements;
      }
    }
    if (!suffixes[k].empty()) check_generated_name(*v, part->name, k == 0, ctx, names, "");
    entry.lowered_names.push_back(part->name);
    entry.lowered_types.push_back(ir::type_name(part->type) + ir::array_suffix(part->type));
    if (part->layout.location >= 0) entry.locations.push_back(part->layout.location);
    s.parts.push_back(part);
  }
  if (suffixes[0].empty()) {
    v->name = ir::join_identifier(v->name, "_value");
    check_generated_name(*s.original, v->name, false, ctx, names, "");
  }
  entry.split = true;
  entry.encoding = exact_io::kEncoding;
  entry.lowered_type = ir::type_name(s.parts[0]->type) + ir::array_suffix(s.parts[0]->type);
  return s;
}

// Mode exact: a loose `uniform dmatCxR M[n]` becomes `uniform uvec4 M[ceil(n*C*R/2)]`, the
// matrices' doubles column-major, element after element, two per uvec4 (low word, high word each):
// the host's column-major doubles are the words unchanged (only an odd count, e.g. dmat3, leaves
// the last zw unused). M itself becomes the private df_dmat value M_value, loaded at main's start.
struct MatrixSplit {
  ir::VarPtr original, words;
  int cols = 0, rows = 0;
};

MatrixSplit split_matrix_uniform(const ir::VarPtr& v, Context& ctx, std::set<std::string>& names,
                                 InterfaceVariable& entry) {
  MatrixSplit s;
  s.original = v;
  s.cols = v->declared_type.cols;
  s.rows = v->declared_type.vec;
  const int elements = v->declared_type.is_array() ? v->declared_type.array_dims[0] : 1;
  s.words = std::make_shared<ir::Var>(*v);
  s.words->type = ir::scalar_type(ir::Base::Uint, 4);
  s.words->type.array_dims = {(elements * s.cols * s.rows + 1) / 2};
  s.words->declared_type = s.words->type;
  v->name = ir::join_identifier(v->name, "_value");
  check_generated_name(*s.original, v->name, false, ctx, names, "");
  entry.split = true;
  entry.encoding = exact_io::kEncoding;
  entry.lowered_names = {s.words->name};
  entry.lowered_type = ir::type_name(s.words->type) + ir::array_suffix(s.words->type);
  entry.lowered_types = {entry.lowered_type};
  return s;
}

// The df_dmatCxR value whose first double is double number `first` of the words.
ExprPtr matrix_value(const MatrixSplit& s, int first) {
  const ir::Type word = ir::scalar_type(ir::Base::Uint), column = ir::scalar_type(ir::Base::Uint, s.rows);
  ir::Type columns = column;
  columns.array_dims = {s.cols};
  auto half = [&](bool high) {
    auto array = Expr::make(Kind::Construct, columns);
    for (int j = 0; j < s.cols; ++j) {
      auto col = Expr::make(Kind::Construct, column);
      for (int i = 0; i < s.rows; ++i) {
        const int k = first + j * s.rows + i;  // double k: words 2k (low), 2k + 1 (high)
        const char* letter = k % 2 == 0 ? (high ? "y" : "x") : (high ? "w" : "z");
        col->args.push_back(member(ir::make_index(ir::make_sym(s.words), k / 2), letter, word));
      }
      array->args.push_back(s.rows == 1 ? col->args[0] : col);
    }
    return array;
  };
  ir::Type type = s.original->type;
  type.array_dims.clear();
  auto value = Expr::make(Kind::Construct, type);
  value->args = {half(true), half(false)};
  return value;
}

}  // namespace

// The hi (half 0) or lo (half 1) words of a double constant, as a float constant of `type`:
// hi = float(x), lo = float(x - hi) (x - hi is exact in binary64), lo = 0 where hi is not finite:
// the split the host helpers make (doublet::split).
static ExprPtr split_constant(const std::vector<double>& values, const ir::Type& type, int half, ir::Loc loc) {
  auto e = ir::Expr::make(Kind::Const, type, loc);
  for (double x : values) {
    const float hi = static_cast<float>(x);
    ir::Scalar s;
    s.base = ir::Base::Float;
    s.d = half == 0 ? hi : std::isfinite(hi) ? static_cast<float>(x - static_cast<double>(hi)) : 0.0f;
    e->values.push_back(s);
  }
  return e;
}

bool split_interfaces(ir::Module& module, Context& ctx, Manifest& manifest) {
  const bool es100 = ctx.config.target == Target::Es100;
  std::set<std::string> names;
  for (const auto& g : module.globals) names.insert(g->name);
  for (const auto& f : module.functions) names.insert(f->name);

  // Next free location per storage class, for the _lo halves (and exact's displaced parts).
  HeldLocations locations;
  std::map<ir::Storage, int>& next_location = locations.next;
  for (const auto& g : module.globals) {
    if (g->layout.location < 0) continue;
    int slots = (g->type.is_array() ? g->type.array_dims[0] : 1) * std::max(g->declared_type.cols, 1);
    if (g->declared_type.is_double() && g->declared_type.vec > 2) slots *= 2;  // dvec3/4 take two locations
    next_location[g->storage] = std::max(next_location[g->storage], g->layout.location + slots);
    locations.held[g->storage].emplace_back(g.get(), g->layout.location, slots);
  }

  std::vector<ir::VarPtr> globals;
  std::vector<ExprPtr> inits;
  std::vector<Split> splits;
  std::vector<WordSplit> word_splits;
  std::vector<MatrixSplit> matrix_splits;
  for (size_t i = 0; i < module.globals.size(); ++i) {
    const ir::VarPtr& v = module.globals[i];
    bool interface = v->storage == ir::Storage::In || v->storage == ir::Storage::Out ||
                     v->storage == ir::Storage::Uniform || v->storage == ir::Storage::Buffer;
    if (interface && v->type.base != ir::Base::Block) {
      InterfaceVariable entry;
      entry.name = v->name;
      if (auto it = ctx.flattened_blocks.find(v.get()); it != ctx.flattened_blocks.end()) entry.block = it->second;
      entry.storage = storage_name(v->storage, module.stage, es100);
      entry.type = ir::type_name(v->declared_type) + ir::array_suffix(v->declared_type);
      const auto default_value = ctx.uniform_defaults.find(v.get());
      if (default_value != ctx.uniform_defaults.end()) entry.default_value = default_value->second;
      if (ctx.exact_struct_uniforms.count(v.get())) {
        // Mode exact: a struct uniform's twin (exact_blocks.cpp): every double member a uvec2/uvec4
        // word leaf, "s.m", "s.v_xy", "s.q[1].zw"; padding members are not listed.
        entry.split = true;
        entry.encoding = exact_io::kEncoding;
        entry.lowered_type = ir::type_name(v->type) + ir::array_suffix(v->type);
        std::vector<std::string> leaves;
        uniform_leaves(v->type, v->name, leaves);
        for (const std::string& leaf : leaves) {
          if (leaf.find("ex_pad") != std::string::npos) continue;
          entry.lowered_names.push_back(leaf);
        }
        manifest.variables.push_back(entry);
      } else if (v->storage == ir::Storage::Uniform && !v->declared_type.is_double() && v->type.base == ir::Base::Struct &&
          holds_doubles(v->type)) {
        // A struct uniform keeps its name; its double members are df_* structs, so the host sets
        // "s.member.hi" and "s.member.lo": list those leaf names.
        entry.split = true;
        entry.lowered_type = ir::type_name(v->type) + ir::array_suffix(v->type);
        uniform_leaves(v->type, v->name, entry.lowered_names);
        manifest.variables.push_back(entry);
      } else if (!v->declared_type.is_double() || v->type.base != ir::Base::Struct) {
        // Not a double, or a double kept as one value: demoted to float (mode fp32) or kept
        // double (mode native).
        entry.lowered_type = ir::type_name(v->type) + ir::array_suffix(v->type);
        entry.lowered_names = {v->name};
        if (v->layout.location >= 0) entry.locations = {v->layout.location};
        manifest.variables.push_back(entry);
      } else if (v->declared_type.is_array() && std::any_of(v->declared_type.array_dims.begin(),
                                                             v->declared_type.array_dims.end(),
                                                             [](int d) { return d <= 0; })) {
        ctx.error(v->loc, "unsized arrays of doubles cannot be split into hi/lo interface variables");
      } else if (ctx.config.binary64_words() && v->declared_type.is_matrix()) {
        // lower_doubles let only loose uniforms through (in/out matrices are diagnosed there).
        matrix_splits.push_back(split_matrix_uniform(v, ctx, names, entry));
        globals.push_back(matrix_splits.back().words);
        inits.push_back(nullptr);
        manifest.variables.push_back(entry);
        v->storage = ir::Storage::Global;  // the private df_dmat value the shader body uses
        v->layout = {};
      } else if (ctx.config.binary64_words()) {
        WordSplit s = split_into_words(v, module.stage, ctx, names, entry, locations);
        for (const auto& part : s.parts) {
          globals.push_back(part);
          inits.push_back(nullptr);
        }
        manifest.variables.push_back(entry);
        v->storage = ir::Storage::Global;  // the private df_* value the shader body uses
        v->layout = {};
        v->interp = ir::Interp::Default;
        v->invariant = false;
        word_splits.push_back(s);
      } else {
        if (v->storage == ir::Storage::In && module.stage == ir::StageKind::Fragment && v->interp != ir::Interp::Flat)
          ctx.warning(v->loc, "'" + v->name + "' is a smooth double varying: hi and lo are interpolated separately "
                              "in float, so it carries only float precision; declare it flat");
        Split s;
        s.original = v;
        s.storage = v->storage;
        for (int half = 0; half < 2; ++half) {
          auto part = std::make_shared<ir::Var>(*v);
          part->name = ir::join_identifier(v->name, half == 0 ? ctx.config.hi_suffix : ctx.config.lo_suffix);
          part->type = v->declared_type.with_base(ir::Base::Float);
          part->declared_type = part->type;
          check_generated_name(*v, part->name, half == 0, ctx, names);
          if (half == 1 && v->layout.location >= 0) {
            part->layout.location = next_location[v->storage];
            next_location[v->storage] +=
                (v->type.is_array() ? v->type.array_dims[0] : 1) * std::max(v->declared_type.cols, 1);
          }
          (half == 0 ? s.hi : s.lo) = part;
          globals.push_back(part);
          // A kept initializer (uniform_defaults: desktop targets) initialises both words.
          inits.push_back(module.global_inits[i] && default_value != ctx.uniform_defaults.end()
                              ? split_constant(default_value->second, part->type, half, v->loc)
                              : nullptr);
          entry.lowered_names.push_back(part->name);
          if (part->layout.location >= 0) entry.locations.push_back(part->layout.location);
        }
        entry.split = true;
        entry.lowered_type = ir::type_name(s.hi->type) + ir::array_suffix(s.hi->type);
        manifest.variables.push_back(entry);
        v->storage = ir::Storage::Global;  // the private df_* copy the shader body uses
        v->layout = {};
        v->interp = ir::Interp::Default;
        v->invariant = false;
        splits.push_back(s);
      }
    }
    if (interface && v->type.base == ir::Base::Block && (holds_doubles(v->type) || ctx.exact_block_members.count(v.get()))) {
      InterfaceVariable entry;
      entry.name = v->name.rfind("anon@", 0) == 0 ? v->type.name : v->name;
      entry.storage = storage_name(v->storage, module.stage, es100);
      entry.type = v->type.name;
      entry.split = true;
      entry.lowered_type = v->type.name;
      entry.lowered_names = {entry.name};
      if (v->storage == ir::Storage::Uniform || v->storage == ir::Storage::Buffer) {  // in/out blocks have no layout
        entry.layout = v->layout.packing;
        if (auto words = ctx.exact_block_members.find(v.get()); words != ctx.exact_block_members.end()) {
          entry.members = words->second;  // mode exact: the original offsets, words in place of doubles
          entry.encoding = exact_io::kEncoding;
        } else {
          entry.members = block_layout(v->type, v->layout.packing);
        }
      }
      manifest.variables.push_back(entry);
    }
    globals.push_back(v);
    inits.push_back(module.global_inits[i]);
  }
  module.globals = globals;
  module.global_inits = inits;
  if (splits.empty() && word_splits.empty() && matrix_splits.empty()) return !ctx.failed;

  auto main = std::find_if(module.functions.begin(), module.functions.end(),
                           [](const ir::FunctionPtr& f) { return f->name == "main"; });
  if (main == module.functions.end()) {
    ctx.error({}, "the shader has no main function");
    return false;
  }
  std::vector<ir::StmtPtr> copy_in, copy_out;
  if (!tessellation_control_outputs_are_own(module, splits, word_splits, ctx)) return false;
  // A tessellation control shader writes only its own vertex of a per-vertex output.
  auto own_vertex = [&](const ir::Var& v, bool out) {
    return out && module.stage == ir::StageKind::TessControl && v.type.is_array() && !v.patch;
  };
  auto elements = [&](const ExprPtr& whole, bool own, std::vector<ExprPtr>& into) {
    if (own) return into.push_back(index_by_invocation(whole));
    for_each_element(whole, [&](const ExprPtr& e) { into.push_back(e); });
  };
  std::vector<PatchOutput> patch_outputs;
  patch_outputs.reserve(splits.size() + word_splits.size());  // lists_for's pointers stay valid
  // Where an output's stores and an input's joins go: a per-patch output of a control shader has
  // its own lists (PatchOutput), whose joins also read it back at main's start.
  auto lists_for = [&](const ir::VarPtr& v, bool out) -> std::pair<std::vector<ir::StmtPtr>*, std::vector<ir::StmtPtr>*> {
    if (!(out && module.stage == ir::StageKind::TessControl && v->patch)) return {&copy_in, &copy_out};
    patch_outputs.push_back({v.get(), {}, {}});
    return {&patch_outputs.back().copy_in, &patch_outputs.back().copy_out};
  };
  for (const auto& s : splits) {
    bool out = s.storage == ir::Storage::Out;
    const bool own = own_vertex(*s.original, out);
    auto [ins, outs] = lists_for(s.original, out);
    const bool patch = ins != &copy_in;
    ExprPtr whole = ir::make_sym(s.original), hi = ir::make_sym(s.hi), lo = ir::make_sym(s.lo);
    std::vector<ExprPtr> elems_df, elems_hi, elems_lo;
    elements(whole, own, elems_df);
    elements(hi, own, elems_hi);
    elements(lo, own, elems_lo);
    for (size_t k = 0; k < elems_df.size(); ++k) {
      const ir::Type& ft = elems_hi[k]->type;
      if (out) {
        outs->push_back(assign(elems_hi[k], member(elems_df[k], "hi", ft)));
        outs->push_back(assign(elems_lo[k], member(elems_df[k], "lo", ft)));
      }
      if (!out || patch) {
        auto join = Expr::make(Kind::Construct, elems_df[k]->type);
        join->args = {elems_hi[k], elems_lo[k]};
        if (s.storage == ir::Storage::Uniform && ctx.config.reads_uniforms_through_guard()) {
          for (auto& word : join->args) word = less_guard(word, ctx.config);
          ctx.guard_read_outside_rules = true;
        }
        ins->push_back(assign(elems_df[k], join));
      }
    }
  }
  for (const auto& s : word_splits) {
    std::vector<ExprPtr> elems_df;
    const bool out = s.storage == ir::Storage::Out;
    const bool own = own_vertex(*s.original, out);
    auto [ins, outs] = lists_for(s.original, out);
    const bool patch = ins != &copy_in;
    elements(ir::make_sym(s.original), own, elems_df);
    std::vector<std::vector<ExprPtr>> elems_parts(s.parts.size());
    for (size_t k = 0; k < s.parts.size(); ++k) elements(ir::make_sym(s.parts[k]), own, elems_parts[k]);
    for (size_t i = 0; i < elems_df.size(); ++i) {
      if (out)
        for (size_t k = 0; k < s.parts.size(); ++k)
          outs->push_back(assign(elems_parts[k][i], exact_io::words_of(elems_df[i], s.width, static_cast<int>(k))));
      if (!out || patch) {
        std::vector<ExprPtr> words;
        for (const auto& p : elems_parts) words.push_back(p[i]);
        ins->push_back(assign(elems_df[i], exact_io::value_of(words, s.width)));
      }
    }
  }
  for (const auto& s : matrix_splits) {
    std::vector<ExprPtr> elems_df;
    for_each_element(ir::make_sym(s.original), [&](const ExprPtr& e) { elems_df.push_back(e); });
    for (size_t e = 0; e < elems_df.size(); ++e)
      copy_in.push_back(assign(elems_df[e], matrix_value(s, static_cast<int>(e) * s.cols * s.rows)));
  }
  auto& body = (*main)->body->body;
  std::vector<ir::StmtPtr> patch_copy_in;
  for (const PatchOutput& p : patch_outputs) {
    for (const auto& f : module.functions) add_copy_out_after_writes(f->body, p, module, ctx);
    patch_copy_in.insert(patch_copy_in.end(), p.copy_in.begin(), p.copy_in.end());
  }
  add_copy_in_after_barriers((*main)->body, patch_copy_in);
  body.insert(body.begin(), patch_copy_in.begin(), patch_copy_in.end());
  body.insert(body.begin(), copy_in.begin(), copy_in.end());
  if (module.stage == ir::StageKind::Geometry) {
    for (const auto& f : module.functions) add_copy_out_before_emits(f->body, copy_out);
    return !ctx.failed;
  }
  add_copy_out((*main)->body, copy_out);
  if (body.empty() || body.back()->kind != ir::Stmt::Kind::Return)
    body.insert(body.end(), copy_out.begin(), copy_out.end());
  return !ctx.failed;
}

}  // namespace doublet::passes
