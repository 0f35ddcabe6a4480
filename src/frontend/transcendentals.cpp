#include "frontend/transcendentals.hpp"

#include <set>

#include "ir/walk.hpp"

namespace doublet::frontend {
namespace {

constexpr const char* kUnary[] = {"exp", "exp2", "log", "log2", "sin", "cos", "tan",
                                  "asin", "acos", "atan", "sinh", "cosh", "tanh"};
constexpr const char* kBinary[] = {"pow", "atan"};

}  // namespace

bool is_transcendental_name(std::string_view word) {
  for (const char* n : kUnary)
    if (word == n) return true;
  return word == "pow";
}

bool refuses_transcendental(std::string_view glslang_log) {
  for (const char* n : kUnary)
    if (glslang_log.find("'" + std::string(n) + "' : no matching overloaded function found") != std::string_view::npos)
      return true;
  return glslang_log.find("'pow' : no matching overloaded function found") != std::string_view::npos;
}

const std::string& transcendental_prototypes() {
  static const std::string text = [] {
    const char* types[] = {"double", "dvec2", "dvec3", "dvec4"};
    std::string s;
    for (const char* t : types) {
      for (const char* n : kUnary) s += std::string(t) + " " + n + "(" + t + " x);";
      for (const char* n : kBinary) s += std::string(t) + " " + n + "(" + t + " a, " + t + " b);";
    }
    return s + "\n";
  }();
  return text;
}

void mark_transcendental_calls(ir::Module& module) {
  std::set<std::string> defined;
  for (const auto& f : module.functions) defined.insert(f->name);
  auto mark = [&](const ir::ExprPtr& e) -> ir::ExprPtr {
    if (e->kind == ir::Expr::Kind::Call && is_transcendental_name(e->name) && !defined.count(e->name)) e->kind = ir::Expr::Kind::Builtin;
    return e;
  };
  for (size_t i = 0; i < module.global_inits.size(); ++i)
    if (module.global_inits[i]) module.global_inits[i] = ir::rewrite(module.global_inits[i], mark);
  for (const auto& f : module.functions) ir::rewrite(f->body, mark);
}

}  // namespace doublet::frontend
