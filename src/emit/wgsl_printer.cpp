// WGSL printer (see wgsl_printer.hpp). The module's functions keep their GLSL shape; what WGSL
// spells differently is translated here, and what it cannot express is an error:
//  - overloaded functions get the parameter types in their names (WGSL has no overloading);
//  - out/inout parameters become ptr<function, T>, the argument `&x` (x a local variable);
//  - the user's main becomes df_main; the entry point `main` copies the stage inputs (built-ins
//    and @location inputs) into private variables, calls df_main and returns the outputs;
//  - loose uniforms (the guard df_guard included) become members of one uniform buffer,
//    df_uniforms, at the binding after the highest the shader uses (reported to the caller);
//  - float literals are printed exactly (decimal where it is exact, else a hexadecimal float), so
//    WGSL's implementation-chosen rounding of inexact literals never applies.
#include "emit/wgsl_printer.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "emit/wgsl_std140.hpp"
#include "ir/walk.hpp"

namespace doublet::emit {
namespace {

using ir::Base;
using ir::Expr;
using ir::Stmt;
using Kind = ir::Expr::Kind;

// WGSL keywords and reserved words that a GLSL identifier could be (W3C WGSL, 15.2-15.3).
const std::set<std::string>& wgsl_reserved() {
  static const std::set<std::string> words = {
      "alias", "bitcast", "break", "case", "const", "const_assert", "continue", "continuing", "default", "diagnostic",
      "discard", "else", "enable", "false", "fn", "for", "if", "let", "loop", "override", "requires", "return",
      "struct", "switch", "true", "var", "while", "array", "atomic", "bool", "f16", "f32", "i32", "u32", "mat2x2",
      "mat3x3", "mat4x4", "ptr", "sampler", "vec2", "vec3", "vec4", "NULL", "Self", "abstract", "active", "alignas",
      "alignof", "as", "asm", "async", "attribute", "auto", "await", "become", "cast", "catch", "class", "co_await",
      "co_return", "co_yield", "coherent", "column_major", "common", "compile", "compile_fragment", "concept",
      "const_cast", "consteval", "constexpr", "constinit", "crate", "debugger", "decltype", "delete", "demote",
      "demote_to_helper", "do", "dynamic_cast", "enum", "explicit", "export", "extends", "extern", "external",
      "fallthrough", "filter", "final", "finally", "friend", "from", "fxgroup", "get", "goto", "groupshared",
      "highp", "impl", "implements", "import", "inline", "instanceof", "interface", "layout", "lowp", "macro",
      "macro_rules", "match", "mediump", "meta", "mod", "module", "move", "mut", "mutable", "namespace", "new",
      "nil", "noexcept", "noinline", "nointerpolation", "non_coherent", "noncoherent", "noperspective", "null",
      "nullptr", "of", "operator", "package", "packoffset", "partition", "pass", "patch", "pixelfragment",
      "precise", "precision", "premerge", "priv", "protected", "pub", "public", "readonly", "ref", "regardless",
      "register", "reinterpret_cast", "require", "resource", "restrict", "self", "set", "shared", "sizeof",
      "smooth", "snorm", "static", "static_assert", "static_cast", "std", "subroutine", "super", "target",
      "template", "this", "thread_local", "throw", "trait", "try", "type", "typedef", "typeid", "typename",
      "typeof", "union", "unless", "unorm", "unsafe", "unsized", "use", "using", "varying", "virtual", "volatile",
      "wgsl", "where", "with", "writeonly", "yield", "main", "select", "all", "any"};
  return words;
}

std::string ident(const std::string& name) { return wgsl_reserved().count(name) ? name + "_" : name; }

// A float literal equal to `value` exactly. WGSL rounds an inexact literal in an implementation-
// chosen direction, so a decimal is used only where it reads back exactly as a double.
std::string f32_literal(float value) {
  char buf[64];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(value));
    if (std::strtod(buf, nullptr) == static_cast<double>(value)) {
      std::string s = buf;
      if (s.find_first_of(".e") == std::string::npos) s += ".0";
      return s + "f";
    }
  }
  std::snprintf(buf, sizeof buf, "%af", static_cast<double>(value));
  return buf;
}

class WgslPrinter {
 public:
  WgslPrinter(const ir::Module& m, const std::string& file, const std::string& note, const std::map<std::string, int>& groups)
      : m_(m), file_(file), note_(note), block_groups_(groups) {
    out_.imbue(std::locale::classic());
  }

  WgslPrintResult run() {
    collect_overloads();
    std140_ = plan_wgsl_std140(m_);
    for (const auto& r : std140_.refusals) error(r.loc, r.message);
    std140_wrappers();
    for (const auto& t : m_.structs) struct_definition(t);
    globals();
    for (const auto& f : m_.functions) function(*f);
    entry_point();
    std::string text = helpers_text();
    return {text + out_.str(), diags_, uniform_buffer_, block_bindings_};
  }

 private:
  const ir::Module& m_;
  std::string file_, note_;
  const std::map<std::string, int>& block_groups_;
  std::ostringstream out_;
  std::vector<Diagnostic> diags_;
  InterfaceVariable uniform_buffer_;
  std::vector<WgslPrintResult::BlockBinding> block_bindings_;
  std::map<std::string, int> overload_count_;
  std::set<const ir::Var*> loose_uniforms_, pointer_params_;
  // Loose uniform arrays of scalars or 2-vectors: WGSL's uniform buffers need a 16-byte element
  // stride, so each element is the first components of a vec4 (the swizzle that reads it).
  std::map<const ir::Var*, std::string> padded_uniform_arrays_;
  WgslStd140Plan std140_;
  std::map<const ir::Var*, std::string> block_var_names_;
  std::map<std::string, std::string> helpers_;  // name -> WGSL text, emitted before the module
  std::map<std::string, ir::Loc> builtins_used_;  // gl_* variables the functions name, first use

  // Where the shader first writes block `block` (an assignment, ++/--, an atomic or other built-in
  // with side effects whose first argument is in it); false when it only reads it.
  bool block_written(const ir::Var* block, ir::Loc& where) const {
    auto in_block = [&](const ir::ExprPtr& e) {
      const ir::Var* v = e ? ir::root_variable(e) : nullptr;
      return v && (v == block || v->block.get() == block);
    };
    bool written = false;
    for (const auto& f : m_.functions)
      ir::visit(f->body, [&](const ir::ExprPtr& e) {
        if (written || e->args.empty()) return;
        const bool writes = (e->kind == ir::Expr::Kind::Binary && ir::is_assignment_operator(e->op)) ||
                            (e->kind == ir::Expr::Kind::Unary &&
                             (e->op.find("++") != std::string::npos || e->op.find("--") != std::string::npos)) ||
                            (e->kind == ir::Expr::Kind::Builtin && ir::has_side_effects(e));
        if (writes && in_block(e->args[0])) {
          written = true;
          where = e->loc;
        }
      });
    return written;
  }

  void error(ir::Loc loc, const std::string& msg) {
    if (!diags_.empty() && diags_.back().line == loc.line && diags_.back().message.rfind(msg, 0) == 0) return;
    diags_.push_back({file_, loc.line, loc.column, Severity::Error, msg + note_});
  }

  // ---- types ---------------------------------------------------------------
  static std::string scalar_name(Base b) {
    switch (b) {
      case Base::Bool: return "bool";
      case Base::Int: return "i32";
      case Base::Uint: return "u32";
      default: return "f32";
    }
  }

  std::string type(const ir::Type& t, ir::Loc loc = {}) {
    if (t.is_array()) {
      ir::Type e = t.element();
      int n = t.array_dims[0];
      return "array<" + type(e, loc) + (n > 0 ? ", " + std::to_string(n) : "") + ">";
    }
    switch (t.base) {
      case Base::Struct:
      case Base::Block: return ident(t.name);
      case Base::Opaque:
        if (t.name == "atomic_uint")
          error(loc, "atomic counters ('atomic_uint') have no WGSL counterpart; use an atomic<u32> in a storage buffer");
        else if (t.name.find("image") != std::string::npos)
          error(loc, "'" + t.name + "' (a storage image) is not translated to WGSL by doublet yet");
        else
          error(loc, "'" + t.name + "' cannot be expressed in WGSL by doublet (WGSL separates textures and samplers, "
                     "and doublet's WGSL target does not translate them yet)");
        return "f32";
      case Base::Double: error(loc, "internal error: a double reached the WGSL printer"); return "f32";
      case Base::Void: return "";
      default: break;
    }
    const std::string s = scalar_name(t.base);
    if (t.is_matrix()) return "mat" + std::to_string(t.cols) + "x" + std::to_string(t.vec) + "<" + s + ">";
    if (t.vec > 1) return "vec" + std::to_string(t.vec) + "<" + s + ">";
    return s;
  }

