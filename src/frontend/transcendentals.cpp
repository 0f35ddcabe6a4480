#include "frontend/transcendentals.hpp"

#include <cctype>
#include <set>

#include "ir/walk.hpp"

namespace doublet::frontend {
namespace {

constexpr const char* kUnary[] = {"exp", "exp2", "log", "log2", "sin", "cos", "tan",
                                  "asin", "acos", "atan", "sinh", "cosh", "tanh"};
constexpr const char* kBinary[] = {"pow", "atan"};

bool is_name(std::string_view word) {
  for (const char* n : kUnary)
    if (word == n) return true;
  return word == "pow";
}

}  // namespace

bool mentions_transcendental(std::string_view text) {
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t i = 0; i < text.size();) {
    if (!is_word(text[i]) || (i > 0 && is_word(text[i - 1]))) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < text.size() && is_word(text[end])) ++end;
    size_t next = end;
    while (next < text.size() && (text[next] == ' ' || text[next] == '\t')) ++next;
    if (next < text.size() && text[next] == '(' && is_name(text.substr(i, end - i))) return true;
    i = end;
  }
  return false;
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
    if (e->kind == ir::Expr::Kind::Call && is_name(e->name) && !defined.count(e->name)) e->kind = ir::Expr::Kind::Builtin;
    return e;
  };
  for (size_t i = 0; i < module.global_inits.size(); ++i)
    if (module.global_inits[i]) module.global_inits[i] = ir::rewrite(module.global_inits[i], mark);
  for (const auto& f : module.functions) ir::rewrite(f->body, mark);
}

}  // namespace doublet::frontend
