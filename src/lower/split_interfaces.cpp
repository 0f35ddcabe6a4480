// split_interfaces: a double `in`/`out`/`uniform` X becomes two variables of the
// same-shaped float type, X_hi then X_lo. X itself stays as a private df_*
// global: inputs are joined into it at the start of main, outputs are split
// out of it before every return from main. Runs after lower_doubles.
#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "lower/block_layout.hpp"
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

ExprPtr sym(const ir::VarPtr& v) {
  auto e = Expr::make(Kind::Sym, v->type, v->loc);
  e->var = v;
  return e;
}

ExprPtr index(const ExprPtr& base, int i) {
  auto c = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Int));
  ir::Scalar s;
  s.base = ir::Base::Int;
  s.i = i;
  c->values = {s};
  auto e = Expr::make(Kind::Index, base->type.element());
  e->args = {base, c};
  return e;
}

ExprPtr member(const ExprPtr& base, const std::string& name, const ir::Type& type) {
  auto e = Expr::make(Kind::Member, type);
  e->name = name;
  e->args = {base};
  return e;
}

ir::StmtPtr assign(const ExprPtr& lhs, const ExprPtr& rhs) {
  auto a = Expr::make(Kind::Binary, lhs->type);
  a->op = "=";
  a->args = {lhs, rhs};
  auto s = ir::Stmt::make(ir::Stmt::Kind::Expr);
  s->expr = a;
  return s;
}

// Element accessors for every array element (unrolled; arrays are sized).
void for_each_element(const ExprPtr& e, const std::function<void(const ExprPtr&)>& f) {
  if (!e->type.is_array()) return f(e);
  for (int i = 0; i < e->type.array_dims[0]; ++i) for_each_element(index(e, i), f);
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

void add_copy_out(const ir::StmtPtr& s, const std::vector<ir::StmtPtr>& copy_out) {
  for (size_t i = 0; i < s->body.size(); ++i) {
    auto& child = s->body[i];
    if (!child) continue;
    if (child->kind == ir::Stmt::Kind::Return) {
      auto block = ir::Stmt::make(ir::Stmt::Kind::Block, child->loc);
      block->body = copy_out;
      block->body.push_back(child);
      child = block;
    } else {
      add_copy_out(child, copy_out);
    }
  }
}

}  // namespace