  // ---- declarations --------------------------------------------------------
  // A struct or block; in a std140 block, with std140's offsets (wgsl_std140.hpp).
  void struct_definition(const ir::Type& t) {
    const auto std140 = std140_.members.find(t.name);
    out_ << "struct " << ident(t.name) << " {\n";
    for (const auto& f : *t.fields) {
      out_ << "  ";
      const Std140Member* m = nullptr;
      if (std140 != std140_.members.end())
        if (auto it = std140->second.find(f.name); it != std140->second.end()) m = &it->second;
      if (m && m->align) out_ << "@align(" << m->align << ") ";
      if (m && m->size) out_ << "@size(" << m->size << ") ";
      std::string declared = type(f.type);
      if (m && !m->wrapper.empty())
        declared = "array<" + m->wrapper + (f.type.array_dims[0] > 0 ? ", " + std::to_string(f.type.array_dims[0]) : "") + ">";
      out_ << ident(f.name) << ": " << declared << ",\n";
    }
    out_ << "}\n\n";
  }

  // std140's element stride for arrays WGSL would pack tighter: `a[i]` reads `a[i].v`.
  void std140_wrappers() {
    for (const Std140Wrapper& w : std140_.wrappers)
      out_ << "struct " << w.name << " {\n  @align(16) @size(" << w.stride << ") v: " << type(w.element) << ",\n}\n\n";
  }

  // The instance name of a block, "" for an anonymous one.
  static std::string anonymous_name(const ir::Var& v) { return v.name.rfind("anon@", 0) == 0 ? "" : v.name; }

  static bool is_loose_uniform(const ir::Var& v) {
    return v.storage == ir::Storage::Uniform && !v.block && v.type.base != Base::Block && v.type.base != Base::Opaque;
  }

  int group_of(const ir::Var& block) const {
    const auto found = block_groups_.find(block.type.name);
    return found == block_groups_.end() ? 0 : found->second;
  }

  // Explicit bindings first, per group (GL's uniform and storage blocks have separate binding
  // namespaces, a WGSL group has one: a clash is an error); blocks without one take the next free
  // numbers of their group in declaration order, and the loose-uniform buffer the one after group
  // 0's.
  std::map<const ir::Var*, int> assign_bindings(int& next_free) {
    std::map<const ir::Var*, int> assigned;
    std::map<int, std::set<int>> used;  // by group
    auto is_block = [](const ir::Var& v) {
      return (v.storage == ir::Storage::Uniform || v.storage == ir::Storage::Buffer) && v.type.base == Base::Block;
    };
    for (const auto& v : m_.globals)
      if (is_block(*v) && v->layout.binding >= 0) {
        if (!used[group_of(*v)].insert(v->layout.binding).second)
          error(v->loc, "binding " + std::to_string(v->layout.binding) + " of group " + std::to_string(group_of(*v)) +
                            " is used twice: WGSL has one binding namespace per group (GL's uniform and storage "
                            "blocks have two); give each block its own binding");
        assigned[v.get()] = v->layout.binding;
      }
    std::map<int, int> next;  // by group
    for (const auto& [group, bindings] : used) next[group] = bindings.empty() ? 0 : *bindings.rbegin() + 1;
    for (const auto& v : m_.globals)
      if (is_block(*v) && v->layout.binding < 0) assigned[v.get()] = next[group_of(*v)]++;
    next_free = next[0];
    return assigned;
  }

  void globals() {
    int uniform_binding = 0;
    const std::map<const ir::Var*, int> bindings_of = assign_bindings(uniform_binding);
    std::vector<ir::VarPtr> loose;
    for (size_t i = 0; i < m_.globals.size(); ++i) {
      const ir::VarPtr& v = m_.globals[i];
      const ir::ExprPtr& init = m_.global_inits[i];
      if (v->storage == ir::Storage::BuiltIn) continue;
      if (v->type.base == Base::Opaque) {
        type(v->type, v->loc);
        continue;
      }
      if (is_loose_uniform(*v)) {
        loose.push_back(v);
        loose_uniforms_.insert(v.get());
        continue;
      }
      const std::string name = ident(v->name);
      switch (v->storage) {
        case ir::Storage::Const: out_ << "const " << name << ": " << type(v->type, v->loc) << " = " << expr(init) << ";\n"; break;
        case ir::Storage::Shared: out_ << "var<workgroup> " << name << ": " << type(v->type, v->loc) << ";\n"; break;
        case ir::Storage::Uniform:
        case ir::Storage::Buffer: {
          if (v->type.is_array()) {
            error(v->loc, "arrays of interface blocks cannot be expressed in WGSL (one binding holds one buffer)");
            break;
          }
          const bool uniform = v->storage == ir::Storage::Uniform;
          const int binding = bindings_of.at(v.get());
          block_bindings_.push_back({v->type.name, anonymous_name(*v), group_of(*v), binding});
          struct_definition(v->type);
          const std::string var_name = anonymous_name(*v).empty() ? "df_block_" + v->type.name : name;
          block_var_names_[v.get()] = var_name;
          // WebGPU has no writable storage buffers in vertex shaders: one the shader only reads is
          // declared read; one it writes is refused (it was printed read_write, which Dawn rejects).
          bool read_only = v->readonly;
          if (!uniform && !read_only && m_.stage == ir::StageKind::Vertex) {
            if (ir::Loc at; block_written(v.get(), at))
              error(at, "WebGPU has no writable storage buffers in vertex shaders, and this writes '" +
                            (anonymous_name(*v).empty() ? v->type.name : v->name) +
                            "'; write it from a compute shader, or use --target glsl450/es310");
            read_only = true;
          }
          out_ << "@group(" << group_of(*v) << ") @binding(" << binding << ") var<"
               << (uniform ? "uniform" : read_only ? "storage, read" : "storage, read_write") << "> " << var_name
               << ": " << ident(v->type.name) << ";\n";
          break;
        }
        case ir::Storage::In:
        case ir::Storage::Out:
        case ir::Storage::Global:
          out_ << "var<private> " << name << ": " << type(v->type, v->loc);
          if (init) out_ << " = " << expr(init);
          out_ << ";\n";
          break;
        default: break;
      }
    }
    if (!loose.empty()) uniform_struct(loose, uniform_binding);
    out_ << "\n";
  }

  void uniform_struct(const std::vector<ir::VarPtr>& vars, int binding) {
    uniform_buffer_.name = "df_uniforms";
    uniform_buffer_.storage = "uniform";
    uniform_buffer_.type = "df_uniforms";
    uniform_buffer_.lowered_type = "df_uniforms";
    uniform_buffer_.lowered_names = {"df_uniforms"};
    uniform_buffer_.layout = "wgsl-uniform";
    uniform_buffer_.group = 0;
    uniform_buffer_.binding = binding;
    out_ << "struct df_uniforms_t {\n";
    int offset = 0;
    for (const auto& v : vars) {
      if (v->type.base == Base::Bool) error(v->loc, "bool uniform '" + v->name + "': WGSL buffers hold no bool; use int or uint");
      WgslLayout l = wgsl_layout(v->type, true);
      std::string declared = type(v->type, v->loc);
      if (v->type.is_array() && l.size / std::max(v->type.array_dims[0], 1) % 16 != 0) {
        const ir::Type element = v->type.element();
        if (v->type.array_dims.size() == 1 && !element.is_matrix() && element.base != Base::Struct && element.vec <= 2) {
          padded_uniform_arrays_[v.get()] = element.vec == 1 ? ".x" : ".xy";
          ir::Type vec4 = element;
          vec4.vec = 4;
          declared = "array<" + type(vec4, v->loc) + ", " + std::to_string(v->type.array_dims[0]) + ">";
          l = {16, 16 * v->type.array_dims[0]};
        } else {
          error(v->loc, "uniform array '" + v->name + "': WGSL's uniform buffers need a 16-byte element stride; use vec4 elements");
        }
      }
      offset = (offset + l.align - 1) / l.align * l.align;
      out_ << "  " << (l.align == 16 && (v->type.is_array() || v->type.base == Base::Struct) ? "@align(16) " : "")
           << ident(v->name) << ": " << declared << ",  // offset " << offset << "\n";
      BlockMember m;
      m.name = v->name;
      m.type = ir::type_name(v->type) + ir::array_suffix(v->type);
      m.lowered_type = declared;
      m.offset = offset;
      m.size = l.size;
      if (v->type.is_array()) m.array_stride = l.size / std::max(v->type.array_dims[0], 1);
      if (v->type.is_matrix()) m.matrix_stride = l.size / v->type.cols;
      uniform_buffer_.members.push_back(m);
      offset += l.size;
    }
    out_ << "}\n@group(0) @binding(" << binding << ") var<uniform> df_uniforms: df_uniforms_t;\n";
  }

