#include "ir/ir.hpp"

namespace doublet::ir {

bool Type::contains_double() const {
  if (base == Base::Double) return true;
  if (fields)
    for (const Field& f : *fields)
      if (f.type.contains_double()) return true;
  return false;
}

Type Type::element() const {
  Type t = *this;
  if (!t.array_dims.empty()) t.array_dims.erase(t.array_dims.begin());
  return t;
}

Type Type::with_base(Base b) const {
  Type t = *this;
  t.base = b;
  return t;
}

Type scalar_type(Base b, int vec) {
  Type t;
  t.base = b;
  t.vec = vec;
  return t;
}

std::string type_name(const Type& t) {
  if (!t.name.empty()) return t.name;
  if (t.is_matrix()) {
    std::string prefix = t.base == Base::Double ? "dmat" : "mat";
    if (t.cols == t.vec) return prefix + std::to_string(t.cols);
    return prefix + std::to_string(t.cols) + "x" + std::to_string(t.vec);
  }
  const char* scalar = "void";
  const char* vecp = "";
  switch (t.base) {
    case Base::Bool: scalar = "bool"; vecp = "bvec"; break;
    case Base::Int: scalar = "int"; vecp = "ivec"; break;
    case Base::Uint: scalar = "uint"; vecp = "uvec"; break;
    case Base::Int64: scalar = "int64_t"; vecp = "i64vec"; break;
    case Base::Uint64: scalar = "uint64_t"; vecp = "u64vec"; break;
    case Base::Float: scalar = "float"; vecp = "vec"; break;
    case Base::Double: scalar = "double"; vecp = "dvec"; break;
    default: return "void";
  }
  if (t.vec == 1) return scalar;
  return std::string(vecp) + std::to_string(t.vec);
}

ExprPtr make_node(Expr::Kind k, const std::string& name, Type type, std::vector<ExprPtr> args, Loc loc) {
  auto e = Expr::make(k, std::move(type), loc);
  e->name = name;
  e->args = std::move(args);
  return e;
}

bool is_array_length(const Expr& e) {
  return e.kind == Expr::Kind::Builtin && e.name == "length" && e.args.size() == 1 && e.args[0]->type.is_array();
}

bool is_pure(const ExprPtr& e) {
  switch (e->kind) {
    case Expr::Kind::Sym:
    case Expr::Kind::Const: return true;
    case Expr::Kind::Member: return is_pure(e->args[0]);
    case Expr::Kind::Index: return is_pure(e->args[0]) && is_pure(e->args[1]);
    default: return false;
  }
}

bool is_assignment_operator(const std::string& op) {
  return !op.empty() && op.back() == '=' && op != "==" && op != "!=" && op != "<=" && op != ">=";
}

bool is_increment(const Expr& e) {
  return e.kind == Expr::Kind::Unary && (e.op == "++x" || e.op == "--x" || e.op == "x++" || e.op == "x--");
}

bool builtin_writes_second_argument(const Expr& e) {
  return e.kind == Expr::Kind::Builtin && (e.name == "modf" || e.name == "frexp") && e.args.size() == 2;
}

size_t unconditional_operands(const Expr& e) {
  if ((e.kind == Expr::Kind::Binary && (e.op == "&&" || e.op == "||")) || e.kind == Expr::Kind::Ternary) return 1;
  return e.args.size();
}

bool builtin_has_side_effects(const std::string& name) {
  static const char* const kPrefixes[] = {"atomic", "imageAtomic", "imageStore", "memoryBarrier", "EmitVertex",
                                          "EndPrimitive", "subgroupBarrier", "subgroupMemoryBarrier"};
  for (const char* p : kPrefixes)
    if (name.rfind(p, 0) == 0) return true;
  static const char* const kNames[] = {"modf", "frexp", "uaddCarry", "usubBorrow", "umulExtended", "imulExtended",
                                       "barrier", "groupMemoryBarrier"};
  for (const char* n : kNames)
    if (name == n) return true;
  return false;
}

Var* root_variable(ExprPtr e) {
  while ((e->kind == Expr::Kind::Member || e->kind == Expr::Kind::Index) && !e->args.empty()) e = e->args[0];
  return e->kind == Expr::Kind::Sym ? e->var.get() : nullptr;
}

bool has_side_effects(const ExprPtr& e) {
  switch (e->kind) {
    case Expr::Kind::Unary:
      if (e->op.find("++") != std::string::npos || e->op.find("--") != std::string::npos) return true;
      break;
    case Expr::Kind::Binary:
      if (is_assignment_operator(e->op)) return true;
      break;
    case Expr::Kind::Call: return true;
    case Expr::Kind::Builtin:
      if (builtin_has_side_effects(e->name)) return true;
      break;
    default: break;
  }
  for (const auto& a : e->args)
    if (has_side_effects(a)) return true;
  return false;
}

ExprPtr clone(const ExprPtr& e) {
  auto c = std::make_shared<Expr>(*e);
  for (auto& a : c->args) a = clone(a);
  return c;
}

bool is_compound_arithmetic(const std::string& op) { return op == "+=" || op == "-=" || op == "*=" || op == "/="; }

std::string join_identifier(const std::string& name, const std::string& suffix) {
  if (name.empty() || name.back() != '_') return name + suffix;
  size_t first = suffix.find_first_not_of('_');
  return name + (first == std::string::npos ? "" : suffix.substr(first));
}

std::string array_suffix(const Type& t) {
  std::string s;
  for (int d : t.array_dims) s += d > 0 ? "[" + std::to_string(d) + "]" : "[]";
  return s;
}

ExprPtr make_sym(const VarPtr& v, Loc loc) {
  auto e = Expr::make(Expr::Kind::Sym, v->type, loc);
  e->var = v;
  return e;
}

ExprPtr make_sym(const VarPtr& v) { return make_sym(v, v->loc); }

ExprPtr make_binary(const std::string& op, Type type, ExprPtr a, ExprPtr b) {
  auto e = Expr::make(Expr::Kind::Binary, std::move(type), a->loc);
  e->op = op;
  e->args = {std::move(a), std::move(b)};
  return e;
}

ExprPtr make_assign(const ExprPtr& target, const ExprPtr& value) {
  auto e = make_binary("=", target->type, target, value);
  e->loc = value->loc;
  return e;
}

ExprPtr make_int(int value, Loc loc) {
  auto e = Expr::make(Expr::Kind::Const, scalar_type(Base::Int), loc);
  Scalar s;
  s.base = Base::Int;
  s.i = value;
  e->values = {s};
  return e;
}

ExprPtr make_index(const ExprPtr& array, int k) {
  auto e = Expr::make(Expr::Kind::Index, array->type.element());
  e->args = {array, make_int(k)};
  return e;
}

StmtPtr make_statement(const ExprPtr& e) {
  auto s = Stmt::make(Stmt::Kind::Expr, e->loc);
  s->expr = e;
  return s;
}

std::vector<const Function*> overloads(const Module& m, const Expr& call,
                                       const std::function<bool(const Var& param, const Expr& arg)>& param_matches) {
  std::vector<const Function*> found;
  for (const auto& f : m.functions) {
    if (f->name != call.name || f->params.size() != call.args.size()) continue;
    bool match = true;
    for (size_t i = 0; i < f->params.size() && match; ++i) match = param_matches(*f->params[i], *call.args[i]);
    if (match) found.push_back(f.get());
  }
  return found;
}

}  // namespace doublet::ir
