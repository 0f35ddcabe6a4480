#include "emit/printer.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <locale>
#include <map>
#include <set>
#include <sstream>

#include "target/target.hpp"
#include "ir/walk.hpp"

namespace doublet::emit {

std::string float_literal(float value) {
  if (std::isinf(value)) return value > 0 ? "uintBitsToFloat(0x7F800000u)" : "uintBitsToFloat(0xFF800000u)";
  if (std::isnan(value)) return "uintBitsToFloat(0x7FC00000u)";
  char buf[64];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, static_cast<double>(value));
    if (std::strtof(buf, nullptr) == value) break;
  }
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  else if (s.find('.') == std::string::npos) s.insert(s.find('e'), ".0");
  return s;
}

namespace {

using ir::Expr;
using ir::Stmt;

class Printer {
 public:
  Printer(const ir::Module& m, const PrintOptions& o, const std::string& file)
      : module_(m), options_(o), file_(file), es_(target_is_es(o.target)), version_(target_version(o.target)) {
    out_.imbue(std::locale::classic());  // no digit grouping from a global C++ locale ("1.024")
  }

  PrintResult run() {
    header();
    print_structs();
    if (!options_.after_structs.empty()) out_ << options_.after_structs << "\n";
    fragment_output_rename();
    for (size_t i = 0; i < module_.globals.size(); ++i) global(module_.globals[i], module_.global_inits[i]);
    if (frag_color_declared_) out_ << "layout(location = 0) out highp vec4 df_frag_color;\n";
    if (frag_data_size_ && frag_data_dynamic_)
      out_ << "layout(location = 0) out highp vec4 df_frag_data[" << frag_data_size_ << "];\n";
    else
      for (int k : frag_data_slots_) out_ << "layout(location = " << k << ") out highp vec4 df_frag_data_" << k << ";\n";
    if (!module_.globals.empty() || frag_color_declared_ || frag_data_size_) out_ << "\n";
    for (const auto& f : module_.functions)
      if (f->name != "main") out_ << signature(*f) << ";\n";
    for (const auto& f : module_.functions) {
      out_ << "\n";
      mark(f->loc);
      out_ << signature(*f) << "\n";
      statement(f->body, 0);
    }
    PrintResult result{out_.str(), diags_, builtin_first_use_, {}};
    // Byte offsets → line numbers, in one pass over the text (the marks are in increasing order).
    int line = 1;
    size_t at = 0;
    for (const auto& [offset, loc] : marks_) {
      for (; at < offset && at < result.text.size(); ++at) line += result.text[at] == '\n';
      result.source_lines.emplace_back(line, loc);
    }
    return result;
  }

  // One expression (expression_text).
  std::string expression(const ir::ExprPtr& e) { return expr(e); }

 private:
  std::string target_name() const { return options_.target_name.empty() ? std::string(to_string(options_.target)) : options_.target_name; }

  void error(ir::Loc loc, const std::string& msg) {
    diags_.push_back({ir::file_of(loc, file_), loc.line, loc.column, Severity::Error, msg});
  }

  // ---- header --------------------------------------------------------------
  void header() {
    out_ << target::version_directive(options_.target) << "\n";
    for (const auto& e : options_.extensions) out_ << "#extension " << e << " : require\n";
    for (const auto& e : options_.user_extensions)
      if (std::find(options_.extensions.begin(), options_.extensions.end(), e) == options_.extensions.end())
        out_ << "#extension " << e << " : enable\n";
    out_ << "precision highp float;\nprecision highp int;\n";
    if (es_ && version_ >= 300) {
      std::set<std::string> opaque;
      for (const auto& g : module_.globals)
        if (g->type.base == ir::Base::Opaque && g->type.name != "sampler2D" && g->type.name != "samplerCube")
          opaque.insert(g->type.name);
      for (const auto& t : opaque) out_ << "precision highp " << t << ";\n";
    }
    for (const auto& layout : module_.stage_layouts) out_ << layout << "\n";
    if (module_.stage == ir::StageKind::Compute)
      out_ << "layout(local_size_x = " << module_.local_size[0] << ", local_size_y = " << module_.local_size[1]
           << ", local_size_z = " << module_.local_size[2] << ") in;\n";
    out_ << "\n";
    if (!options_.guard_uniform.empty()) hoist_loose_uniforms(is_loose_numeric_uniform);
    out_ << options_.runtime_types;
    const bool struct_uniforms = std::any_of(module_.globals.begin(), module_.globals.end(),
                                             [](const auto& v) { return is_loose_struct_uniform(*v); });
    if (!options_.guard_uniform.empty() && struct_uniforms) {
      print_structs();
      hoist_loose_uniforms(is_loose_struct_uniform);
    }
    if (!options_.runtime.empty()) out_ << options_.runtime << "\n";
  }