  // ---- functions -----------------------------------------------------------
  std::string mangled_suffix(const std::vector<ir::Type>& types) {
    std::string s;
    for (const auto& t : types) {
      std::string n = ir::type_name(t);
      for (int d : t.array_dims) n += "_" + std::to_string(d);
      s += "_" + n;
    }
    return s;
  }

  void collect_overloads() {
    for (const auto& f : m_.functions) ++overload_count_[f->name];
  }

  std::string function_name(const std::string& name, const std::vector<ir::Type>& param_types) {
    if (name == "main") return "df_main";
    if (overload_count_[name] > 1) return ident(name) + mangled_suffix(param_types);
    return ident(name);
  }

  void function(const ir::Function& f) {
    std::vector<ir::Type> types;
    for (const auto& p : f.params) types.push_back(p->type);
    out_ << "fn " << function_name(f.name, types) << "(";
    for (size_t i = 0; i < f.params.size(); ++i) {
      const ir::Var& p = *f.params[i];
      out_ << (i ? ", " : "") << ident(p.name) << ": ";
      if (ir::is_out_parameter(p.storage)) {
        pointer_params_.insert(&p);
        out_ << "ptr<function, " << type(p.type, p.loc) << ">";
      } else {
        out_ << type(p.type, p.loc);
      }
    }
    out_ << ")";
    if (f.return_type.base != Base::Void) out_ << " -> " << type(f.return_type, f.loc);
    out_ << " {\n";
    // WGSL parameters are immutable: a parameter the body assigns gets a local copy.
    std::set<const ir::Var*> assigned;
    ir::visit(f.body, [&](const ir::ExprPtr& e) {
      bool assign = (e->kind == Kind::Binary && e->op.back() == '=' && e->op != "==" && e->op != "<=" && e->op != ">=" &&
                     e->op != "!=") ||
                    (e->kind == Kind::Unary && e->op.find_first_of("+-") != std::string::npos && e->op.size() == 3);
      auto mark = [&](const ir::ExprPtr& target) {
        if (const ir::Var* v = ir::root_variable(target)) assigned.insert(v);
      };
      // An argument for an out/inout parameter is passed by pointer (&p), which a parameter cannot
      // give (Chromium: "cannot take the address of parameter"): doublet's df_assign_* helpers for
      // swizzle assignments are such calls too.
      if (const ir::Function* callee = e->kind == Kind::Call ? callee_of(*e) : nullptr)
        for (size_t i = 0; i < e->args.size(); ++i)
          if (ir::is_out_parameter(callee->params[i]->storage))
            mark(e->args[i]);
      if (assign) mark(e->args[0]);
    });
    for (const auto& p : f.params)
      if (assigned.count(p.get()) && !pointer_params_.count(p.get())) {
        shadowed_params_.insert(p.get());
        out_ << "  var " << ident(p->name) << "_v: " << type(p->type) << " = " << ident(p->name) << ";\n";
      }
    for (const auto& s : f.body->body) statement(s, 1);
    out_ << "}\n\n";
  }
  std::set<const ir::Var*> shadowed_params_;

  // ---- statements ----------------------------------------------------------
  void indent(int depth) { out_ << std::string(static_cast<size_t>(depth) * 2, ' '); }

  void block(const ir::StmtPtr& s, int depth) {
    if (!s) return;
    if (s->kind == Stmt::Kind::Block)
      for (const auto& b : s->body) statement(b, depth);
    else
      statement(s, depth);
  }

  // An assignment, increment or call as a WGSL statement (no trailing ';').
  std::string simple_statement(const ir::ExprPtr& e) {
    if (e->kind == Kind::Unary && (e->op == "x++" || e->op == "++x" || e->op == "x--" || e->op == "--x")) {
      const bool inc = e->op.find('+') != std::string::npos;
      if (e->type.base == Base::Float) return lvalue(e->args[0]) + (inc ? " += 1.0f" : " -= 1.0f");
      return lvalue(e->args[0]) + (inc ? "++" : "--");
    }
    if (e->kind == Kind::Binary && ir::is_compound_arithmetic(e->op) ) return lvalue(e->args[0]) + " " + e->op + " " + expr(e->args[1]);
    if (e->kind == Kind::Binary && (e->op == "=" || e->op == "%=" || e->op == "&=" || e->op == "|=" || e->op == "^=" ||
                                    e->op == "<<=" || e->op == ">>=")) {
      const ir::ExprPtr& target = e->args[0];
      if (target->kind == Kind::Member && target->name.size() > 1 && target->args[0]->type.base != Base::Struct &&
          target->args[0]->type.base != Base::Block) {
        if (e->op != "=") error(e->loc, "compound assignment to a multi-component swizzle cannot be expressed in WGSL");
        return swizzle_assignment(target, e->args[1]);
      }
      std::string rhs = expr(e->args[1]);
      if (e->op == "<<=" || e->op == ">>=") rhs = shift_amount(e->args[1]);
      return lvalue(target) + " " + e->op + " " + rhs;
    }
    if (e->kind == Kind::Comma) {
      std::string s;
      for (size_t i = 0; i < e->args.size(); ++i) s += (i ? "; " : "") + simple_statement(e->args[i]);
      return s;
    }
    if (e->type.base == Base::Void) return expr(e);  // a call of a void function or built-in
    return "_ = " + expr(e);                         // a value computed and dropped
  }

  // v.xz = e -> { let t = e; v.x = t.x; v.z = t.y; } (WGSL assigns one component at a time).
  std::string swizzle_assignment(const ir::ExprPtr& target, const ir::ExprPtr& value) {
    const ir::ExprPtr& base = target->args[0];
    if (!ir::is_pure(base)) error(target->loc, "assignment to a swizzle of an expression with side effects cannot be expressed in WGSL");
    std::string tmp = "df_swz" + std::to_string(++temp_counter_);
    std::string s = "{ let " + tmp + " = " + expr(value) + "; ";
    static const char* comps = "xyzw";
    for (size_t i = 0; i < target->name.size(); ++i) {
      char c = target->name[i];
      const char* p = std::strchr("xyzwrgbastpq", c);
      int k = p ? static_cast<int>(p - "xyzwrgbastpq") % 4 : 0;
      s += lvalue(base) + "." + comps[k] + " = " + tmp + "." + comps[i] + "; ";
    }
    return s + "}";
  }
  int temp_counter_ = 0;

  void statement(const ir::StmtPtr& s, int depth) {
    if (!s) return;
    switch (s->kind) {
      case Stmt::Kind::Block:
        indent(depth);
        out_ << "{\n";
        block(s, depth + 1);
        indent(depth);
        out_ << "}\n";
        return;
      case Stmt::Kind::Expr:
        if (s->expr->kind == Kind::Binary && s->expr->op == "=" && branching_ternary(s->expr->args[1]) &&
            ir::is_pure(s->expr->args[0]) && !(s->expr->args[0]->kind == Kind::Member && s->expr->args[0]->name.size() > 1 &&
                                               s->expr->args[0]->args[0]->type.base != Base::Struct &&
                                               s->expr->args[0]->args[0]->type.base != Base::Block)) {
          const std::string target = lvalue(s->expr->args[0]);
          ternary_as_if(s->expr->args[1], depth, [&](const std::string& v) { return target + " = " + v + ";"; });
          return;
        }
        indent(depth);
        out_ << simple_statement(s->expr) << ";\n";
        return;
      case Stmt::Kind::Decl:
        indent(depth);
        out_ << "var " << ident(s->var->name) << ": " << type(s->var->type, s->var->loc);
        if (s->expr && branching_ternary(s->expr) && !names_variable(s->expr, s->var->name)) {
          out_ << ";\n";
          const std::string target = ident(s->var->name);
          ternary_as_if(s->expr, depth, [&](const std::string& v) { return target + " = " + v + ";"; });
          return;
        }
        if (s->expr) out_ << " = " << expr(s->expr);
        out_ << ";\n";
        return;
      case Stmt::Kind::If:
        indent(depth);
        out_ << "if " << condition(s->expr) << " {\n";
        block(s->body[0], depth + 1);
        indent(depth);
        out_ << "}";
        if (s->body.size() > 1 && s->body[1]) {
          out_ << " else {\n";
          block(s->body[1], depth + 1);
          indent(depth);
          out_ << "}";
        }
        out_ << "\n";
        return;
      case Stmt::Kind::Loop: loop(*s, depth); return;
      case Stmt::Kind::Switch: switch_statement(*s, depth); return;
      case Stmt::Kind::Case:
      case Stmt::Kind::Default: error(s->loc, "a case label outside a switch"); return;
      case Stmt::Kind::Break: indent(depth); out_ << "break;\n"; return;
      case Stmt::Kind::Continue: indent(depth); out_ << "continue;\n"; return;
      case Stmt::Kind::Discard: indent(depth); out_ << "discard;\n"; return;
      case Stmt::Kind::Return:
        if (s->expr && branching_ternary(s->expr)) {
          ternary_as_if(s->expr, depth, [](const std::string& v) { return "return " + v + ";"; });
          return;
        }
        indent(depth);
        out_ << "return" << (s->expr ? " " + expr(s->expr) : "") << ";\n";
        return;
    }
  }

