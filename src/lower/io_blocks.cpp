// flatten_io_blocks: on targets without in/out interface blocks (ES 1.00, ES 3.00, and ES 3.10
// without GL_EXT_shader_io_blocks) every in/out block becomes one plain in/out variable per
// member, named BLOCK_MEMBER after the block's name (not its instance name), which GLSL requires
// to match across stages (GLSL ES 3.20 §4.3.9), so a vertex and a fragment shader lowered
// separately still match. Members keep their interpolation qualifiers and explicit locations;
// a block with an explicit location gives its members consecutive ones, as GLSL assigns them.
// The manifest names each variable's block (InterfaceVariable::block). Runs right after import,
// so the flattened double members are split into _hi/_lo like any other double varying.
#include <algorithm>
#include <map>
#include <set>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using Kind = ir::Expr::Kind;

bool is_io_block(const ir::Var& v) {
  return v.type.base == ir::Base::Block && (v.storage == ir::Storage::In || v.storage == ir::Storage::Out);
}


// Locations a member takes: dvec3/dvec4 take two, matrices one per column, arrays one per element.
int location_slots(const ir::Type& t) {
  int n = std::max(t.cols, 1) * (t.is_double() && t.vec > 2 ? 2 : 1);
  for (int d : t.array_dims) n *= std::max(d, 1);
  return n;
}

// One more than the largest variable id in the module, so new variables get ids of their own.
int next_free_id(const ir::Module& m) {
  int top = 0;
  auto see = [&](const ir::Var& v) { top = std::max(top, v.id); };
  for (const auto& g : m.globals) see(*g);
  for (const auto& f : m.functions) {
    for (const auto& p : f->params) see(*p);
    ir::visit(f->body, [&](const ir::ExprPtr& e) {
      if (e->kind == Kind::Sym) see(*e->var);
    });
  }
  return top + 1;
}

class Flattener {
 public:
  Flattener(ir::Module& m, Context& c) : module_(m), ctx_(c), next_id_(next_free_id(m)) {}

  void run() {
    std::set<std::string> taken;
    for (const auto& g : module_.globals) taken.insert(g->name);
    for (const auto& f : module_.functions) taken.insert(f->name);
    std::vector<ir::VarPtr> globals;
    std::vector<ir::ExprPtr> inits;
    for (size_t i = 0; i < module_.globals.size(); ++i) {
      const ir::VarPtr& g = module_.globals[i];
      if (!is_io_block(*g) || !flattenable(*g)) {
        globals.push_back(g);
        inits.push_back(module_.global_inits[i]);
        continue;
      }
      for (const ir::VarPtr& member : flatten(*g, taken)) {
        globals.push_back(member);
        inits.push_back(nullptr);
      }
    }
    module_.globals = std::move(globals);
    module_.global_inits = std::move(inits);
    if (members_.empty()) return;
    auto replace = [&](const ir::ExprPtr& e) -> ir::ExprPtr {
      if (e->kind == Kind::Member && e->args[0]->kind == Kind::Sym)  // instance.member
        if (auto it = members_.find({e->args[0]->var.get(), e->name}); it != members_.end())
          return ir::make_sym(it->second, e->loc);
      if (e->kind == Kind::Sym && e->var->block)  // a member of an anonymous block
        if (auto it = members_.find({e->var->block.get(), e->var->name}); it != members_.end())
          return ir::make_sym(it->second, e->loc);
      return nullptr;
    };
    for (auto& init : module_.global_inits) init = ir::rewrite(init, replace);
    for (const auto& f : module_.functions) ir::rewrite(f->body, replace);
  }

 private:
  bool flattenable(const ir::Var& block) {
    if (block.layout.passthrough) {  // a passthrough input must stay a block (or gl_PerVertex)
      ctx_.error(block.loc, "the passthrough input block '" + block.type.name +
                                "' (GL_NV_geometry_shader_passthrough) cannot be flattened into plain inputs for " +
                                ctx_.config.target_name() +
                                " (it has no in/out blocks); target es320 or glsl450");
      return false;
    }
    if (!block.type.is_array()) return true;
    ctx_.error(block.loc, "the " + std::string(block.storage == ir::Storage::In ? "input" : "output") + " block '" +
                              block.type.name + "' is an array, which cannot be flattened into plain varyings for " +
                              ctx_.config.target_name() +
                              " (it has no in/out blocks); declare one block per element, or target es320 or glsl330+");
    return false;
  }

  std::vector<ir::VarPtr> flatten(const ir::Var& block, std::set<std::string>& taken) {
    std::vector<ir::VarPtr> out;
    int next_location = block.layout.location;
    for (const ir::Field& f : *block.type.fields) {
      auto v = std::make_shared<ir::Var>();
      v->id = next_id_++;
      v->name = block.type.name + "_" + f.name;
      if (!taken.insert(v->name).second)
        ctx_.error(block.loc, "flattening the block '" + block.type.name + "' for " +
                                  ctx_.config.target_name() + " needs the name '" + v->name +
                                  "', which the shader already uses; rename it, or target es320 or glsl330+");
      v->type = f.type;
      v->declared_type = f.type;
      v->storage = block.storage;
      v->interp = f.interp != ir::Interp::Default ? f.interp : block.interp;
      v->invariant = block.invariant;
      v->precise = block.precise;
      v->loc = block.loc;
      if (f.layout.location >= 0) next_location = f.layout.location;
      if (next_location >= 0) {
        v->layout.location = next_location;
        next_location += location_slots(f.type);
      }
      ctx_.flattened_blocks[v.get()] = block.type.name;
      members_[{&block, f.name}] = v;
      out.push_back(v);
    }
    return out;
  }

  ir::Module& module_;
  Context& ctx_;
  int next_id_;
  std::map<std::pair<const ir::Var*, std::string>, ir::VarPtr> members_;  // (block, member) → variable
};

}  // namespace

bool flatten_io_blocks(ir::Module& module, Context& ctx) {
  if (ctx.config.facts->io_blocks) return true;
  Flattener(module, ctx).run();
  return !ctx.failed;
}

}  // namespace doublet::passes