  static bool is_loose_numeric_uniform(const ir::Var& v) {
    const ir::Base b = v.type.base;
    return v.storage == ir::Storage::Uniform && !v.block &&
           (b == ir::Base::Float || b == ir::Base::Int || b == ir::Base::Uint || b == ir::Base::Bool);
  }
  static bool is_loose_struct_uniform(const ir::Var& v) {
    return v.storage == ir::Storage::Uniform && !v.block && v.type.base == ir::Base::Struct;
  }

  // See PrintOptions::guard_uniform.
  void hoist_loose_uniforms(bool (*wanted)(const ir::Var&)) {
    bool any = false;
    for (size_t i = 0; i < module_.globals.size(); ++i) {
      const ir::VarPtr& v = module_.globals[i];
      if (!wanted(*v) || v->name == options_.guard_uniform) continue;
      global(v, module_.global_inits[i]);
      hoisted_.insert(v.get());
      any = true;
    }
    if (any) out_ << "\n";
  }

  void print_structs() {
    if (structs_printed_) return;
    structs_printed_ = true;
    for (const auto& t : module_.structs) struct_definition(t);
    if (!module_.structs.empty()) out_ << "\n";
  }

  void struct_definition(const ir::Type& t) {
    out_ << "struct " << t.name << " {\n";
    for (const auto& f : *t.fields) out_ << "  " << declarator(f.type, f.name) << ";\n";
    out_ << "};\n";
  }

  // The constant index k of gl_FragData[k], or -1.
  static int constant_frag_data_index(const Expr& index_expr) {
    const ir::ExprPtr& index = index_expr.args[1];
    if (index->kind != Expr::Kind::Const || index->values.size() != 1 || index->values[0].i < 0) return -1;
    return static_cast<int>(index->values[0].i);
  }

  int count_symbol_uses(const std::string& name) const {
    int uses = 0;
    for (const auto& f : module_.functions)
      ir::visit(f->body, [&](const ir::ExprPtr& e) { uses += e->kind == Expr::Kind::Sym && e->var->name == name; });
    return uses;
  }

  // gl_FragData on targets without it (ES 3.00+, core profiles) becomes one output per constant
  // index k (df_frag_data_k at location k), or an array of the 4 draw buffers every ES 3.00
  // implementation has when an index is computed or the array is used whole (desktop only: GLSL
  // ES, 1.00 included, forbids computed indices into fragment outputs).
  void scan_frag_data() {
    int uses = 0, indexed_uses = 0, size = 0;
    bool dynamic = false;
    std::set<int> slots;
    for (const auto& f : module_.functions)
      ir::visit(f->body, [&](const ir::ExprPtr& e) {
        uses += e->kind == Expr::Kind::Sym && e->var->name == "gl_FragData";
        if (e->kind != Expr::Kind::Index || e->args[0]->kind != Expr::Kind::Sym || e->args[0]->var->name != "gl_FragData")
          return;
        if (const int k = constant_frag_data_index(*e); k >= 0) {
          slots.insert(k);
          size = std::max(size, k + 1);
          ++indexed_uses;
        } else if (!dynamic) {
          dynamic = true;
          if (es_)
            error(e->loc, "gl_FragData indexed by a computed value cannot be expressed on " +
                              target_name() +
                              " (GLSL ES forbids variable indexing of fragment outputs); index it with constants or "
                              "target glsl330/glsl450");
        }
      });
    if (uses == 0 || options_.target == Target::Es100) return;  // ES 1.00 keeps gl_FragData
    frag_data_dynamic_ = dynamic || uses > indexed_uses;
    frag_data_size_ = frag_data_dynamic_ ? std::max(size, 4) : size;
    if (!frag_data_dynamic_) frag_data_slots_ = std::move(slots);
  }

