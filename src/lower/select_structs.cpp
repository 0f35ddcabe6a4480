// select_structs: on webgl2, every `c ? a : b` whose value is a struct (df_double, df_dvecN,
// df_dmatCxR, a user struct) becomes a selection through a temporary, because WebGL forbids the
// ternary operator on structures (ANGLE: "'?:' : ternary operator is not allowed for structures
// in ESSL 1.0 and webgl"; docs/web.md records it rejecting doublet's es300 output).
// On every other target only a struct ternary with an operand read from a uniform or buffer
// block is rewritten: glslang 12 compiles `c ? df_double(...) : block_member` to an OpSelect
// whose operands have two different struct types (the block's, with offsets, and the
// function's), which spirv-val rejects, so such a shader could not be compiled for Vulkan
// (found by the differential tester; docs/robustness.md, "Differential testing").
//
//   c ? a : b   →   (c ? (tmp = a, true) : (tmp = b, true), tmp)
//
// The rewritten expression keeps GLSL's semantics exactly (GLSL ES 3.00 §5.7, §5.9): the
// condition is evaluated first, then only the chosen operand, and the whole is still one
// expression, so it stays correct wherever the ternary was: in a loop condition or step, in the
// right operand of && or ||, inside another ternary's operand (the inner one is rewritten first).
// `tmp` is a local declared, uninitialised, at the top of the enclosing function.
// When the condition is a constant the chosen operand replaces the ternary.
//
// ANGLE (the compiler behind Chromium's WebGL) also refuses the sequence operator on arrays and
// on structs that contain arrays, so a ternary of such a type is rewritten only where it is a whole
// declaration initialiser or a whole assignment's right side (`T x = c ? a : b;` becomes
// `T x; if (c) x = a; else x = b;`); elsewhere it is diagnosed at its position.
#include <string>
#include <vector>

#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using Kind = ir::Expr::Kind;

bool holds_array(const ir::Type& t) {
  if (t.is_array()) return true;
  if ((t.base == ir::Base::Struct) && t.fields)
    for (const auto& f : *t.fields)
      if (holds_array(f.type)) return true;
  return false;
}

bool is_struct_ternary(const ir::ExprPtr& e) {
  return e->kind == Kind::Ternary && (e->type.base == ir::Base::Struct || e->type.is_array());
}

// True when `e` reads (through members and indices) a variable of a uniform or buffer block.
bool reads_block(const ir::ExprPtr& e) {
  const ir::Var* v = ir::root_variable(e);
  return v && (v->storage == ir::Storage::Uniform || v->storage == ir::Storage::Buffer);
}

bool constant_condition(const ir::ExprPtr& c, bool& value) {
  if (c->kind != Kind::Const || c->type.base != ir::Base::Bool || c->type.vec != 1 || c->values.size() != 1)
    return false;
  value = c->values[0].b;
  return true;
}

ir::ExprPtr bool_true(ir::Loc loc) {
  auto e = Expr::make(Kind::Const, ir::scalar_type(ir::Base::Bool), loc);
  ir::Scalar s;
  s.base = ir::Base::Bool;
  s.b = true;
  e->values.push_back(s);
  return e;
}

class StructSelectRewriter {
 public:
  StructSelectRewriter(ir::Module& m, Context& c) : module_(m), ctx_(c), every_struct_(c.config.facts->webgl_rules) {}

  void run() {
    for (size_t i = 0; i < module_.globals.size(); ++i)
      if (module_.global_inits[i]) module_.global_inits[i] = rewrite_global(module_.global_inits[i]);
    rewrite_functions_with_temporaries(module_, temporaries_, [&](const ir::StmtPtr& body) { rewrite_block(body); });
  }

 private:
  // Global initialisers left at global scope are constant expressions (move_global_initialisers
  // moved the others into main): a constant condition folds; anything else cannot be written.
  ir::ExprPtr rewrite_global(const ir::ExprPtr& init) {
    return ir::rewrite(init, [&](const ir::ExprPtr& e) -> ir::ExprPtr {
      if (!every_struct_ || !rewritten(e)) return nullptr;  // (a block read is no constant initialiser)
      bool value;
      if (constant_condition(e->args[0], value)) return value ? e->args[1] : e->args[2];
      ctx_.error(e->loc, "webgl2: WebGL has no ternary operator on structures, and this one is in a global "
                         "constant initialiser; select with if/else inside a function instead");
      return nullptr;
    });
  }

  void rewrite_block(const ir::StmtPtr& s) {
    if (!s) return;
    for (size_t i = 0; i < s->body.size(); ++i) {
      const ir::StmtPtr child = s->body[i];
      if (!child) continue;
      if (s->kind == ir::Stmt::Kind::Block) {
        std::vector<ir::StmtPtr> replacement = split_whole_selection(child);
        if (!replacement.empty()) {
          s->body.erase(s->body.begin() + static_cast<long>(i));
          s->body.insert(s->body.begin() + static_cast<long>(i), replacement.begin(), replacement.end());
          i += replacement.size() - 1;
          continue;
        }
      }
      rewrite_block(child);
    }
    if (s->expr) s->expr = rewrite_expr(s->expr, s);
    if (s->step) s->step = rewrite_expr(s->step, s);
  }