  std::string condition(const ir::ExprPtr& e) { return "(" + expr(e) + ")"; }

  // A ?: that select() cannot take (a branch calls a function of the shader or has side
  // effects) at the top of a return, a declaration or an assignment: if/else, so that only the
  // chosen operand is evaluated, as in GLSL (mode exact's runtime: `return c ? ex_f(a) : ex_g(b);`).
  bool branching_ternary(const ir::ExprPtr& e) {
    if (e->kind != Kind::Ternary) return false;
    bool calls = false;  // a call of the shader's own functions (not the float-float runtime's): cost
    for (int k = 1; k <= 2; ++k)
      ir::visit(e->args[static_cast<size_t>(k)],
                [&](const ir::ExprPtr& x) { calls |= x->kind == Kind::Call && x->name.rfind("doublet_rt_", 0) != 0; });
    return calls || has_effects(e->args[1]) || has_effects(e->args[2]);
  }

  static bool names_variable(const ir::ExprPtr& e, const std::string& name) {
    bool found = false;
    ir::visit(e, [&](const ir::ExprPtr& x) { found |= x->kind == Kind::Sym && x->var && x->var->name == name; });
    return found;
  }

  void ternary_as_if(const ir::ExprPtr& e, int depth, const std::function<std::string(const std::string&)>& finish) {
    indent(depth);
    out_ << "if " << condition(e->args[0]) << " {\n";
    for (int branch = 1; branch <= 2; ++branch) {
      const ir::ExprPtr& x = e->args[static_cast<size_t>(branch)];
      if (branching_ternary(x)) {
        ternary_as_if(x, depth + 1, finish);
      } else {
        indent(depth + 1);
        out_ << finish(expr(x)) << "\n";
      }
      indent(depth);
      out_ << (branch == 1 ? "} else {\n" : "}\n");
    }
  }

  // for/while: { init; loop { if !(cond) { break; } body; continuing { step } } };
  // do-while: loop { body; continuing { break if !(cond); } }.
  void loop(const Stmt& s, int depth) {
    indent(depth);
    out_ << "{\n";
    if (s.body[0]) block(s.body[0], depth + 1);
    indent(depth + 1);
    out_ << "loop {\n";
    if (s.test_first && s.expr) {
      indent(depth + 2);
      out_ << "if !" << condition(s.expr) << " { break; }\n";
    }
    block(s.body[1], depth + 2);
    if (s.step || !s.test_first) {
      indent(depth + 2);
      out_ << "continuing {\n";
      if (s.step) {
        indent(depth + 3);
        out_ << simple_statement(s.step) << ";\n";
      }
      if (!s.test_first) {
        indent(depth + 3);
        out_ << "break if !" << condition(s.expr) << ";\n";
      }
      indent(depth + 2);
      out_ << "}\n";
    }
    indent(depth + 1);
    out_ << "}\n";
    indent(depth);
    out_ << "}\n";
  }

  // GLSL's labels and fall-through become WGSL clauses: labels with no statement between them
  // share a clause; a clause must end in break/return/continue/discard (no fall-through).
  void switch_statement(const Stmt& s, int depth) {
    indent(depth);
    out_ << "switch " << condition(s.expr) << " {\n";
    const auto& items = s.body[0]->body;
    bool has_default = false;
    for (size_t i = 0; i < items.size();) {
      std::vector<std::string> labels;
      ir::Loc at = items[i]->loc;
      while (i < items.size() && (items[i]->kind == Stmt::Kind::Case || items[i]->kind == Stmt::Kind::Default)) {
        labels.push_back(items[i]->kind == Stmt::Kind::Default ? "default" : expr(items[i]->expr));
        has_default |= items[i]->kind == Stmt::Kind::Default;
        ++i;
      }
      std::vector<ir::StmtPtr> body;
      while (i < items.size() && items[i]->kind != Stmt::Kind::Case && items[i]->kind != Stmt::Kind::Default)
        body.push_back(items[i++]);
      if (labels.empty()) {
        error(at, "statements before the first case label");
        continue;
      }
      const bool ends = !body.empty() && ends_in_jump(body.back());
      if (!ends && i < items.size())
        error(at, "a switch case that falls through into the next cannot be expressed in WGSL; end it with 'break'");
      if (!body.empty() && body.back()->kind == Stmt::Kind::Break) body.pop_back();
      indent(depth + 1);
      std::string joined;
      for (size_t k = 0; k < labels.size(); ++k) joined += (k ? ", " : "") + labels[k];
      out_ << (labels.size() == 1 && labels[0] == "default" ? "default" : "case " + joined) << ": {\n";
      for (const auto& b : body) statement(b, depth + 2);
      indent(depth + 1);
      out_ << "}\n";
    }
    if (!has_default) {
      indent(depth + 1);
      out_ << "default: {}\n";
    }
    indent(depth);
    out_ << "}\n";
  }

  // ir::has_side_effects, except that a call of a float-float runtime function (they write no
  // global and have no out parameters, apart from df_assign_component_*) has none of its own.
  bool has_effects(const ir::ExprPtr& e) {
    if (e->kind == Kind::Call && e->name.rfind("doublet_rt_", 0) == 0) {
      const ir::Function* f = callee_of(*e);
      if (!f) return true;
      for (const auto& p : f->params)
        if (p->storage != ir::Storage::ParamIn) return true;
      for (const auto& a : e->args)
        if (has_effects(a)) return true;
      return false;
    }
    if (e->kind == Kind::Call) {
      const ir::Function* f = callee_of(*e);
      if (!f || !pure_and_loop_free(*f)) return true;
      for (const auto& a : e->args)
        if (has_effects(a)) return true;
      return false;
    }
    if (e->kind == Kind::Sym || e->kind == Kind::Const) return ir::has_side_effects(e);
    if (e->kind == Kind::Binary || e->kind == Kind::Unary || e->kind == Kind::Builtin) {
      auto shallow = std::make_shared<Expr>(*e);
      shallow->args.clear();
      for (const auto& a : e->args) {
        if (has_effects(a)) return true;
        shallow->args.push_back(ir::Expr::make(Kind::Const, a->type));
        shallow->args.back()->values.resize(1);
      }
      return ir::has_side_effects(shallow);
    }
    for (const auto& a : e->args)
      if (has_effects(a)) return true;
    return false;
  }

  // A function select() may call for the operand it does not choose: it has only `in` parameters,
  // assigns only its own locals and parameters, has no loop (so it ends on any argument), no
  // discard, and calls only such functions and built-ins without side effects (mode exact's
  // `ex_from_bits(ex_is_nan(w) ? ex_pick_nan(w, w) : ...)`).
  std::map<const ir::Function*, bool> pure_memo_;
  bool pure_and_loop_free(const ir::Function& f) {
    if (auto it = pure_memo_.find(&f); it != pure_memo_.end()) return it->second;
    pure_memo_[&f] = false;  // GLSL has no recursion; a cycle would be refused here
    bool pure = true;
    for (const auto& p : f.params) pure &= p->storage == ir::Storage::ParamIn;
    std::function<void(const ir::StmtPtr&)> walk = [&](const ir::StmtPtr& st) {
      if (!st || !pure) return;
      if (st->kind == Stmt::Kind::Loop || st->kind == Stmt::Kind::Discard) pure = false;
      for (const auto& b : st->body) walk(b);
    };
    walk(f.body);
    if (pure)
      ir::visit(f.body, [&](const ir::ExprPtr& x) {
        if (!pure) return;
        if (x->kind == Kind::Call) {
          const ir::Function* g = callee_of(*x);
          pure &= g && pure_and_loop_free(*g);
        } else if (x->kind == Kind::Builtin) {
          pure &= !ir::builtin_has_side_effects(x->name);
        } else if ((x->kind == Kind::Binary && x->op.size() >= 1 && x->op.back() == '=' && x->op != "==" && x->op != "!=" &&
                    x->op != "<=" && x->op != ">=") ||
                   (x->kind == Kind::Unary && x->op.size() == 3)) {
          const ir::Var* root = ir::root_variable(x->args[0]);
          pure &= root && (root->storage == ir::Storage::Local || root->storage == ir::Storage::ParamIn);
        }
      });
    return pure_memo_[&f] = pure;
  }