bool split_interfaces(ir::Module& module, Context& ctx, Manifest& manifest) {
  const bool es100 = ctx.options.target == Target::Es100;
  std::set<std::string> names;
  for (const auto& g : module.globals) names.insert(g->name);
  for (const auto& f : module.functions) names.insert(f->name);

  // Next free location per storage class, for the _lo halves.
  std::map<ir::Storage, int> next_location;
  for (const auto& g : module.globals) {
    if (g->layout.location < 0) continue;
    int slots = (g->type.is_array() ? g->type.array_dims[0] : 1) * std::max(g->declared_type.cols, 1);
    if (g->declared_type.is_double() && g->declared_type.vec > 2) slots *= 2;  // dvec3/4 take two locations
    next_location[g->storage] = std::max(next_location[g->storage], g->layout.location + slots);
  }

  std::vector<ir::VarPtr> globals;
  std::vector<ExprPtr> inits;
  std::vector<Split> splits;
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
      if (v->storage == ir::Storage::Uniform && !v->declared_type.is_double() && v->type.base == ir::Base::Struct &&
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
      } else {
        if (v->storage == ir::Storage::In && module.stage == ir::StageKind::Fragment && v->interp != ir::Interp::Flat)
          ctx.warning(v->loc, "'" + v->name + "' is a smooth double varying: hi and lo are interpolated separately "
                              "in float, so it carries only float precision; declare it flat");
        Split s;
        s.original = v;
        s.storage = v->storage;
        for (int half = 0; half < 2; ++half) {
          auto part = std::make_shared<ir::Var>(*v);
          part->name = ir::join_identifier(v->name, half == 0 ? ctx.options.hi_suffix : ctx.options.lo_suffix);
          // Mode exact: X_hi/X_lo hold the high/low uint words of the binary64 pattern.
          part->type = v->declared_type.with_base(ctx.options.mode == Mode::Exact ? ir::Base::Uint : ir::Base::Float);
          part->declared_type = part->type;
          // Integer varyings must be flat (GLSL); a fragment shader's double input is flat already.
          const bool varying = (v->storage == ir::Storage::Out && module.stage == ir::StageKind::Vertex) ||
                               (v->storage == ir::Storage::In && module.stage == ir::StageKind::Fragment);
          if (ctx.options.mode == Mode::Exact && varying) part->interp = ir::Interp::Flat;
          if (part->name.find("__") != std::string::npos) {
            // GLSL reserves every name containing "__" and GLSL ES compilers reject them.
            if (half == 0 && v->name.find("__") != std::string::npos)
              ctx.error(v->loc, "'" + v->name + "' contains '__', which GLSL reserves, and so would its split "
                                "names ('" + part->name + "'); rename it");
            else if (v->name.find("__") == std::string::npos)
              ctx.error(v->loc, "splitting '" + v->name + "' makes '" + part->name + "', which contains '__' "
                                "(GLSL reserves it); choose a --hi-suffix/--lo-suffix without '__'");
          } else if (names.count(part->name))
            ctx.error(v->loc, "splitting '" + v->name + "' needs the name '" + part->name +
                                  "', which the shader already uses; rename it or change --hi-suffix/--lo-suffix");
          names.insert(part->name);
          if (half == 1 && v->layout.location >= 0) {
            part->layout.location = next_location[v->storage];
            next_location[v->storage] +=
                (v->type.is_array() ? v->type.array_dims[0] : 1) * std::max(v->declared_type.cols, 1);
          }
          (half == 0 ? s.hi : s.lo) = part;
          globals.push_back(part);
          inits.push_back(nullptr);
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
    if (interface && v->type.base == ir::Base::Block && holds_doubles(v->type)) {
      InterfaceVariable entry;
      entry.name = v->name.rfind("anon@", 0) == 0 ? v->type.name : v->name;
      entry.storage = storage_name(v->storage, module.stage, es100);
      entry.type = v->type.name;
      entry.split = true;
      entry.lowered_type = v->type.name;
      entry.lowered_names = {entry.name};
      if (v->storage == ir::Storage::Uniform || v->storage == ir::Storage::Buffer) {  // in/out blocks have no layout
        entry.layout = v->layout.packing;
        entry.members = block_layout(v->type, v->layout.packing);
      }
      manifest.variables.push_back(entry);
    }
    globals.push_back(v);
    inits.push_back(module.global_inits[i]);
  }
  module.globals = globals;
  module.global_inits = inits;
  if (splits.empty()) return !ctx.failed;

  auto main = std::find_if(module.functions.begin(), module.functions.end(),
                           [](const ir::FunctionPtr& f) { return f->name == "main"; });
  if (main == module.functions.end()) {
    ctx.error({}, "the shader has no main function");
    return false;
  }
  std::vector<ir::StmtPtr> copy_in, copy_out;
  for (const auto& s : splits) {
    bool out = s.storage == ir::Storage::Out;
    ExprPtr whole = sym(s.original), hi = sym(s.hi), lo = sym(s.lo);
    std::vector<ExprPtr> elems_df, elems_hi, elems_lo;
    for_each_element(whole, [&](const ExprPtr& e) { elems_df.push_back(e); });
    for_each_element(hi, [&](const ExprPtr& e) { elems_hi.push_back(e); });
    for_each_element(lo, [&](const ExprPtr& e) { elems_lo.push_back(e); });
    for (size_t k = 0; k < elems_df.size(); ++k) {
      const ir::Type& ft = elems_hi[k]->type;
      if (out) {
        copy_out.push_back(assign(elems_hi[k], member(elems_df[k], "hi", ft)));
        copy_out.push_back(assign(elems_lo[k], member(elems_df[k], "lo", ft)));
      } else {
        auto join = Expr::make(Kind::Construct, elems_df[k]->type);
        join->args = {elems_hi[k], elems_lo[k]};
        copy_in.push_back(assign(elems_df[k], join));
      }
    }
  }
  auto& body = (*main)->body->body;
  body.insert(body.begin(), copy_in.begin(), copy_in.end());
  add_copy_out((*main)->body, copy_out);
  if (body.empty() || body.back()->kind != ir::Stmt::Kind::Return)
    body.insert(body.end(), copy_out.begin(), copy_out.end());
  return !ctx.failed;
}

}  // namespace doublet::passes