  // ES 1.00 has one fragment output, gl_FragColor; ES 3.00+ has no gl_FragColor.
  void fragment_output_rename() {
    if (module_.stage != ir::StageKind::Fragment) return;
    scan_frag_data();
    if (options_.target != Target::Es100)
      for (const auto& f : module_.functions)
        ir::visit(f->body, [&](const ir::ExprPtr& e) {
          frag_color_declared_ |= e->kind == Expr::Kind::Sym && e->var->name == "gl_FragColor";
        });
    if (options_.target == Target::Es100) {
      std::vector<ir::VarPtr> outs;
      for (const auto& g : module_.globals)
        if (g->storage == ir::Storage::Out) outs.push_back(g);
      if (outs.size() == 1 && ir::type_name(outs[0]->type) == "vec4" && !outs[0]->type.is_array()) {
        frag_output_ = outs[0].get();
      } else if (!outs.empty()) {
        error(outs[0]->loc, "GLSL ES 1.00 has a single fragment output (gl_FragColor); this shader declares " +
                                std::to_string(outs.size()) + " outputs or a non-vec4 output");
      }
    }
  }

  // ---- declarations --------------------------------------------------------
  std::string declarator(const ir::Type& t, const std::string& name) {
    return ir::type_name(t) + " " + name + ir::array_suffix(t);
  }

  std::string storage_keyword(const ir::Var& v) {
    bool vert = module_.stage == ir::StageKind::Vertex;
    switch (v.storage) {
      case ir::Storage::In:
        if (options_.target == Target::Es100) return vert ? "attribute" : "varying";
        return "in";
      case ir::Storage::Out:
        if (options_.target == Target::Es100) return "varying";
        return "out";
      case ir::Storage::Uniform: return "uniform";
      case ir::Storage::Buffer: return "buffer";
      case ir::Storage::Shared: return "shared";
      case ir::Storage::Const: return "const";
      default: return "";
    }
  }

  bool location_allowed(const ir::Var& v) {
    if (v.storage == ir::Storage::Uniform || v.storage == ir::Storage::Buffer)
      return es_ ? version_ >= 310 : version_ >= 430;
    if (options_.target == Target::Es100) return false;
    bool vert = module_.stage == ir::StageKind::Vertex;
    if ((v.storage == ir::Storage::In && vert) || (v.storage == ir::Storage::Out && !vert)) return true;
    return es_ ? version_ >= 310 : version_ >= 410;
  }

  std::string layout(const ir::Var& v) {
    std::vector<std::string> parts;
    const bool block = v.type.base == ir::Base::Block;
    if (!v.layout.packing.empty() && block) {
      if (options_.target == Target::Es100)
        error(v.loc, "interface blocks need GLSL ES 3.00 or later");
      else if (target::facts(options_.target).webgl_rules && v.storage == ir::Storage::Uniform &&
               (v.layout.packing == "shared" || v.layout.packing == "packed"))
        // WebGL 2.0 allows only std140 (ANGLE: "Only std140 layout is allowed in WebGL"); shared and
        // packed (glslang's default) leave the layout to the implementation, which may choose std140.
        parts.push_back("std140");
      else
        parts.push_back(v.layout.packing);
    }
    if (!v.layout.format.empty()) parts.push_back(v.layout.format);
    if (v.layout.passthrough) parts.push_back("passthrough");
    if (v.layout.set >= 0 && !es_ && version_ >= 450) parts.push_back("set = " + std::to_string(v.layout.set));
    if (v.layout.binding >= 0 && (es_ ? version_ >= 310 : version_ >= 420))
      parts.push_back("binding = " + std::to_string(v.layout.binding));
    if (v.layout.location >= 0 && location_allowed(v)) parts.push_back("location = " + std::to_string(v.layout.location));
    if (v.layout.offset >= 0 && v.type.name == "atomic_uint") parts.push_back("offset = " + std::to_string(v.layout.offset));
    if (parts.empty()) return "";
    std::string s = "layout(";
    for (size_t i = 0; i < parts.size(); ++i) s += (i ? ", " : "") + parts[i];
    return s + ") ";
  }