  static bool ends_in_jump(const ir::StmtPtr& s) {
    if (s->kind == Stmt::Kind::Block) return !s->body.empty() && ends_in_jump(s->body.back());
    return s->kind == Stmt::Kind::Break || s->kind == Stmt::Kind::Return || s->kind == Stmt::Kind::Continue ||
           s->kind == Stmt::Kind::Discard;
  }

  // ---- expressions ---------------------------------------------------------
  std::string lvalue(const ir::ExprPtr& e) { return expr(e); }

  std::string symbol(const ir::Var& v) {
    if (v.storage == ir::Storage::BuiltIn) {
      builtins_used_.emplace(v.name, current_loc_);
      if (v.name == "gl_WorkGroupSize")
        return "vec3<u32>(" + std::to_string(m_.local_size[0]) + "u, " + std::to_string(std::max(m_.local_size[1], 1)) +
               "u, " + std::to_string(std::max(m_.local_size[2], 1)) + "u)";
      return "df_" + v.name.substr(3);
    }
    if (pointer_params_.count(&v)) return "(*" + ident(v.name) + ")";
    if (shadowed_params_.count(&v)) return ident(v.name) + "_v";
    if (padded_uniform_arrays_.count(&v))
      error(current_loc_, "uniform array '" + v.name + "' is used as a whole: WGSL pads its elements to 16 bytes, so "
                          "doublet reads it element by element only (" + v.name + "[i])");
    if (loose_uniforms_.count(&v)) return "df_uniforms." + ident(v.name);
    if (v.block) {
      auto it = block_var_names_.find(v.block.get());
      return (it != block_var_names_.end() ? it->second : ident(v.block->name)) + "." + ident(v.name);
    }
    if (auto it = block_var_names_.find(&v); it != block_var_names_.end()) return it->second;
    return ident(v.name);
  }

  std::string scalar(const ir::Scalar& v, Base base) {
    switch (base) {
      case Base::Bool: return v.b ? "true" : "false";
      case Base::Int:
        if (v.i == -2147483648LL) return "i32(-2147483647i - 1i)";
        return v.i < 0 ? "(" + std::to_string(v.i) + "i)" : std::to_string(v.i) + "i";
      case Base::Uint: return std::to_string(static_cast<unsigned long long>(v.i) & 0xffffffffULL) + "u";
      default: {
        const float f = static_cast<float>(v.d);
        if (std::isnan(f)) return nonfinite("0x7fc00000u");
        if (std::isinf(f)) return nonfinite(f > 0 ? "0x7f800000u" : "0xff800000u");
        std::string s = f32_literal(f);
        return f < 0 || std::signbit(f) ? "(" + s + ")" : s;
      }
    }
  }

  // WGSL's constant evaluation rejects infinities and NaNs: they come from bits read at run time.
  std::string nonfinite(const std::string& bits) {
    helpers_["df_bits_u32"] = "fn df_bits_u32(bits: u32) -> f32 {\n  return bitcast<f32>(bits);\n}\n";
    return "df_bits_u32(" + bits + ")";
  }

  std::string constant(const ir::Type& t, const std::vector<ir::Scalar>& values, size_t& at) {
    if (t.is_array()) {
      std::string s = type(t) + "(";
      for (int i = 0; i < t.array_dims[0]; ++i) s += (i ? ", " : "") + constant(t.element(), values, at);
      return s + ")";
    }
    if (t.base == Base::Struct) {
      std::string s = ident(t.name) + "(";
      for (size_t i = 0; i < t.fields->size(); ++i) s += (i ? ", " : "") + constant((*t.fields)[i].type, values, at);
      return s + ")";
    }
    const int n = t.vec * std::max(t.cols, 1);
    if (n == 1) return at < values.size() ? scalar(values[at++], t.base) : "0";
    std::string s = type(t) + "(";
    for (int i = 0; i < n; ++i) s += (i ? ", " : "") + (at < values.size() ? scalar(values[at++], t.base) : "0");
    return s + ")";
  }

  std::string binary(const Expr& e) {
    const std::string& op = e.op;
    const ir::Type& lt = e.args[0]->type;
    const ir::Type& rt = e.args[1]->type;
    if (ir::is_assignment_operator(op)) {  // "=" too: WGSL assigns in statements only
      error(e.loc, "an assignment inside an expression cannot be expressed in WGSL; make it a statement of its own");
      return "0";
    }
    const bool per_column = (op == "+" || op == "-" || op == "/") && (lt.is_matrix() || rt.is_matrix()) &&
                            !(lt.is_matrix() && rt.is_matrix() && op != "/");
    if (per_column) return matrix_per_column(e, op);
    std::string a = expr(e.args[0]), b = expr(e.args[1]);
    if (op == "^^") return "(" + a + " != " + b + ")";
    if (op == "<<" || op == ">>") {
      std::string amount = shift_amount(e.args[1]);
      if (lt.vec > 1 && rt.vec == 1) amount = "vec" + std::to_string(lt.vec) + "<u32>(" + amount + ")";
      return "(" + a + " " + op + " " + amount + ")";
    }
    // GLSL's bitwise operators take a vector and a scalar; WGSL's want one type: splat the scalar.
    if ((op == "&" || op == "|" || op == "^") && lt.vec != rt.vec) {
      if (lt.vec == 1) a = splat(e.args[0], rt);
      if (rt.vec == 1) b = splat(e.args[1], lt);
    }
    if ((op == "==" || op == "!=") && (lt.base == Base::Struct || lt.is_array())) {
      error(e.loc, "comparing structs or arrays with '" + op + "' cannot be expressed in WGSL; compare the members");
      return "false";
    }
    if ((op == "==" || op == "!=") && lt.is_matrix()) {
      std::string s;
      for (int c = 0; c < lt.cols; ++c)
        s += (c ? " && " : "") + std::string("all(") + a + "[" + std::to_string(c) + "] == " + b + "[" + std::to_string(c) + "])";
      return op == "==" ? "(" + s + ")" : "!(" + s + ")";
    }
    if ((op == "==" || op == "!=") && lt.vec > 1) return std::string(op == "==" ? "all" : "any") + "(" + a + " " + op + " " + b + ")";
    if (op == "%" && (lt.base == Base::Float || rt.base == Base::Float)) {
      error(e.loc, "'%' on floats");
      return "0";
    }
    return "(" + a + " " + op + " " + b + ")";
  }

  // Matrix-scalar + - /, matrix / matrix and matrixCompMult are component-wise in GLSL; WGSL has them
  // only for vectors, so they are applied column by column (the operands are evaluated per column).
  std::string matrix_per_column(const Expr& e, const std::string& op) {
    const ir::Type& t = e.type;
    for (const auto& arg : e.args)
      if (!ir::is_pure(arg)) {
        error(e.loc, "a component-wise matrix operation on an operand with side effects cannot be expressed in WGSL");
        return "0";
      }
    auto column = [&](const ir::ExprPtr& x, int c) {
      return x->type.is_matrix() ? expr(x) + "[" + std::to_string(c) + "]" : expr(x);
    };
    std::string s = type(t) + "(";
    for (int c = 0; c < t.cols; ++c)
      s += std::string(c ? ", " : "") + "(" + column(e.args[0], c) + " " + op + " " + column(e.args[1], c) + ")";
    return s + ")";
  }

  // WGSL shifts by u32 (or vecN<u32>) only.
  std::string shift_amount(const ir::ExprPtr& e) {
    if (e->type.base == Base::Uint) return expr(e);
    return (e->type.vec > 1 ? "vec" + std::to_string(e->type.vec) + "<u32>(" : std::string("u32(")) + expr(e) + ")";
  }

  std::string args_text(const std::vector<ir::ExprPtr>& args, size_t from = 0) {
    std::string s;
    for (size_t i = from; i < args.size(); ++i) s += (i > from ? ", " : "") + expr(args[i]);
    return s;
  }

