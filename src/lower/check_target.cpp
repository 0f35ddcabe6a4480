// check_target: constructs the lowered shader would need but the target language lacks are
// diagnosed here, by construct and target, instead of surfacing as "the lowered shader is not
// valid GLSL" from the re-validation. Runs last, on the lowered IR.
//
// GLSL ES 1.00 (The OpenGL ES Shading Language 1.00.17, 2009): no unsigned integers, no bitwise
// or % operators, no switch, no array constructors, varyings and attributes of float types only
// (section 4.3.5); Appendix A makes while/do-while loops and indexing other than by
// constant-index-expressions optional, so those are warnings.
//
// Every target: opaque types the target's language lacks (sampler1D, sampler2DRect and
// samplerBuffer on ES, images and atomic_uint before ES 3.10 / desktop 4.20, ...) and storage
// blocks before ES 3.10 / desktop 4.30. Which opaque types a target has is asked of glslang (a
// one-line declaration parsed in the target's profile, cached), so the answer follows the specs
// glslang implements instead of a table kept here.
#include <map>
#include <mutex>
#include <set>

#include "target/glslang_checks.hpp"
#include "target/target.hpp"
#include "ir/walk.hpp"
#include "lower/lower.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using Kind = ir::Expr::Kind;

bool float_based(const ir::Type& t) { return t.base == ir::Base::Float; }

