#include "round_trip.hpp"

#include <cstdio>
#include <memory>
#include <vector>

#include "emit/printer.hpp"
#include "frontend/frontend.hpp"
#include "frontend/import.hpp"

namespace doublet::roundtrip {
namespace {

using ir::Base;
using ir::Expr;
using ir::ExprPtr;
using ir::Stmt;
using ir::StmtPtr;
using Kind = ir::Expr::Kind;

// The value types the generator builds expressions of.
enum class Shape { Float, Vec2, Vec3, Int, Bool };
constexpr Shape kShapes[] = {Shape::Float, Shape::Vec2, Shape::Vec3, Shape::Int, Shape::Bool};

ir::Type type_of(Shape s) {
  switch (s) {
    case Shape::Float: return ir::scalar_type(Base::Float);
    case Shape::Vec2: return ir::scalar_type(Base::Float, 2);
    case Shape::Vec3: return ir::scalar_type(Base::Float, 3);
    case Shape::Int: return ir::scalar_type(Base::Int);
    case Shape::Bool: return ir::scalar_type(Base::Bool);
  }
  return {};
}

bool is_vector(Shape s) { return s == Shape::Vec2 || s == Shape::Vec3; }
int width(Shape s) { return s == Shape::Vec2 ? 2 : s == Shape::Vec3 ? 3 : 1; }
Shape vector_of(int n) { return n == 1 ? Shape::Float : n == 2 ? Shape::Vec2 : Shape::Vec3; }

ir::VarPtr variable(const std::string& name, ir::Type type, ir::Storage storage) {
  auto v = std::make_shared<ir::Var>();
  v->name = name;
  v->type = type;
  v->declared_type = type;
  v->storage = storage;
  return v;
}

ExprPtr sym(const ir::VarPtr& v) {
  auto e = Expr::make(Kind::Sym, v->type);
  e->var = v;
  return e;
}

// `op_or_name`: the operator of a Unary/Binary, the name of a Call/Builtin/Member.
ExprPtr node(Kind kind, ir::Type type, std::vector<ExprPtr> args, const std::string& op_or_name = "") {
  auto e = ir::make_node(kind, "", std::move(type), std::move(args), {});
  (kind == Kind::Unary || kind == Kind::Binary ? e->op : e->name) = op_or_name;
  return e;
}

class Generator {
 public:
  explicit Generator(const Chooser& choose) : choose_(choose) {
    for (Shape s : kShapes) {
      const std::string suffix = shape_suffix(s);
      for (int i = 0; i < 2; ++i) {
        uniforms_.push_back(variable("u" + suffix + std::to_string(i), type_of(s), ir::Storage::Uniform));
        module_.globals.push_back(uniforms_.back());
        module_.global_inits.push_back(nullptr);
      }
      locals_.push_back(variable("l" + suffix, type_of(s), ir::Storage::Local));
    }
    ir::Type array = type_of(Shape::Float);
    array.array_dims = {4};
    table_ = variable("table", array, ir::Storage::Uniform);
    module_.globals.push_back(table_);
    module_.global_inits.push_back(nullptr);
    module_.stage = ir::StageKind::Fragment;
    // float f(float a), float f(vec2 a, float b), vec2 g(vec2 a): one overload set, so that a
    // comma expression printed without its parentheses calls the other f.
    add_function("f", Shape::Float, {Shape::Float});
    add_function("f", Shape::Float, {Shape::Vec2, Shape::Float});
    add_function("g", Shape::Vec2, {Shape::Vec2});
  }

  ir::Module run(int statements, int depth) {
    auto main = std::make_shared<ir::Function>();
    main->name = "main";
    main->body = Stmt::make(Stmt::Kind::Block);
    // Locals first, each initialised from uniforms only (it is declared where it is first used).
    for (const auto& local : locals_) {
      auto d = Stmt::make(Stmt::Kind::Decl);
      d->var = local;
      d->expr = pure_expression(shape_of(local->type), depth);
      main->body->body.push_back(d);
    }
    locals_declared_ = true;
    for (int i = 0; i < statements; ++i) main->body->body.push_back(statement(depth));
    module_.functions.push_back(main);
    return std::move(module_);
  }

 private:
  static std::string shape_suffix(Shape s) {
    switch (s) {
      case Shape::Float: return "f";
      case Shape::Vec2: return "v2_";
      case Shape::Vec3: return "v3_";
      case Shape::Int: return "i";
      case Shape::Bool: return "b";
    }
    return "";
  }