  const ir::Function* callee_of(const Expr& e) {
    for (const auto& f : m_.functions) {
      if (f->name != e.name || f->params.size() != e.args.size()) continue;
      bool same = true;
      for (size_t i = 0; i < f->params.size(); ++i)
        same &= ir::type_name(f->params[i]->type) == ir::type_name(e.args[i]->type) &&
                f->params[i]->type.array_dims == e.args[i]->type.array_dims;
      if (same) return f.get();
    }
    return nullptr;
  }

  static bool is_local_root(const ir::ExprPtr& arg) {
    return arg->kind == Kind::Sym && ir::is_function_local(arg->var->storage);
  }

  std::string call(const Expr& e) {
    std::vector<ir::Type> types;
    for (const auto& a : e.args) types.push_back(a->type);
    const ir::Function* callee = callee_of(e);
    std::string s = function_name(e.name, types) + "(";
    for (size_t i = 0; i < e.args.size(); ++i) {
      s += i ? ", " : "";
      const bool pointer = callee && ir::is_out_parameter(callee->params[i]->storage);
      if (!pointer) {
        s += expr(e.args[i]);
        continue;
      }
      ir::ExprPtr root = e.args[i];
      while (root->kind == Kind::Index || (root->kind == Kind::Member && root->args[0]->type.base == Base::Struct))
        root = root->args[0];
      const bool local = is_local_root(e.args[i]);
      if (!local)
        error(e.args[i]->loc, "an out/inout argument that is not a whole local variable cannot be expressed in WGSL "
                              "(a pointer must point to function memory); pass a local variable and copy it");
      if (root->kind == Kind::Sym && pointer_params_.count(root->var.get()))
        s += ident(root->var->name);
      else
        s += "&" + expr(e.args[i]);
    }
    return s + ")";
  }

  std::string splat(const ir::ExprPtr& a, const ir::Type& like) {
    if (a->type.vec == like.vec || like.is_matrix()) return expr(a);
    ir::Type t = like;
    t.base = a->type.base;
    return type(t) + "(" + expr(a) + ")";
  }

  std::string bits_helper(const std::string& name, const ir::Type& t, const std::string& body_op) {
    const std::string tn = type(t);
    ir::Type u = t;
    u.base = Base::Uint;
    ir::Type b = t;
    b.base = Base::Bool;
    const std::string key = name + "_" + std::to_string(t.vec);
    // df_float_*: the runtime's own df_isnan/df_isinf (rules/common.glsl) take df_double, and WGSL
    // has no overloading.
    const std::string fn = "df_float_" + name + (t.vec > 1 ? std::to_string(t.vec) : "");
    helpers_[key] = "fn " + fn + "(x: " + tn + ") -> " + type(b) + " {\n  let m = bitcast<" + type(u) + ">(x) & " + type(u) +
                    "(0x7fffffffu);\n  return m " + body_op + " " + type(u) + "(0x7f800000u);\n}\n";
    return fn;
  }

  // umulExtended(x, y, msb, lsb): WGSL has no widening multiply; a helper forms the 64-bit
  // products from 16-bit halves (four 16x16-bit products, the middle sum's carry kept), msb and lsb
  // written through pointers (they must be local variables, as for calls of the shader's functions).
  std::string umul_extended(const Expr& e) {
    const auto& a = e.args;
    const std::string t = type(a[0]->type);
    const std::string fn = "df_umulExtended" + (a[0]->type.vec > 1 ? std::to_string(a[0]->type.vec) : std::string());
    helpers_[fn] = "fn " + fn + "(x: " + t + ", y: " + t + ", msb: ptr<function, " + t + ">, lsb: ptr<function, " + t +
                   ">) {\n"
                   "  let xl = x & " + t + "(0xFFFFu);\n  let xh = x >> " + t + "(16u);\n"
                   "  let yl = y & " + t + "(0xFFFFu);\n  let yh = y >> " + t + "(16u);\n"
                   "  let ll = xl * yl;\n  let lh = xl * yh;\n  let hl = xh * yl;\n  let hh = xh * yh;\n"
                   "  let mid = lh + hl;\n"
                   "  let mid_carry = select(" + t + "(0u), " + t + "(0x10000u), mid < lh);\n"
                   "  let lo = ll + (mid << " + t + "(16u));\n"
                   "  *lsb = lo;\n"
                   "  *msb = hh + (mid >> " + t + "(16u)) + mid_carry + select(" + t + "(0u), " + t + "(1u), lo < ll);\n}\n";
    std::string s = fn + "(" + expr(a[0]) + ", " + expr(a[1]);
    for (size_t i = 2; i < 4; ++i) {
      ir::ExprPtr root = a[i];
      if (!is_local_root(root)) {
        error(a[i]->loc, "umulExtended's msb and lsb arguments must be local variables in WGSL (they become pointers to "
                         "function memory); pass locals and copy them");
        return "0";
      }
      s += ", " + (pointer_params_.count(root->var.get()) ? ident(root->var->name) : "&" + expr(root));
    }
    return s + ")";
  }

  // modf(x, out whole) and frexp(x, out exponent) on floats: WGSL's return a struct (fract and
  // whole; fract and exp, GLSL's meanings), so a helper stores the second part through a pointer to
  // function memory (wgsl-out-arguments gives a buffer element or global a local temporary).
  std::string split_result_builtin(const Expr& e) {
    const auto& a = e.args;
    const std::string t = type(a[0]->type), part_type = type(a[1]->type);
    const std::string fn = "df_float_" + e.name + (a[0]->type.vec > 1 ? std::to_string(a[0]->type.vec) : std::string());
    const std::string part = e.name == "modf" ? "whole" : "exp";
    helpers_[fn] = "fn " + fn + "(x: " + t + ", " + part + ": ptr<function, " + part_type + ">) -> " + t + " {\n  let r = " +
                   e.name + "(x);\n  *" + part + " = r." + part + ";\n  return r.fract;\n}\n";
    if (!is_local_root(a[1])) {
      error(a[1]->loc, e.name + "'s out argument must be a local variable in WGSL (it becomes a pointer to function "
                       "memory); pass a local and copy it");
      return "0";
    }
    const ir::Var& root = *a[1]->var;
    return fn + "(" + expr(a[0]) + ", " + (pointer_params_.count(&root) ? ident(root.name) : "&" + expr(a[1])) + ")";
  }