  // The user's `precise`, where the target has it (ES 3.20, desktop 4.00+, ES 3.10 with
  // GL_EXT_gpu_shader5); elsewhere it is dropped with one warning. The float-float rules do not
  // depend on it: they carry their own guard.
  std::string precise_keyword(const ir::Var& v) {
    if (!v.precise) return "";
    bool gpu_shader5 = std::find(options_.extensions.begin(), options_.extensions.end(), "GL_EXT_gpu_shader5") !=
                       options_.extensions.end();
    if (es_ ? version_ >= 320 || gpu_shader5 : version_ >= 400) return "precise ";
    if (!precise_dropped_) {
      precise_dropped_ = true;
      diags_.push_back({ir::file_of(v.loc, file_), v.loc.line, v.loc.column, Severity::Warning,
                        "'precise' on '" + v.name + "' is dropped: target " + target_name() +
                            " has no 'precise' qualifier (ES 3.20, desktop 4.00+, or ES 3.10 with GL_EXT_gpu_shader5), "
                            "so the driver may reorder or fuse that float arithmetic; target es320 or glsl450 to keep it"});
    }
    return "";
  }

  std::string interpolation(ir::Interp interp) {
    if (options_.target == Target::Es100) return "";
    if (interp == ir::Interp::Flat) return "flat ";
    if (interp == ir::Interp::Centroid) return "centroid ";
    if (interp == ir::Interp::NoPerspective && !es_) return "noperspective ";
    return "";
  }

  std::string qualifiers(const ir::Var& v) {
    std::string s;
    if (v.invariant) s += "invariant ";
    s += precise_keyword(v);
    s += layout(v);
    bool interface = v.storage == ir::Storage::In || v.storage == ir::Storage::Out;
    if (interface && v.patch) s += "patch ";
    if (interface) s += interpolation(v.interp);
    if (v.coherent) s += "coherent ";
    if (v.volatile_) s += "volatile ";
    if (v.restrict_) s += "restrict ";
    if (v.readonly) s += "readonly ";
    if (v.writeonly) s += "writeonly ";
    std::string kw = storage_keyword(v);
    if (!kw.empty()) s += kw + " ";
    return s;
  }

  // The user's place of what is printed next (PrintResult::source_lines).
  void mark(const ir::Loc& loc) {
    if (loc.line > 0) marks_.emplace_back(static_cast<size_t>(out_.tellp()), loc);
  }

  void global(const ir::VarPtr& v, const ir::ExprPtr& init) {
    if (v.get() == frag_output_ || hoisted_.count(v.get())) return;
    if (v->storage == ir::Storage::BuiltIn) return;
    mark(v->loc);
    if (v->type.base == ir::Base::Block) {
      out_ << qualifiers(*v) << v->type.name << " {\n";
      for (const auto& f : *v->type.fields) out_ << "  " << interpolation(f.interp) << declarator(f.type, f.name) << ";\n";
      out_ << "}";
      if (v->name.rfind("anon@", 0) != 0) out_ << " " << v->name << ir::array_suffix(v->type);
      out_ << ";\n";
      return;
    }
    out_ << qualifiers(*v) << declarator(v->type, v->name);
    if (init) out_ << " = " << argument(init);
    out_ << ";\n";
  }

  std::string signature(const ir::Function& f) {
    // An array return type keeps its size (`float[4] foo(...)`: printed `float foo` before, web.array.frag).
    std::string s = ir::type_name(f.return_type) + ir::array_suffix(f.return_type) + " " + f.name + "(";
    for (size_t i = 0; i < f.params.size(); ++i) {
      const auto& p = *f.params[i];
      if (i) s += ", ";
      // An image argument may not drop a memory qualifier (spv.paramMemory.frag, reflection.vert).
      if (p.coherent) s += "coherent ";
      if (p.volatile_) s += "volatile ";
      if (p.restrict_) s += "restrict ";
      if (p.readonly) s += "readonly ";
      if (p.writeonly) s += "writeonly ";
      if (p.storage == ir::Storage::ParamOut) s += "out ";
      if (p.storage == ir::Storage::ParamInOut) s += "inout ";
      s += declarator(p.type, p.name);
    }
    return s + ")";
  }

  // ---- statements ----------------------------------------------------------
  void indent(int depth) { out_ << std::string(static_cast<size_t>(depth) * 2, ' '); }

  std::string decl_text(const Stmt& s) {
    std::string text = precise_keyword(*s.var) + declarator(s.var->type, s.var->name);
    if (s.expr) text += " = " + argument(s.expr);
    return text;
  }