  static Shape shape_of(const ir::Type& t) {
    if (t.base == Base::Int) return Shape::Int;
    if (t.base == Base::Bool) return Shape::Bool;
    return vector_of(t.vec);
  }

  void add_function(const std::string& name, Shape result, const std::vector<Shape>& params) {
    auto f = std::make_shared<ir::Function>();
    f->name = name;
    f->return_type = type_of(result);
    for (size_t i = 0; i < params.size(); ++i)
      f->params.push_back(variable(std::string(1, static_cast<char>('a' + i)), type_of(params[i]), ir::Storage::ParamIn));
    auto ret = Stmt::make(Stmt::Kind::Return);
    // f(vec2 a, float b) returns a.x * b; the others return their first parameter.
    ret->expr = params.size() == 2 ? node(Kind::Binary, type_of(Shape::Float),
                                          {swizzle(sym(f->params[0]), "x"), sym(f->params[1])}, "*")
                                   : sym(f->params[0]);
    f->body = Stmt::make(Stmt::Kind::Block);
    f->body->body = {ret};
    module_.functions.push_back(f);
  }

  uint32_t pick(uint32_t bound) { return bound <= 1 ? 0 : choose_(bound) % bound; }
  bool chance(uint32_t percent) { return pick(100) < percent; }

  StmtPtr statement(int depth) {
    switch (pick(4)) {
      case 0: {  // if (bool) { assignment } else { assignment }
        auto s = Stmt::make(Stmt::Kind::If);
        s->expr = expression(Shape::Bool, depth, false);
        s->body = {block(assignment_statement(depth)), block(assignment_statement(depth))};
        return s;
      }
      case 1: {  // for (; bool; any expression) { assignment }
        auto s = Stmt::make(Stmt::Kind::Loop);
        s->expr = expression(Shape::Bool, depth, false);
        s->step = expression(kShapes[pick(5)], depth, false);
        s->body = {nullptr, block(assignment_statement(depth))};
        return s;
      }
      default: return assignment_statement(depth);
    }
  }

  static StmtPtr block(StmtPtr s) {
    auto b = Stmt::make(Stmt::Kind::Block);
    b->body = {std::move(s)};
    return b;
  }

  StmtPtr assignment_statement(int depth) {
    auto s = Stmt::make(Stmt::Kind::Expr);
    s->expr = assignment(kShapes[pick(5)], depth);
    return s;
  }

  // An initialiser: uniforms, operators and calls; no locals, no assignments.
  ExprPtr pure_expression(Shape s, int depth) {
    pure_ = true;
    ExprPtr e = expression(s, depth, false);
    pure_ = false;
    return e;
  }

  ExprPtr constant(Shape s) {
    auto e = Expr::make(Kind::Const, type_of(s));
    for (int i = 0; i < width(s); ++i) {
      ir::Scalar v;
      v.base = type_of(s).base;
      if (s == Shape::Bool) v.b = chance(50);
      else if (s == Shape::Int) v.i = static_cast<long long>(pick(9)) + 1;  // never 0: x / 0 is an error
      else v.d = (static_cast<double>(pick(17)) - 8.0) * 0.75;
      e->values.push_back(v);
    }
    if (s == Shape::Int && chance(30)) e->values[0].i = -e->values[0].i;
    return e;
  }

  ExprPtr leaf(Shape s, bool allow_constant) {
    if (allow_constant && chance(20)) return constant(s);
    std::vector<ir::VarPtr> candidates;
    for (const auto& u : uniforms_)
      if (shape_of(u->type) == s) candidates.push_back(u);
    if (locals_declared_ && !pure_)
      for (const auto& l : locals_)
        if (shape_of(l->type) == s) candidates.push_back(l);
    if (s == Shape::Float && chance(15)) return index(sym(table_), Shape::Float, 0);
    return sym(candidates[pick(static_cast<uint32_t>(candidates.size()))]);
  }

  static bool is_constant(const ExprPtr& e) { return e->kind == Kind::Const; }