  // `T x = c ? a : b;` and `x = c ? a : b;` (x pure), directly in a block, of an array type or a
  // struct holding one: the sequence operator cannot carry those, so the selection becomes
  // `T x; if (c) x = a; else x = b;`. Empty when `s` is not such a statement.
  std::vector<ir::StmtPtr> split_whole_selection(const ir::StmtPtr& s) {
    const ir::ExprPtr& e = s->expr;
    if (!e) return {};
    ir::ExprPtr selection;
    ir::ExprPtr target;
    if (s->kind == ir::Stmt::Kind::Decl && rewritten(e) && holds_array(e->type)) {
      selection = e;
      target = ir::make_sym(s->var, s->loc);
    } else if (s->kind == ir::Stmt::Kind::Expr && e->kind == Kind::Binary && e->op == "=" &&
               rewritten(e->args[1]) && holds_array(e->args[1]->type) && ir::is_pure(e->args[0])) {
      selection = e->args[1];
      target = e->args[0];
    } else {
      return {};
    }
    auto branch = [&](const ir::ExprPtr& value) {
      auto stmt = ir::make_statement(ir::make_assign(ir::clone(target), value));
      stmt->expr = rewrite_expr(stmt->expr, stmt);
      auto block = ir::Stmt::make(ir::Stmt::Kind::Block, value->loc);
      block->body = {stmt};
      return block;
    };
    auto choose = ir::Stmt::make(ir::Stmt::Kind::If, s->loc);
    choose->expr = rewrite_expr(selection->args[0], s);
    choose->body = {branch(selection->args[1]), branch(selection->args[2])};
    if (s->kind != ir::Stmt::Kind::Decl) return {choose};
    if (s->var->storage == ir::Storage::Const) s->var->storage = ir::Storage::Local;
    auto declaration = ir::Stmt::make(ir::Stmt::Kind::Decl, s->loc);
    declaration->var = s->var;
    return {declaration, choose};
  }

  ir::ExprPtr rewrite_expr(const ir::ExprPtr& root, const ir::StmtPtr& owner) {
    bool comma_used = false;
    ir::ExprPtr result = ir::rewrite(root, [&](const ir::ExprPtr& e) -> ir::ExprPtr {
      if (!rewritten(e)) return nullptr;
      bool value;
      if (constant_condition(e->args[0], value)) return value ? e->args[1] : e->args[2];
      if (holds_array(e->type)) {
        if (!every_struct_) return nullptr;  // only WebGL lacks the sequence operator's way around
        ctx_.error(e->loc, "webgl2: WebGL allows neither the ternary operator nor the sequence operator on " +
                               std::string(e->type.is_array() ? "arrays" : "structures that contain arrays") +
                               " (" + ir::type_name(e->type) + ir::array_suffix(e->type) +
                               "); make this selection a whole declaration or assignment (T x = c ? a : b;), or "
                               "use if/else");
        return nullptr;
      }
      ir::VarPtr tmp = declare_temporary("df_select" + std::to_string(++counter_), e->type, e->loc, temporaries_);
      auto chosen = [&](const ir::ExprPtr& operand) {
        auto store = ir::make_assign(ir::make_sym(tmp, operand->loc), operand);
        return ir::make_node(Kind::Comma, "", ir::scalar_type(ir::Base::Bool), {store, bool_true(e->loc)},
                             e->loc);
      };
      auto select = ir::make_node(Kind::Ternary, "", ir::scalar_type(ir::Base::Bool),
                                  {e->args[0], chosen(e->args[1]), chosen(e->args[2])}, e->loc);
      comma_used = true;
      return ir::make_node(Kind::Comma, "", e->type, {select, ir::make_sym(tmp, e->loc)}, e->loc);
    });
    // A constant initialised by a sequence is no longer a constant expression.
    if (comma_used && owner && owner->kind == ir::Stmt::Kind::Decl && owner->var &&
        owner->var->storage == ir::Storage::Const && owner->expr == root)
      owner->var->storage = ir::Storage::Local;
    return result;
  }

  // The ternaries this target needs rewritten: every struct one (WebGL), or those reading a block.
  bool rewritten(const ir::ExprPtr& e) const {
    return is_struct_ternary(e) && (every_struct_ || reads_block(e->args[1]) || reads_block(e->args[2]));
  }

  ir::Module& module_;
  Context& ctx_;
  const bool every_struct_;
  std::vector<ir::StmtPtr> temporaries_;
  int counter_ = 0;
};

}  // namespace

bool select_structs(ir::Module& module, Context& context) {
  StructSelectRewriter(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