  std::string simple_statement(const ir::StmtPtr& s) {
    if (!s) return "";
    if (s->kind == Stmt::Kind::Decl) return decl_text(*s);
    if (s->kind == Stmt::Kind::Expr) return expr(s->expr);
    return "";
  }

  void statement(const ir::StmtPtr& s, int depth) {
    mark(s->loc);
    switch (s->kind) {
      case Stmt::Kind::Block:
        indent(depth);
        out_ << "{\n";
        for (const auto& b : s->body) statement(b, depth + 1);
        indent(depth);
        out_ << "}\n";
        return;
      case Stmt::Kind::Expr: indent(depth); out_ << expr(s->expr) << ";\n"; return;
      case Stmt::Kind::Decl: indent(depth); out_ << decl_text(*s) << ";\n"; return;
      case Stmt::Kind::If:
        indent(depth);
        out_ << "if (" << expr(s->expr) << ")\n";
        statement(s->body[0], depth);
        if (s->body.size() > 1) {
          indent(depth);
          out_ << "else\n";
          statement(s->body[1], depth);
        }
        return;
      case Stmt::Kind::Loop:
        indent(depth);
        if (!s->test_first) {
          out_ << "do\n";
          statement(s->body[1], depth);
          indent(depth);
          out_ << "while (" << expr(s->expr) << ");\n";
          return;
        }
        if (!s->body[0] && !s->step && s->expr) {
          out_ << "while (" << expr(s->expr) << ")\n";
        } else {
          out_ << "for (" << simple_statement(s->body[0]) << "; " << (s->expr ? expr(s->expr) : "") << "; "
               << (s->step ? expr(s->step) : "") << ")\n";
        }
        statement(s->body[1], depth);
        return;
      case Stmt::Kind::Switch:
        indent(depth);
        out_ << "switch (" << expr(s->expr) << ")\n";
        statement(s->body[0], depth);
        return;
      case Stmt::Kind::Case: indent(depth - 1); out_ << "case " << expr(s->expr) << ":\n"; return;
      case Stmt::Kind::Default: indent(depth - 1); out_ << "default:\n"; return;
      case Stmt::Kind::Break: indent(depth); out_ << "break;\n"; return;
      case Stmt::Kind::Continue: indent(depth); out_ << "continue;\n"; return;
      case Stmt::Kind::Discard: indent(depth); out_ << "discard;\n"; return;
      case Stmt::Kind::Return:
        indent(depth);
        out_ << "return" << (s->expr ? " " + expr(s->expr) : "") << ";\n";
        return;
    }
  }

  // ---- expressions ---------------------------------------------------------
  std::string scalar(const ir::Scalar& v) {
    switch (v.base) {
      case ir::Base::Bool: return v.b ? "true" : "false";
      case ir::Base::Int: return std::to_string(v.i);
      case ir::Base::Uint: return std::to_string(v.i) + "u";
      // -2^63 has no literal of its own (its magnitude overflows int64_t before the minus applies).
      case ir::Base::Int64: return v.i == LLONG_MIN ? "(-9223372036854775807l - 1l)" : std::to_string(v.i) + "l";
      case ir::Base::Uint64: return std::to_string(static_cast<unsigned long long>(v.i)) + "ul";
      case ir::Base::Float: return float_literal(static_cast<float>(v.d));
      case ir::Base::Double: {  // only mode native keeps doubles
        // GLSL has no infinity or NaN literal; glslang folds these divisions to them (`1e+309` in
        // glslang's own stringToDouble.vert printed as `inf.0lf` before).
        if (std::isinf(v.d)) return v.d > 0 ? "(1.0lf / 0.0lf)" : "(-1.0lf / 0.0lf)";
        if (std::isnan(v.d)) return "(0.0lf / 0.0lf)";
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.17g", v.d);
        std::string s = buf;
        if (s.find_first_of(".e") == std::string::npos) s += ".0";
        else if (s.find('.') == std::string::npos) s.insert(s.find('e'), ".0");
        return s + "lf";
      }
      default: return "<double constant>";
    }
  }