  // An expression of shape `s`, at most `depth` operators deep. `allow_constant`: a bare
  // constant is fine here (an operand next to a non-constant one).
  ExprPtr expression(Shape s, int depth, bool allow_constant) {
    if (depth <= 0 || chance(20)) return leaf(s, allow_constant);
    const int d = depth - 1;
    const int productions = pure_ ? 6 : 9;
    switch (pick(productions)) {
      case 0: return operation(s, d);
      case 1: return operation(s, d);
      case 2: {  // cond ? a : b
        ExprPtr c = expression(Shape::Bool, d, false);
        return node(Kind::Ternary, type_of(s), {c, expression(s, d, true), expression(s, d, true)});
      }
      case 3: return call_or_construct(s, d);
      case 4: return selection(s, d);
      case 5: {  // (a, b): the left operand of any shape
        ExprPtr left = expression(kShapes[pick(5)], d, false);
        return node(Kind::Comma, type_of(s), {left, expression(s, d, false)});
      }
      case 6: return assignment(s, d);
      case 7:
        if (s == Shape::Float || s == Shape::Int) return step(s);
        return assignment(s, d);
      default: return operation(s, d);
    }
  }

  ExprPtr step(Shape s) {
    static const char* const kOps[] = {"++x", "--x", "x++", "x--"};
    return node(Kind::Unary, type_of(s), {sym(local(s))}, kOps[pick(4)]);
  }

  const ir::VarPtr& local(Shape s) {
    for (const auto& l : locals_)
      if (shape_of(l->type) == s) return l;
    return locals_[0];
  }

  // lX = e, lX op= e, or a swizzle of a vector local written: lv3_.zx = e.
  ExprPtr assignment(Shape s, int depth) {
    ExprPtr target;
    if (s == Shape::Float && chance(30)) {
      target = swizzle(sym(local(Shape::Vec3)), std::string(1, "xyz"[pick(3)]));
    } else if (s == Shape::Vec2 && chance(30)) {
      static const char* const kPairs[] = {"zx", "xy", "yz"};
      target = swizzle(sym(local(Shape::Vec3)), kPairs[pick(3)]);
    } else {
      target = sym(local(s));
    }
    std::string op = "=";
    if (s == Shape::Float || is_vector(s)) {
      static const char* const kOps[] = {"=", "+=", "-=", "*=", "/="};
      op = kOps[pick(5)];
    } else if (s == Shape::Int) {
      static const char* const kOps[] = {"=", "+=", "-=", "*=", "%=", "&=", "|=", "^=", "<<=", ">>="};
      op = kOps[pick(10)];
    }
    return node(Kind::Binary, type_of(s), {target, expression(s, depth, op == "=")}, op);
  }

  static ExprPtr swizzle(ExprPtr base, const std::string& letters) {
    return node(Kind::Member, type_of(vector_of(static_cast<int>(letters.size()))), {std::move(base)}, letters);
  }

  // base[i]: i a constant in range or an int expression.
  ExprPtr index(ExprPtr base, Shape element, int depth) {
    int size = base->type.is_array() ? base->type.array_dims[0] : base->type.vec;
    ExprPtr i;
    if (chance(40)) {
      i = constant(Shape::Int);
      i->values[0].i = pick(static_cast<uint32_t>(size));
    } else {
      i = expression(Shape::Int, depth, false);
    }
    return node(Kind::Index, type_of(element), {std::move(base), i});
  }

  // Components of a vector expression: v.zx, v.y, v[i], table[i].
  ExprPtr selection(Shape s, int depth) {
    if (s == Shape::Int || s == Shape::Bool) return operation(s, depth);
    Shape from = chance(50) ? Shape::Vec3 : Shape::Vec2;
    ExprPtr base = expression(from, depth, false);
    if (s == Shape::Float && chance(30)) return index(base, Shape::Float, depth);
    std::string letters;
    for (int i = 0; i < width(s); ++i) letters += "xyz"[pick(static_cast<uint32_t>(width(from)))];
    return swizzle(base, letters);
  }

  // Operands of a binary operation: at most one of them a bare constant.
  std::vector<ExprPtr> operands(Shape a, Shape b, int depth) {
    bool constant_first = chance(50);
    return {expression(a, depth, constant_first), expression(b, depth, !constant_first)};
  }