  std::string builtin(const Expr& e) {
    const std::string& n = e.name;
    const auto& a = e.args;
    static const std::map<std::string, std::string> renamed = {
        {"inversesqrt", "inverseSqrt"}, {"dFdx", "dpdx"},          {"dFdy", "dpdy"},
        {"roundEven", "round"},         {"bitCount", "countOneBits"}, {"findLSB", "firstTrailingBit"},
        {"findMSB", "firstLeadingBit"}, {"bitfieldReverse", "reverseBits"}, {"bitfieldExtract", "extractBits"},
        {"bitfieldInsert", "insertBits"}, {"packHalf2x16", "pack2x16float"}, {"unpackHalf2x16", "unpack2x16float"},
        {"packUnorm2x16", "pack2x16unorm"}, {"unpackUnorm2x16", "unpack2x16unorm"}, {"packSnorm2x16", "pack2x16snorm"},
        {"unpackSnorm2x16", "unpack2x16snorm"}, {"packUnorm4x8", "pack4x8unorm"}, {"unpackUnorm4x8", "unpack4x8unorm"},
        {"packSnorm4x8", "pack4x8snorm"}, {"unpackSnorm4x8", "unpack4x8snorm"}, {"barrier", "workgroupBarrier"},
        {"memoryBarrierShared", "workgroupBarrier"}, {"groupMemoryBarrier", "workgroupBarrier"},
        {"memoryBarrierBuffer", "storageBarrier"}, {"memoryBarrier", "storageBarrier"}, {"fwidth", "fwidth"}};
    static const std::set<std::string> same = {
        "abs", "sign", "floor", "ceil", "fract", "trunc", "round", "sqrt", "exp", "exp2", "log", "log2", "pow", "sin",
        "cos", "tan", "asin", "acos", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "length", "distance", "dot",
        "cross", "normalize", "reflect", "refract", "faceForward", "transpose", "determinant", "all", "any", "fma",
        "ldexp", "radians", "degrees"};
    static const std::set<std::string> splatting = {"min", "max", "clamp", "step", "smoothstep"};
    static const std::map<std::string, std::string> comparisons = {
        {"lessThan", "<"}, {"lessThanEqual", "<="}, {"greaterThan", ">"}, {"greaterThanEqual", ">="},
        {"equal", "=="}, {"notEqual", "!="}};
    if (ir::is_array_length(e)) {
      if (a[0]->type.array_dims[0] > 0) return std::to_string(a[0]->type.array_dims[0]) + "i";
      return "i32(arrayLength(&" + (std140_.wrapped(*a[0]) ? member_access(*a[0]) : expr(a[0])) + "))";
    }
    if (auto it = comparisons.find(n); it != comparisons.end()) return "(" + expr(a[0]) + " " + it->second + " " + expr(a[1]) + ")";
    if (n == "matrixCompMult") {
      auto product = ir::make_node(Kind::Binary, "", e.type, a, e.loc);
      product->op = "*";
      return matrix_per_column(*product, "*");
    }
    if (n == "not") return "!(" + expr(a[0]) + ")";
    // GLSL's findMSB, findLSB and bitCount return int (ivecN) for uint operands too; WGSL's return
    // the operand's type. u32 -> i32 keeps the bits, so findMSB(0u) is still -1.
    if ((n == "findMSB" || n == "findLSB" || n == "bitCount") && a.size() == 1 && a[0]->type.base == Base::Uint) {
      const std::string wgsl = n == "findMSB" ? "firstLeadingBit" : n == "findLSB" ? "firstTrailingBit" : "countOneBits";
      return type(e.type) + "(" + wgsl + "(" + expr(a[0]) + "))";
    }
    if (n == "umulExtended" && a.size() == 4) return umul_extended(e);
    if (ir::builtin_writes_second_argument(e)) return split_result_builtin(e);
    if (n == "atan") return a.size() == 2 ? "atan2(" + args_text(a) + ")" : "atan(" + expr(a[0]) + ")";
    if (n == "uintBitsToFloat" || n == "intBitsToFloat") {
      // A constant argument would make this a const-expression, where WGSL rejects an infinite or
      // NaN result: a function call (never a const-expression) defers it to run time.
      bool constant = true;
      ir::visit(a[0], [&](const ir::ExprPtr& x) { constant &= x->kind != Kind::Sym && x->kind != Kind::Call; });
      if (constant) {
        const std::string tn = type(a[0]->type);
        std::string fn = "df_runtime_" + tn;
        for (char& ch : fn)
          if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        helpers_[fn] = "fn " + fn + "(x: " + tn + ") -> " + tn + " {\n  return x;\n}\n";
        return "bitcast<" + type(e.type) + ">(" + fn + "(" + expr(a[0]) + "))";
      }
    }
    if (n == "floatBitsToUint" || n == "floatBitsToInt" || n == "uintBitsToFloat" || n == "intBitsToFloat")
      return "bitcast<" + type(e.type) + ">(" + expr(a[0]) + ")";
    if (n == "mod") {
      const ir::Type& t = e.type;
      const std::string key = "mod_" + type(t) + "_" + type(a[1]->type);
      const std::string fn = "df_mod" + mangled_suffix({t, a[1]->type});
      helpers_[key] = "fn " + fn + "(x: " + type(t) + ", y: " + type(a[1]->type) + ") -> " + type(t) +
                      " {\n  return x - y * floor(x / y);\n}\n";
      return fn + "(" + args_text(a) + ")";
    }
    if (n == "isnan") return bits_helper("isnan", a[0]->type, ">") + "(" + expr(a[0]) + ")";
    if (n == "isinf") return bits_helper("isinf", a[0]->type, "==") + "(" + expr(a[0]) + ")";
    if (n == "mix" && a.size() == 3 && a[2]->type.base == Base::Bool)
      return "select(" + expr(a[0]) + ", " + expr(a[1]) + ", " + expr(a[2]) + ")";
    if (n == "mix") return "mix(" + expr(a[0]) + ", " + expr(a[1]) + ", " + expr(a[2]) + ")";
    if (splatting.count(n)) {
      std::string s = n + "(";
      for (size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + splat(a[i], e.type);
      return s + ")";
    }
    if (same.count(n)) return n + "(" + args_text(a) + ")";
    if (auto it = renamed.find(n); it != renamed.end()) return it->second + "(" + args_text(a) + ")";
    error(e.loc, "the built-in function '" + n + "' has no WGSL translation in doublet");
    return "0";
  }

  std::string construct(const Expr& e) {
    const ir::Type& t = e.type;
    const auto& a = e.args;
    if (t.base == Base::Struct || t.is_array()) return type(t, e.loc) + "(" + args_text(a) + ")";
    if (t.is_matrix()) {
      if (a.size() == 1 && a[0]->type.vec == 1 && !a[0]->type.is_matrix()) {
        // GLSL: a scalar on the diagonal.
        std::string s = type(t) + "(";
        for (int c = 0; c < t.cols; ++c)
          for (int r = 0; r < t.vec; ++r) s += std::string(c || r ? ", " : "") + (c == r ? expr(a[0]) : "0.0f");
        return s + ")";
      }
      if (a.size() == 1 && a[0]->type.is_matrix() && (a[0]->type.cols != t.cols || a[0]->type.vec != t.vec)) {
        // GLSL: element (c, r) comes from the operand where it has one, else from the identity.
        if (!ir::is_pure(a[0])) {
          error(e.loc, "a matrix built from a matrix of another shape with side effects cannot be expressed in WGSL");
          return "0";
        }
        const std::string m = expr(a[0]);
        std::string s = type(t) + "(";
        for (int c = 0; c < t.cols; ++c)
          for (int r = 0; r < t.vec; ++r)
            s += std::string(c || r ? ", " : "") +
                 (c < a[0]->type.cols && r < a[0]->type.vec ? m + "[" + std::to_string(c) + "][" + std::to_string(r) + "]"
                                                             : c == r ? "1.0f" : "0.0f");
        return s + ")";
      }
      return type(t) + "(" + args_text(a) + ")";
    }
    // A vector or scalar from a larger vector: GLSL drops the extra components, WGSL does not.
    if (a.size() == 1 && a[0]->type.vec > t.vec && !a[0]->type.is_matrix()) {
      static const char* comps = "xyzw";
      const std::string part = t.vec == 1 ? "x" : std::string(comps, static_cast<size_t>(t.vec));
      const std::string inner = expr(a[0]) + "." + part;
      return a[0]->type.base == t.base ? inner : type(t) + "(" + inner + ")";
    }
    if (a.size() == 1 && a[0]->type.base == t.base && a[0]->type.vec == t.vec) return expr(a[0]);
    // Mixed scalar bases inside a vector constructor: convert each argument first.
    std::string s = type(t) + "(";
    for (size_t i = 0; i < a.size(); ++i) {
      std::string part = expr(a[i]);
      if (a[i]->type.base != t.base && a.size() > 1) {
        ir::Type conv = a[i]->type;
        conv.base = t.base;
        part = type(conv) + "(" + part + ")";
      }
      s += (i ? ", " : "") + part;
    }
    return s + ")";
  }

  ir::Loc current_loc_;  // of the symbol being printed (first uses of built-ins)

  std::string expr(const ir::ExprPtr& e) {
    if (!e) return "";
    switch (e->kind) {
      case Kind::Sym:
        current_loc_ = e->loc;
        refuse_whole_member_access(*e);
        return symbol(*e->var);
      case Kind::Const: {
        size_t at = 0;
        return constant(e->type, e->values, at);
      }
      case Kind::Unary: {
        const std::string& op = e->op;
        if (op.size() == 3) {
          error(e->loc, "'" + op + "' inside an expression cannot be expressed in WGSL; make it a statement of its own");
          return "0";
        }
        if (op == "-" && e->type.is_matrix()) return "(" + expr(e->args[0]) + " * -1.0f)";  // no matrix negation in WGSL
        return op + "(" + expr(e->args[0]) + ")";
      }
      case Kind::Binary: return binary(*e);
      case Kind::Ternary: {
        const ir::Type& t = e->type;
        if (has_effects(e->args[1]) || has_effects(e->args[2]))
          error(e->loc, "a ?: whose branches have side effects cannot be expressed in WGSL (select evaluates both); "
                        "use if/else");
        std::string c = expr(e->args[0]);
        if (t.base == Base::Struct || t.is_array() || t.is_matrix()) {
          // select() takes scalars and vectors only: a helper evaluates both operands the same way.
          const std::string tn = type(t, e->loc);
          std::string fn = "df_select_" + tn;
          for (char& ch : fn)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
          helpers_[fn] = "fn " + fn + "(f: " + tn + ", t: " + tn + ", c: bool) -> " + tn +
                         " {\n  if c {\n    return t;\n  }\n  return f;\n}\n";
          return fn + "(" + expr(e->args[2]) + ", " + expr(e->args[1]) + ", " + c + ")";
        }
        if (t.vec > 1) c = "vec" + std::to_string(t.vec) + "<bool>(" + c + ")";
        return "select(" + expr(e->args[2]) + ", " + expr(e->args[1]) + ", " + c + ")";
      }
      case Kind::Call: return call(*e);
      case Kind::Builtin: return builtin(*e);
      case Kind::Construct: return construct(*e);
      case Kind::Member: refuse_whole_member_access(*e); return member_access(*e);
      case Kind::Index: {
        std::string index = expr(e->args[1]);
        const ir::ExprPtr& base = e->args[0];
        if (base->kind == Kind::Sym)
          if (auto padded = padded_uniform_arrays_.find(base->var.get()); padded != padded_uniform_arrays_.end())
            return "df_uniforms." + ident(base->var->name) + "[" + index + "]" + padded->second;
        if (std140_.wrapped(*base)) return member_access(*base) + "[" + index + "].v";
        return expr(base) + "[" + index + "]";
      }
      case Kind::Comma:
        error(e->loc, "a comma expression inside an expression cannot be expressed in WGSL");
        return "0";
    }
    return "0";
  }

  // A member (or an anonymous block's member), without the check for whole reads of padded arrays.
  std::string member_access(const Expr& e) {
    if (e.kind == Kind::Sym) return symbol(*e.var);
    const Base base = e.args[0]->type.base;
    return expr(e.args[0]) + "." + (base == Base::Struct || base == Base::Block ? ident(e.name) : e.name);
  }

  // An array member padded to std140's stride is an array of wrappers: read element by element.
  void refuse_whole_member_access(const Expr& e) {
    if (!std140_.wrapped(e)) return;
    const std::string name = e.kind == Kind::Sym ? e.var->name : e.name;
    error(e.loc, "'" + name + "' is read as a whole: in WGSL its elements are padded to std140's 16-byte stride, so " +
                     "doublet reads it element by element only (" + name + "[i])");
  }

  // ---- entry point ---------------------------------------------------------
  struct BuiltinIo {
    const char* glsl;
    const char* wgsl;
    const char* wgsl_type;  // the attribute's type
    const char* private_type;
    const char* convert;  // printf-like conversion from wgsl_type to private_type ("%s" when none)
  };

  void entry_point() {
    static const BuiltinIo inputs[] = {
        {"gl_GlobalInvocationID", "global_invocation_id", "vec3<u32>", "vec3<u32>", ""},
        {"gl_LocalInvocationID", "local_invocation_id", "vec3<u32>", "vec3<u32>", ""},
        {"gl_WorkGroupID", "workgroup_id", "vec3<u32>", "vec3<u32>", ""},
        {"gl_NumWorkGroups", "num_workgroups", "vec3<u32>", "vec3<u32>", ""},
        {"gl_LocalInvocationIndex", "local_invocation_index", "u32", "u32", ""},
        {"gl_VertexID", "vertex_index", "u32", "i32", "i32"},
        {"gl_VertexIndex", "vertex_index", "u32", "i32", "i32"},
        {"gl_InstanceID", "instance_index", "u32", "i32", "i32"},
        {"gl_InstanceIndex", "instance_index", "u32", "i32", "i32"},
        {"gl_FragCoord", "position", "vec4<f32>", "vec4<f32>", ""},
        {"gl_FrontFacing", "front_facing", "bool", "bool", ""},
    };
    const bool vertex = m_.stage == ir::StageKind::Vertex, fragment = m_.stage == ir::StageKind::Fragment;
    std::vector<std::string> params, copies, outputs, out_values;
    std::set<std::string> seen_builtin_attr;
    for (const auto& io : inputs) {
      if (!builtins_used_.count(io.glsl)) continue;
      out_ << "var<private> df_" << (io.glsl + 3) << ": " << io.private_type << ";\n";
      const std::string param = std::string("df_in_") + io.wgsl;
      if (seen_builtin_attr.insert(io.wgsl).second) params.push_back("@builtin(" + std::string(io.wgsl) + ") " + param + ": " + io.wgsl_type);
      copies.push_back("df_" + std::string(io.glsl + 3) + " = " + (*io.convert ? std::string(io.convert) + "(" + param + ")" : param));
    }
    for (const auto& [name, loc] : builtins_used_) {
      bool known = name == "gl_WorkGroupSize" || name == "gl_Position" || name == "gl_FragDepth";
      for (const auto& io : inputs) known |= name == io.glsl;
      if (!known) error(loc, "the built-in variable '" + name + "' has no WGSL translation in doublet");
    }
    // Every input and output has its location by now (the wgsl-io-locations pass).
    auto location = [&](const ir::Var& g) {
      if (g.layout.location < 0) error(g.loc, "internal error: '" + g.name + "' reached the WGSL printer without a location");
      // WGSL's user-defined inputs and outputs are scalars and vectors only (WGSL, "Inter-stage
      // Input and Output Interface"; vertex attributes likewise).
      if (g.type.cols > 1 || g.type.is_array())
        error(g.loc, "'" + g.name + "' is " + (g.type.is_array() ? "an array" : "a matrix") + " " +
                         (g.storage == ir::Storage::In ? "input" : "output") +
                         "; WGSL passes only scalars and vectors between stages and from vertex buffers: declare one "
                         "vector per " + (g.type.is_array() ? "element" : "column") + ", or target a GLSL dialect");
      return std::max(g.layout.location, 0);
    };
    for (const auto& g : m_.globals) {
      if (g->storage == ir::Storage::In && !vertex && !fragment) continue;
      if (g->storage == ir::Storage::In) {
        int loc = location(*g);
        const bool flat = g->type.base != Base::Float || g->interp == ir::Interp::Flat;
        params.push_back("@location(" + std::to_string(loc) + ")" + (flat && fragment ? " @interpolate(flat)" : "") +
                         " df_in_" + g->name + ": " + type(g->type, g->loc));
        copies.push_back(ident(g->name) + " = df_in_" + g->name);
      } else if (g->storage == ir::Storage::Out) {
        int loc = location(*g);
        const bool flat = g->type.base != Base::Float || g->interp == ir::Interp::Flat;
        outputs.push_back("@location(" + std::to_string(loc) + ")" + (flat && vertex ? " @interpolate(flat)" : "") + " " +
                          ident(g->name) + ": " + type(g->type, g->loc));
        out_values.push_back(ident(g->name));
      }
    }
    if (vertex) {
      out_ << "var<private> df_Position: vec4<f32>;\n";
      outputs.insert(outputs.begin(), "@builtin(position) gl_Position: vec4<f32>");
      out_values.insert(out_values.begin(), "df_Position");
    }
    if (fragment && builtins_used_.count("gl_FragDepth")) {
      out_ << "var<private> df_FragDepth: f32;\n";
      outputs.push_back("@builtin(frag_depth) gl_FragDepth: f32");
      out_values.push_back("df_FragDepth");
    }
    if (!outputs.empty()) {
      out_ << "\nstruct df_stage_out {\n";
      for (const auto& o : outputs) out_ << "  " << o << ",\n";
      out_ << "}\n";
    }
    out_ << "\n";
    if (m_.stage == ir::StageKind::Compute)
      out_ << "@compute @workgroup_size(" << std::max(m_.local_size[0], 1) << ", " << std::max(m_.local_size[1], 1) << ", "
           << std::max(m_.local_size[2], 1) << ")\n";
    else
      out_ << (vertex ? "@vertex\n" : "@fragment\n");
    out_ << "fn main(";
    for (size_t i = 0; i < params.size(); ++i) out_ << (i ? ", " : "") << params[i];
    out_ << ")" << (outputs.empty() ? "" : " -> df_stage_out") << " {\n";
    for (const auto& c : copies) out_ << "  " << c << ";\n";
    out_ << "  df_main();\n";
    if (!outputs.empty()) {
      out_ << "  return df_stage_out(";
      for (size_t i = 0; i < out_values.size(); ++i) out_ << (i ? ", " : "") << out_values[i];
      out_ << ");\n";
    }
    out_ << "}\n";
  }

  std::string helpers_text() {
    std::string s;
    for (const auto& [name, text] : helpers_) s += text + "\n";
    return s;
  }
};

}  // namespace

WgslPrintResult print_wgsl(const ir::Module& module, const std::string& file_name, const std::string& position_note,
                           const std::map<std::string, int>& block_groups) {
  return WgslPrinter(module, file_name, position_note, block_groups).run();
}

}  // namespace doublet::emit