class Es100Checker {
 public:
  Es100Checker(const ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  void run() {
    for (const auto& g : module_.globals) {
      check_type(g->type, g->loc);
      bool interface = g->storage == ir::Storage::In || g->storage == ir::Storage::Out;
      if (interface && !float_based(g->type))
        ctx_.error(g->loc, "'" + g->name + "' is " +
                               (module_.stage == ir::StageKind::Vertex && g->storage == ir::Storage::In ? "an attribute"
                                                                                                      : "a varying") + " of type " + ir::type_name(g->type) +
                               ": GLSL ES 1.00 allows only float, vecN and matN there; pass it as a float or target "
                               "es300");
      if (g->type.base == ir::Base::Block)
        ctx_.error(g->loc, "interface block '" + g->type.name + "' is not available on es100; use loose uniforms or "
                                                                 "target es300 (uniform blocks) / es310 (storage blocks)");
    }
    for (size_t i = 0; i < module_.globals.size(); ++i)
      if (module_.global_inits[i]) check_expr(module_.global_inits[i]);
    for (const auto& f : module_.functions) {
      check_type(f->return_type, f->loc);
      for (const auto& p : f->params) check_type(p->type, p->loc);
      check_stmt(f->body, {});
    }
  }

 private:
  void once(const std::string& key, ir::Loc loc, const std::string& message, bool error = true) {
    if (!reported_.insert(key).second) return;
    if (error) ctx_.error(loc, message);
    else ctx_.warning(loc, message);
  }

  void check_type(const ir::Type& t, ir::Loc loc) {
    if (t.base == ir::Base::Uint)
      once("uint", loc, "unsigned integers (" + ir::type_name(t) + ") are not available on es100; use int or target es300");
  }

  // A constant-index-expression (Appendix A): constants and for-loop indices, combined.
  bool constant_index(const ir::ExprPtr& e, const std::set<const ir::Var*>& loop_indices) {
    switch (e->kind) {
      case Kind::Const: return true;
      case Kind::Sym: return loop_indices.count(e->var.get()) || e->var->storage == ir::Storage::Const;
      case Kind::Unary:
      case Kind::Binary:
      case Kind::Construct:
      case Kind::Builtin:
        for (const auto& a : e->args)
          if (!constant_index(a, loop_indices)) return false;
        return true;
      default: return false;
    }
  }

  void check_expr(const ir::ExprPtr& root, const std::set<const ir::Var*>& loop_indices = {}) {
    ir::visit(root, [&](const ir::ExprPtr& e) {
      check_type(e->type, e->loc);
      static const std::set<std::string> bitwise{"&", "|", "^", "<<", ">>", "~", "%", "&=", "|=", "^=", "<<=", ">>=", "%="};
      if ((e->kind == Kind::Binary || e->kind == Kind::Unary) && bitwise.count(e->op))
        once("op" + e->op, e->loc, "the operator '" + e->op + "' is not available on es100 (GLSL ES 1.00 has no bitwise "
                                   "or % operators); use mod()/arithmetic or target es300");
      if (e->kind == Kind::Construct && e->type.is_array())
        once("array-ctor", e->loc, "array constructors (including initialised or constant arrays of doubles) are not "
                                   "available on es100; assign the elements one by one or target es300");
      if (e->kind == Kind::Index && e->args[0]->type.is_array() && !constant_index(e->args[1], loop_indices)) {
        const ir::ExprPtr& base = e->args[0];
        bool uniform_in_vertex = base->kind == Kind::Sym && base->var->storage == ir::Storage::Uniform &&
                                 module_.stage == ir::StageKind::Vertex;
        if (!uniform_in_vertex)
          once("index", e->loc, "indexing an array by a value that is not a constant or a for-loop index is optional "
                                "on es100 (GLSL ES 1.00 Appendix A); some drivers reject it. Target es300 to rely on it",
               false);
      }
    });
  }

  void check_stmt(const ir::StmtPtr& s, std::set<const ir::Var*> loop_indices) {
    if (!s) return;
    switch (s->kind) {
      case ir::Stmt::Kind::Switch:
        once("switch", s->loc, "switch statements are not available on es100; use if/else or target es300");
        break;
      case ir::Stmt::Kind::Loop:
        if (!s->test_first || (!s->body[0] && !s->step))
          once("while", s->loc, "while and do-while loops are optional on es100 (GLSL ES 1.00 Appendix A); some drivers "
                                "reject them. Use a for loop with a constant bound, or target es300", false);
        if (s->body[0] && s->body[0]->kind == ir::Stmt::Kind::Decl) {
          loop_indices.insert(s->body[0]->var.get());
          if (s->body[0]->var->declared_type.is_double())
            once("double loop index", s->loc, "a double loop index becomes a float-float pair (" +
                                                  ir::type_name(s->body[0]->var->type) + "), and GLSL ES 1.00 "
                                                  "Appendix A only guarantees int and float loop indices; some "
                                                  "drivers reject it. Count with an int and compute the double from "
                                                  "it, or target es300", false);
        }
        break;
      case ir::Stmt::Kind::Decl: check_type(s->var->type, s->loc); break;
      default: break;
    }
    if (s->expr) check_expr(s->expr, loop_indices);
    if (s->step) check_expr(s->step, loop_indices);
    for (const auto& b : s->body) check_stmt(b, loop_indices);
  }

  const ir::Module& module_;
  Context& ctx_;
  std::set<std::string> reported_;
};

// How to do without a desktop-only opaque type on ES, where there is a usual way.
std::string replacement_hint(const std::string& name) {
  if (name.find("1D") != std::string::npos) return "a 1D texture can be a 2D one of height 1 (sampler2D, y = 0.5)";
  if (name.find("2DRect") != std::string::npos) return "use sampler2D with coordinates divided by the texture size";
  if (name.find("Buffer") != std::string::npos) return "store the data in a 2D texture or a storage buffer";
  if (name == "atomic_uint") return "count with atomicAdd on a uint in a storage buffer";
  return "";
}

class TypeAvailabilityChecker {
 public:
  TypeAvailabilityChecker(const ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  void run() {
    const Target target = ctx_.config.target;
    const std::string target_name = ctx_.config.target_name();
    for (const auto& g : module_.globals) {
      if (g->type.base == ir::Base::Opaque && !target::opaque_type_exists(g->type.name, target)) {
        std::string elsewhere;
        for (Target t : target::all_targets(false))
          if (target::opaque_type_exists(g->type.name, t)) elsewhere += (elsewhere.empty() ? "" : ", ") + std::string(to_string(t));
        std::string hint = replacement_hint(g->type.name);
        ctx_.error(g->loc, "'" + g->name + "' has the type " + g->type.name + ", which " + target_name +
                               " does not have; " + (hint.empty() ? "" : hint + ", or ") +
                               (elsewhere.empty() ? "no target of doublet has it" : "target " + elsewhere));
      }
      const bool storage_blocks = ctx_.config.facts->storage_blocks;
      if (g->type.base == ir::Base::Block && g->storage == ir::Storage::Buffer && !storage_blocks &&
          target != Target::Es100)  // es100: Es100Checker refuses every block
        ctx_.error(g->loc, "storage block '" + g->type.name + "' (buffer) is not available on " + target_name +
                               ": storage blocks need GLSL ES 3.10 or desktop 4.30; use a uniform block if the "
                               "shader only reads it, or target es310, es320 or glsl450");
    }
  }

 private:
  const ir::Module& module_;
  Context& ctx_;
};

// WebGL 2.0 on top of ES 3.00: the user's names (reserved webgl_ / _webgl_ prefixes, at most
// the target table's max_identifier_length characters), and no ternary on a struct or an array left over
// by select_structs.
class WebglChecker {
 public:
  WebglChecker(const ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  void run() {
    for (const auto& t : module_.structs) check_type_name(t, {});
    for (const auto& g : module_.globals) check_name(g->name, g->loc);
    for (size_t i = 0; i < module_.globals.size(); ++i)
      if (module_.global_inits[i]) check_expr(module_.global_inits[i]);
    for (const auto& f : module_.functions) {
      check_name(f->name, f->loc);
      for (const auto& p : f->params) check_name(p->name, p->loc);
      check_stmt(f->body);
    }
  }

 private:
  void check_name(const std::string& name, ir::Loc loc) {
    if (name.rfind("gl_", 0) == 0 || !reported_.insert(name).second) return;
    if (name.rfind("webgl_", 0) == 0 || name.rfind("_webgl_", 0) == 0)
      ctx_.error(loc, "'" + name + "': WebGL reserves identifiers beginning with webgl_ and _webgl_; rename it");
    else if (name.size() > ctx_.config.facts->max_identifier_length)
      ctx_.error(loc, "'" + name.substr(0, 32) + "...' has " + std::to_string(name.size()) +
                          " characters: WebGL 2.0 allows identifiers of at most " +
                          std::to_string(ctx_.config.facts->max_identifier_length) + "; shorten it");
  }

  void check_type_name(const ir::Type& t, ir::Loc loc) {
    check_name(t.name, loc);
    if (t.fields)
      for (const auto& f : *t.fields) check_name(f.name, loc);
  }

  void check_expr(const ir::ExprPtr& root) {
    ir::visit(root, [&](const ir::ExprPtr& e) {
      if (e->kind == Kind::Ternary && (e->type.base == ir::Base::Struct || e->type.is_array()))
        ctx_.error(e->loc, "internal error: a ternary on " + ir::type_name(e->type) +
                               " is left for webgl2, which forbids it (please report this with the input)");
    });
  }

  void check_stmt(const ir::StmtPtr& s) {
    if (!s) return;
    if (s->kind == ir::Stmt::Kind::Decl) check_name(s->var->name, s->loc);
    if (s->expr) check_expr(s->expr);
    if (s->step) check_expr(s->step);
    for (const auto& b : s->body) check_stmt(b);
  }

  const ir::Module& module_;
  Context& ctx_;
  std::set<std::string> reported_;
};

}  // namespace

bool check_target(const ir::Module& module, Context& context) {
  TypeAvailabilityChecker(module, context).run();
  if (!context.config.facts->uint_and_bit_ops) Es100Checker(module, context).run();
  if (context.config.facts->webgl_rules) WebglChecker(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