  ExprPtr operation(Shape s, int depth) {
    switch (s) {
      case Shape::Float:
      case Shape::Vec2:
      case Shape::Vec3: {
        if (chance(15)) return node(Kind::Unary, type_of(s), {expression(s, depth, false)}, "-");
        static const char* const kOps[] = {"+", "-", "*", "/"};
        std::string op = kOps[pick(4)];
        if (is_vector(s) && chance(30))  // vector op scalar, scalar op vector
          return chance(50) ? node(Kind::Binary, type_of(s), operands(s, Shape::Float, depth), op)
                            : node(Kind::Binary, type_of(s), operands(Shape::Float, s, depth), op);
        return node(Kind::Binary, type_of(s), operands(s, s, depth), op);
      }
      case Shape::Int: {
        if (chance(15)) return node(Kind::Unary, type_of(s), {expression(s, depth, false)}, chance(50) ? "-" : "~");
        static const char* const kOps[] = {"+", "-", "*", "/", "%", "<<", ">>", "&", "|", "^"};
        std::string op = kOps[pick(10)];
        if (op == "<<" || op == ">>")  // a constant shift count could be negative
          return node(Kind::Binary, type_of(s), {expression(s, depth, true), expression(s, depth, false)}, op);
        return node(Kind::Binary, type_of(s), operands(s, s, depth), op);
      }
      case Shape::Bool: {
        switch (pick(3)) {
          case 0: {
            static const char* const kOps[] = {"<", ">", "<=", ">=", "==", "!="};
            Shape of = chance(50) ? Shape::Float : Shape::Int;
            return node(Kind::Binary, type_of(s), operands(of, of, depth), kOps[pick(6)]);
          }
          case 1: {
            static const char* const kOps[] = {"&&", "||", "^^"};
            return node(Kind::Binary, type_of(s), operands(s, s, depth), kOps[pick(3)]);
          }
          default: return node(Kind::Unary, type_of(s), {expression(s, depth, false)}, "!");
        }
      }
    }
    return leaf(s, false);
  }

  ExprPtr call_or_construct(Shape s, int depth) {
    switch (s) {
      case Shape::Float:
        switch (pick(5)) {
          case 0: return node(Kind::Call, type_of(s), {expression(Shape::Float, depth, false)}, "f");
          case 1:
            return node(Kind::Call, type_of(s), operands(Shape::Vec2, Shape::Float, depth), "f");
          case 2: return node(Kind::Builtin, type_of(s), operands(Shape::Vec3, Shape::Vec3, depth), "dot");
          case 3: return node(Kind::Builtin, type_of(s), operands(s, s, depth), chance(50) ? "min" : "max");
          default: return node(Kind::Construct, type_of(s), {expression(Shape::Int, depth, false)});
        }
      case Shape::Vec2:
        if (chance(40)) return node(Kind::Call, type_of(s), {expression(s, depth, false)}, "g");
        return node(Kind::Construct, type_of(s), operands(Shape::Float, Shape::Float, depth));
      case Shape::Vec3:
        if (chance(30)) return node(Kind::Builtin, type_of(s), {expression(s, depth, false)}, "normalize");
        return node(Kind::Construct, type_of(s), operands(Shape::Vec2, Shape::Float, depth));
      case Shape::Int:
        if (chance(50)) return node(Kind::Builtin, type_of(s), {expression(s, depth, false)}, "abs");
        return node(Kind::Construct, type_of(s), {expression(Shape::Float, depth, false)});
      case Shape::Bool: return operation(s, depth);
    }
    return leaf(s, false);
  }