  std::string constant(const Expr& e) {
    ir::Type elem = e.type;
    elem.array_dims.clear();
    size_t per = static_cast<size_t>(elem.vec) * static_cast<size_t>(std::max(elem.cols, 1));
    auto one = [&](size_t start) {
      if (per == 1) return scalar(e.values[start]);
      bool same = true;
      for (size_t i = 1; i < per; ++i) same &= scalar(e.values[start + i]) == scalar(e.values[start]);
      std::string s = ir::type_name(elem) + "(";
      for (size_t i = 0; i < (same && !elem.is_matrix() ? 1 : per); ++i) s += (i ? ", " : "") + scalar(e.values[start + i]);
      return s + ")";
    };
    if (!e.type.is_array()) return e.values.empty() ? "0" : one(0);
    std::string s = ir::type_name(elem) + ir::array_suffix(e.type) + "(";
    for (size_t i = 0; i * per < e.values.size(); ++i) s += (i ? ", " : "") + one(i * per);
    return s + ")";
  }

  // GLSL precedence, highest binds tightest (GLSL ES 3.00 §5.1):
  // primary 17, postfix 16, prefix 15, * / % 14 … || 4, ?: 3, assignment 2, comma 1.
  static int precedence(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::Comma: return 1;
      case Expr::Kind::Ternary: return 3;
      case Expr::Kind::Unary: return e.op == "x++" || e.op == "x--" ? 16 : 15;
      case Expr::Kind::Const:  // a negative scalar literal (-0.0 and -1 too) prints as a prefix minus
        return e.type.vec == 1 && !e.type.is_matrix() && !e.type.is_array() && !e.values.empty() &&
                       is_negative(e.values[0])
                   ? 15
                   : 17;
      case Expr::Kind::Binary: {
        static const std::map<std::string, int> table{
            {"*", 14}, {"/", 14}, {"%", 14}, {"+", 13}, {"-", 13}, {"<<", 12}, {">>", 12}, {"<", 11}, {">", 11},
            {"<=", 11}, {">=", 11}, {"==", 10}, {"!=", 10}, {"&", 9}, {"^", 8}, {"|", 7}, {"&&", 6}, {"^^", 5}, {"||", 4}};
        auto it = table.find(e.op);
        return it == table.end() ? 2 : it->second;  // not in the table: an assignment
      }
      default: return 17;
    }
  }

  static bool is_negative(const ir::Scalar& v) {
    if (v.base == ir::Base::Int) return v.i < 0;
    return (v.base == ir::Base::Float || v.base == ir::Base::Double) && std::signbit(v.d);
  }

  // `e` where the grammar wants an assignment_expression (a function or constructor argument, an
  // initialiser): a comma expression there needs its parentheses, or its parts become arguments.
  std::string argument(const ir::ExprPtr& e) { return operand(e, 2, false); }

  // `e` printed as an operand of an operator of precedence `parent`;
  // `tie_needs_parens` for the side where equal precedence changes meaning.
  std::string operand(const ir::ExprPtr& e, int parent, bool tie_needs_parens = true, bool parent_binary = false) {
    std::string s = expr(e);
    int p = precedence(*e);
    bool parens = p < parent || (p == parent && tie_needs_parens);
    // For the reader: group mixed operators unless both are arithmetic (a*b + c stays).
    if (parent_binary && e->kind == Expr::Kind::Binary && p != parent && p > 2 && !(p >= 13 && parent >= 13))
      parens = true;
    return parens ? "(" + s + ")" : s;
  }

  std::string call(const std::string& name, const std::vector<ir::ExprPtr>& args) {
    std::string s = name + "(";
    for (size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + argument(args[i]);
    return s + ")";
  }

  std::string builtin_name(const Expr& e) {
    if (options_.target != Target::Es100) return e.name;
    std::string sampler = e.args.empty() ? "" : e.args[0]->type.name;
    std::string dim = sampler == "samplerCube" ? "Cube" : "2D";
    if (e.name == "texture") return "texture" + dim;
    if (e.name == "textureProj") return "texture2DProj";
    if (e.name == "textureLod") return "texture" + dim + "Lod";
    if (e.name == "textureProjLod") return "texture2DProjLod";
    return e.name;
  }

  std::string symbol(const ir::Var& v) {
    if (&v == frag_output_) return "gl_FragColor";
    if (v.name == "gl_FragColor" && frag_color_declared_) return "df_frag_color";  // ES 3.00+/core lack it
    if (v.name == "gl_FragData" && frag_data_size_) return "df_frag_data";
    return v.name;
  }

  std::string expr(const ir::ExprPtr& e) {
    switch (e->kind) {
      case Expr::Kind::Sym:
        if (e->var->storage == ir::Storage::BuiltIn)
          builtin_first_use_.emplace(symbol(*e->var), PrintResult::BuiltinUse{e->loc, e->var->name});
        return symbol(*e->var);
      case Expr::Kind::Const: return constant(*e);
      case Expr::Kind::Unary: {
        const std::string& op = e->op;
        if (op == "x++" || op == "x--") return operand(e->args[0], 16) + op.substr(1);
        if (op == "++x" || op == "--x") return op.substr(0, 2) + operand(e->args[0], 15);
        return op + operand(e->args[0], 15);  // `-(-x)`, never `--x`
      }
      case Expr::Kind::Binary: {
        int p = precedence(*e);
        bool assignment = p == 2;  // right-associative; the others are left-associative
        return operand(e->args[0], p, assignment, !assignment) + " " + e->op + " " +
               operand(e->args[1], p, !assignment, !assignment);
      }
      case Expr::Kind::Ternary:
        return operand(e->args[0], 4, false) + " ? " + operand(e->args[1], 4, false) + " : " + operand(e->args[2], 4, false);
      case Expr::Kind::Call: return call(e->name, e->args);
      case Expr::Kind::Builtin:
        if (ir::is_array_length(*e)) return operand(e->args[0], 17, false) + ".length()";
        builtin_first_use_.emplace(builtin_name(*e), PrintResult::BuiltinUse{e->loc, e->name});
        return call(builtin_name(*e), e->args);
      case Expr::Kind::Construct: return call(ir::type_name(e->type) + ir::array_suffix(e->type), e->args);
      case Expr::Kind::Member: return operand(e->args[0], 17, false) + "." + e->name;
      case Expr::Kind::Index: {
        // glslang turns `.y` into `[1]`; give vectors their swizzle back.
        const ir::Type& base = e->args[0]->type;
        const ir::ExprPtr& index = e->args[1];
        if (frag_data_size_ && !frag_data_dynamic_ && e->args[0]->kind == Expr::Kind::Sym &&
            e->args[0]->var->name == "gl_FragData")
          return "df_frag_data_" + std::to_string(constant_frag_data_index(*e));
        if (!base.is_array() && !base.is_matrix() && base.vec > 1 && base.name.empty() &&
            index->kind == Expr::Kind::Const && index->values.size() == 1 && index->values[0].i >= 0 &&
            index->values[0].i < 4)
          return operand(e->args[0], 17, false) + "." + "xyzw"[index->values[0].i];
        return operand(e->args[0], 17, false) + "[" + expr(index) + "]";
      }
      case Expr::Kind::Comma: {
        std::string s;
        for (size_t i = 0; i < e->args.size(); ++i) s += (i ? ", " : "") + argument(e->args[i]);
        return s;
      }
    }
    return "";
  }

  const ir::Module& module_;
  const PrintOptions& options_;
  std::string file_;
  bool es_;
  int version_;
  std::ostringstream out_;
  std::vector<Diagnostic> diags_;
  const ir::Var* frag_output_ = nullptr;
  bool structs_printed_ = false;
  std::set<const ir::Var*> hoisted_;  // loose uniforms printed before the runtime (hoist_loose_uniforms)
  bool frag_color_declared_ = false;
  int frag_data_size_ = 0;  // elements of df_frag_data, the gl_FragData stand-in (0: not used)
  bool frag_data_dynamic_ = false;  // an index is computed: one array instead of one output per slot
  std::set<int> frag_data_slots_;
  std::map<std::string, PrintResult::BuiltinUse> builtin_first_use_;
  std::vector<std::pair<size_t, ir::Loc>> marks_;  // output byte offset → the user's place
  bool precise_dropped_ = false;  // the warning is given once
};

}  // namespace

std::string expression_text(const ir::ExprPtr& e, Target target) {
  static const ir::Module no_module;
  PrintOptions options;
  options.target = target;
  return Printer(no_module, options, "").expression(e);
}

PrintResult print(const ir::Module& module, const PrintOptions& options, const std::string& file_name) {
  return Printer(module, options, file_name).run();
}

}  // namespace doublet::emit