  const Chooser& choose_;
  ir::Module module_;
  std::vector<ir::VarPtr> uniforms_, locals_;
  ir::VarPtr table_;
  bool locals_declared_ = false;
  bool pure_ = false;
};

std::string describe_constant(const Expr& e) {
  std::string s;
  for (const auto& v : e.values) {
    char buf[40];
    if (v.base == Base::Bool) std::snprintf(buf, sizeof buf, "%s", v.b ? "true" : "false");
    else if (v.base == Base::Int || v.base == Base::Uint) std::snprintf(buf, sizeof buf, "%lld", v.i);
    else std::snprintf(buf, sizeof buf, "%.9g", v.d);
    s += (s.empty() ? "" : " ") + std::string(buf);
  }
  return "{" + s + "}";
}

// v.y and v[1] (glslang's spelling of a one-letter swizzle) are the same selection.
std::string swizzle_letters(const Expr& e) {
  if (e.kind == Kind::Member && e.args[0]->type.base != Base::Struct && !e.args[0]->type.is_array())
    return e.name;
  if (e.kind != Kind::Index) return "";
  const ir::Type& base = e.args[0]->type;
  const ExprPtr& i = e.args[1];
  if (base.is_array() || base.is_matrix() || base.vec < 2 || i->kind != Kind::Const || i->values.size() != 1) return "";
  return std::string(1, "xyzw"[i->values[0].i & 3]);
}

// A left-nested comma is one sequence: (a, b), c is a, b, c.
void comma_parts(const ExprPtr& e, std::vector<ExprPtr>& out) {
  if (e->kind != Kind::Comma) {
    out.push_back(e);
    return;
  }
  comma_parts(e->args[0], out);
  for (size_t i = 1; i < e->args.size(); ++i) out.push_back(e->args[i]);
}

}  // namespace

ir::Module random_module(const Chooser& choose, int statements, int depth) {
  return Generator(choose).run(statements, depth);
}

std::string describe(const ExprPtr& e) {
  std::string head;
  std::vector<ExprPtr> parts = e->args;
  if (std::string letters = swizzle_letters(*e); !letters.empty()) {
    head = "." + letters;
    parts = {e->args[0]};
  } else {
    switch (e->kind) {
      case Kind::Sym: head = e->var->name; break;
      case Kind::Const: head = describe_constant(*e); break;
      case Kind::Unary:
      case Kind::Binary: head = e->op; break;
      case Kind::Ternary: head = "?:"; break;
      case Kind::Call: head = "call " + e->name; break;
      case Kind::Builtin: head = "builtin " + e->name; break;
      case Kind::Construct: head = "construct"; break;
      case Kind::Member: head = "." + e->name; break;
      case Kind::Index: head = "[]"; break;
      case Kind::Comma:
        head = ",";
        parts.clear();
        comma_parts(e, parts);
        break;
    }
  }
  std::string s = "(" + head + " :" + ir::type_name(e->type) + ir::array_suffix(e->type);
  for (const auto& p : parts) s += " " + describe(p);
  return s + ")";
}

std::string describe(const StmtPtr& s) {
  if (!s) return "-";
  auto expr = [](const ExprPtr& e) { return e ? describe(e) : std::string("-"); };
  switch (s->kind) {
    case Stmt::Kind::Expr: return expr(s->expr) + ";\n";
    case Stmt::Kind::Decl: return "decl " + s->var->name + " = " + expr(s->expr) + ";\n";
    case Stmt::Kind::Block: {
      std::string out = "{\n";
      for (const auto& b : s->body) out += describe(b);
      return out + "}\n";
    }
    case Stmt::Kind::If:
      return "if " + expr(s->expr) + "\n" + describe(s->body[0]) + (s->body.size() > 1 ? "else\n" + describe(s->body[1]) : "");
    case Stmt::Kind::Loop:
      return "for " + describe(s->body[0]) + " ; " + expr(s->expr) + " ; " + expr(s->step) + "\n" + describe(s->body[1]);
    case Stmt::Kind::Return: return "return " + expr(s->expr) + ";\n";
    default: return "stmt " + std::to_string(static_cast<int>(s->kind)) + ";\n";
  }
}

std::string round_trip_difference(const ir::Module& module, Target target) {
  const StmtPtr* generated = nullptr;
  for (const auto& f : module.functions)
    if (f->name == "main") generated = &f->body;
  if (!generated) return "the module has no main";
  emit::PrintOptions print_options;
  print_options.target = target;
  const emit::PrintResult printed = emit::print(module, print_options, "round_trip.frag");
  if (!printed.diagnostics.empty()) return "the printer refused the module: " + printed.diagnostics[0].message;

  Options options;
  options.stage = Stage::Fragment;
  options.target = target;
  options.file_name = "round_trip.frag";
  frontend::ParsedShader parsed;
  std::vector<Diagnostic> diagnostics;
  ir::Module reparsed;
  if (!frontend::parse(printed.text, options, parsed, diagnostics) ||
      !frontend::import_module(parsed, options, reparsed, diagnostics)) {
    std::string log;
    for (const auto& d : diagnostics) log += format_diagnostic(d) + "\n";
    return "the printed text does not parse back:\n" + log + printed.text;
  }
  for (const auto& f : reparsed.functions) {
    if (f->name != "main") continue;
    const std::string want = describe(*generated), got = describe(f->body);
    if (want == got) return "";
    return "printed:\n" + printed.text + "\ngenerated:\n" + want + "\nparsed back:\n" + got;
  }
  return "main is missing from the printed text:\n" + printed.text;
}

}  // namespace doublet::roundtrip
