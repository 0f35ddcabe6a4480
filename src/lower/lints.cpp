#include "lower/lints.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "support/c_locale.hpp"

namespace doublet::passes {
namespace {

// ---- the source as tokens ----------------------------------------------------
// Just enough of a GLSL lexer to find literals again: identifiers, preprocessing
// numbers, one-character punctuation; comments skipped. Lines and columns are
// 1-based and count bytes, as glslang's locations do.
struct Token {
  enum Kind { Number, Identifier, Punct } kind;
  std::string text;
  int line, column;
  bool in_directive;  // on a #-line (a #define body)
  size_t offset = 0;  // byte offset in the source
};

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  int line = 1, column = 1;
  bool directive = false, line_start = true;
  size_t i = 0;
  auto advance = [&](size_t n) {
    for (size_t k = 0; k < n && i < s.size(); ++k, ++i) {
      if (s[i] == '\n') {
        ++line, column = 1;
        // A backslash-newline continues a directive.
        if (!(i > 0 && s[i - 1] == '\\')) directive = false, line_start = true;
      } else {
        ++column;
      }
    }
  };
  auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < s.size()) {
    char c = s[i];
    if (c == '\n' || c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\\') {
      advance(1);
      continue;
    }
    if (s.compare(i, 2, "//") == 0) {
      size_t end = s.find('\n', i);
      advance((end == std::string_view::npos ? s.size() : end) - i);
      continue;
    }
    if (s.compare(i, 2, "/*") == 0) {
      size_t end = s.find("*/", i + 2);
      advance((end == std::string_view::npos ? s.size() : end + 2) - i);
      continue;
    }
    if (c == '#' && line_start) directive = true;
    line_start = false;
    Token t{Token::Punct, "", line, column, directive, i};
    size_t n = 1;
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      t.kind = Token::Number;  // a pp-number: digits, letters, '.', and a sign after e/E
      while (i + n < s.size() && (word(s[i + n]) || s[i + n] == '.' ||
                                  ((s[i + n] == '+' || s[i + n] == '-') && (s[i + n - 1] == 'e' || s[i + n - 1] == 'E'))))
        ++n;
    } else if (word(c)) {
      t.kind = Token::Identifier;
      while (i + n < s.size() && word(s[i + n])) ++n;
    }
    t.text = std::string(s.substr(i, n));
    out.push_back(std::move(t));
    advance(n);
  }
  return out;
}

// A float literal (`0.1`, `.5`, `1e3`, `2.0f`), without its f suffix; nullopt for
// integers, double (lf) literals and anything else.
std::optional<std::string> float_literal_digits(const std::string& text) {
  std::string body = text;
  if (!body.empty() && (body.back() == 'f' || body.back() == 'F')) {
    body.pop_back();
    if (!body.empty() && (body.back() == 'l' || body.back() == 'L')) return std::nullopt;  // 0.1lf
  }
  if (body.empty() || body.find_first_of(".eE") == std::string::npos) return std::nullopt;
  if (body.size() > 1 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) return std::nullopt;
  size_t i = 0, digits = 0;
  while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, ++digits;
  if (i < body.size() && body[i] == '.') {
    ++i;
    while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, ++digits;
  }
  if (digits == 0) return std::nullopt;
  if (i < body.size() && (body[i] == 'e' || body[i] == 'E')) {
    ++i;
    if (i < body.size() && (body[i] == '+' || body[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < body.size() && std::isdigit(static_cast<unsigned char>(body[i]))) ++i, ++exp_digits;
    if (exp_digits == 0) return std::nullopt;
  }
  if (i != body.size()) return std::nullopt;
  return body;
}

// std::from_chars/to_chars: exact and independent of the C and C++ locales. Emscripten's libc++
// (the WebAssembly build, wasm/CMakeLists.txt) has no floating-point ones: there, musl's correctly
// rounded strtod/strtof and "%.15g" (what to_chars' general format with precision 15 is defined
// as) under the "C" locale give the same results.
#if defined(__cpp_lib_to_chars)
double parse_double(const std::string& digits) {
  double d = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), d);
  return d;
}
float parse_float(const std::string& digits) {
  float f = 0;
  std::from_chars(digits.data(), digits.data() + digits.size(), f);
  return f;
}
std::string format_15(double d) {
  std::array<char, 64> buf{};
  auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), d, std::chars_format::general, 15);
  return ec == std::errc() ? std::string(buf.data(), end) : std::string("?");
}
#else
double parse_double(const std::string& digits) {
  ScopedCLocale c_locale;
  return std::strtod(digits.c_str(), nullptr);
}
float parse_float(const std::string& digits) {
  ScopedCLocale c_locale;
  return std::strtof(digits.c_str(), nullptr);
}
std::string format_15(double d) {
  ScopedCLocale c_locale;
  std::array<char, 64> buf{};
  int n = std::snprintf(buf.data(), buf.size(), "%.15g", d);
  return n > 0 && n < static_cast<int>(buf.size()) ? std::string(buf.data(), static_cast<size_t>(n)) : std::string("?");
}
#endif

const std::set<std::string>& double_type_names() {
  static const std::set<std::string> names{"double", "dvec2", "dvec3", "dvec4", "dmat2", "dmat3", "dmat4",
                                           "dmat2x2", "dmat2x3", "dmat2x4", "dmat3x2", "dmat3x3", "dmat3x4",
                                           "dmat4x2", "dmat4x3", "dmat4x4"};
  return names;
}

// ---- lint plumbing -----------------------------------------------------------
constexpr std::array<std::string_view, 3> kLintNames{"float-literal", "wasted-double", "smooth-double-varying"};

struct Finding {
  ir::Loc loc;
  std::string message;
};

class Lints {
 public:
  Lints(const ir::Module& module, std::string_view source, Context& ctx)
      : module_(module), source_(source), ctx_(ctx) {}

  void run() {
    const auto& disabled = ctx_.config.disabled_lints;
    for (const std::string& name : disabled)
      if (name != "all" && std::find(kLintNames.begin(), kLintNames.end(), name) == kLintNames.end())
        ctx_.error({}, "unknown lint '" + name + "' (known: float-literal, wasted-double, smooth-double-varying, all)");
    auto on = [&](const char* name) {
      return std::find(disabled.begin(), disabled.end(), name) == disabled.end() &&
             std::find(disabled.begin(), disabled.end(), "all") == disabled.end();
    };
    if (!on("float-literal") && !on("wasted-double") && !on("smooth-double-varying")) return;
    tokens_ = tokenize(source_);
    for (size_t i = 0; i + 1 < tokens_.size(); ++i)
      if (tokens_[i].in_directive && tokens_[i].text == "#" &&
          (tokens_[i + 1].text == "include" || tokens_[i + 1].text == "line"))
        foreign_locations_ = true;
    if (on("float-literal")) float_literals();
    if (on("wasted-double")) wasted_doubles();
    if (on("smooth-double-varying")) smooth_varyings();
    std::stable_sort(findings_.begin(), findings_.end(), [](const Finding& a, const Finding& b) {
      return std::tie(a.loc.line, a.loc.column) < std::tie(b.loc.line, b.loc.column);
    });
    for (const Finding& f : findings_) {
      if (ctx_.config.lint_errors)
        ctx_.error(f.loc, f.message);
      else
        ctx_.warning(f.loc, f.message);
    }
  }

 private:
  void report(ir::Loc loc, const std::string& message, const char* lint) {
    findings_.push_back({loc, message + " [-W" + lint + "]"});
  }

  std::optional<size_t> token_at(ir::Loc loc) const {
    // Tokens are in source order: binary search.
    auto it = std::lower_bound(tokens_.begin(), tokens_.end(), loc, [](const Token& t, ir::Loc l) {
      return std::tie(t.line, t.column) < std::tie(l.line, l.column);
    });
    if (it == tokens_.end() || it->line != loc.line || it->column != loc.column) return std::nullopt;
    return static_cast<size_t>(it - tokens_.begin());
  }

  // Every expression of the module, with its parent (null at the root).
  template <typename F>
  void each_expr(F&& f) const {
    std::function<void(const ir::ExprPtr&, const ir::Expr*)> walk = [&](const ir::ExprPtr& e, const ir::Expr* parent) {
      if (!e) return;
      f(*e, parent);
      for (const auto& a : e->args) walk(a, e.get());
    };
    std::function<void(const ir::StmtPtr&)> stmt = [&](const ir::StmtPtr& s) {
      if (!s) return;
      walk(s->expr, nullptr);
      walk(s->step, nullptr);
      for (const auto& b : s->body) stmt(b);
    };
    for (const auto& init : module_.global_inits) walk(init, nullptr);
    for (const auto& fn : module_.functions) stmt(fn->body);
  }

  // ---- float-literal -----------------------------------------------------------
  // glslang folds a float literal that meets a double (`double x = 0.1;`, `d * 0.1`,
  // `dvec2(0.1, 0.25)`, `f(0.1)`) into a double constant with the literal's double
  // value, so the IR holds 0.1 where the GLSL rules say 0.1f widened. The constant's
  // location leads back to the source: the literal itself, the `)` of a folded
  // constructor or call, the first literal of a folded expression, or the name of a
  // constant or macro whose definition holds the literals.
  void float_literals() {
    each_expr([&](const ir::Expr& e, const ir::Expr*) {
      if (e.kind != ir::Expr::Kind::Const || !e.type.is_double() || e.loc.line <= 0) return;
      auto start = token_at(e.loc);
      if (!start) return;
      std::vector<size_t> extent = constant_extent(*start, e);
      bool inexact_literal = false;
      for (size_t i : extent) inexact_literal |= check_literal(i, e);
      if (!inexact_literal && !foreign_locations_) check_float_expression(extent, e);
    });
  }

  // Tokens whose literals make up the constant `e` located at token `i`.
  std::vector<size_t> constant_extent(size_t i, const ir::Expr& e) const {
    const Token& t = tokens_[i];
    if (t.kind == Token::Punct && t.text == ")") {  // a folded constructor: its argument list
      size_t open = matching_open(i);
      if (open == i) return {};
      std::vector<size_t> out;
      for (size_t k = open + 1; k < i; ++k) out.push_back(k);
      return out;
    }
    if (t.kind == Token::Identifier) {
      if (i + 1 < tokens_.size() && tokens_[i + 1].text == "(") return {};
      return definition_extent(t.text, i);
    }
    if (t.kind != Token::Number) return {};
    // The literal alone when it is the value (`-0.1` is folded at the 0.1); otherwise a
    // folded expression starting here (`0.1 + 0.2`): its constant tokens up to where it ends.
    double v = std::abs(e.values.empty() ? 0.0 : e.values[0].d);
    auto digits = float_literal_digits(t.text);
    std::string plain = t.text;
    if (digits) plain = *digits;
    if (e.values.size() >= 1 && std::all_of(e.values.begin(), e.values.end(),
                                            [&](const ir::Scalar& s) { return std::abs(s.d) == v; }) &&
        parse_double(plain) == v)
      return {i};
    return expression_extent(i);
  }

  size_t matching_open(size_t close) const {
    int depth = 0;
    for (size_t k = close + 1; k-- > 0;) {
      if (tokens_[k].text == ")") ++depth;
      if (tokens_[k].text == "(" && --depth == 0) return k;
      if (tokens_[k].text == ";" || tokens_[k].text == "{" || tokens_[k].text == "}") break;
    }
    return close;
  }

  // From token `i` on, the tokens of a constant expression: literals, arithmetic
  // operators, parentheses, calls; it ends at anything else or an unmatched `)`.
  std::vector<size_t> expression_extent(size_t i) const {
    std::vector<size_t> out;
    int depth = 0;
    for (size_t k = i; k < tokens_.size(); ++k) {
      const Token& t = tokens_[k];
      if (t.in_directive != tokens_[i].in_directive) break;
      if (t.kind == Token::Identifier && !(k + 1 < tokens_.size() && tokens_[k + 1].text == "(")) break;
      if (t.kind == Token::Punct) {
        if (t.text == "(") ++depth;
        else if (t.text == ")") { if (--depth < 0) break; }
        else if (t.text == "," ) { if (depth == 0) break; }
        else if (t.text.find_first_of("+-*/%") == std::string::npos) break;
      }
      out.push_back(k);
    }
    return out;
  }

  // The tokens defining `name`, used at token `use`: a `#define name BODY`, or a
  // `const DOUBLETYPE ... name = EXPR` before the use. Empty when not found.
  std::vector<size_t> definition_extent(const std::string& name, size_t use) const {
    std::vector<size_t> out;
    // The last definition before the use wins, as for both macros and scopes.
    for (size_t k = use; k-- > 0;) {
      const Token& t = tokens_[k];
      if (t.kind != Token::Identifier || t.text != name) continue;
      if (t.in_directive && k >= 1 && tokens_[k - 1].text == "define") {
        for (size_t b = k + 1; b < tokens_.size() && tokens_[b].in_directive && tokens_[b].line == t.line; ++b) {
          if (b == k + 1 && tokens_[b].text == "(" && tokens_[b].column == t.column + int(t.text.size()))
            return {};  // a function-like macro: its body is not the value alone
          out.push_back(b);
        }
        return out;
      }
      size_t eq = k + 1;  // past array dimensions: `A[2] = ...`
      while (eq < tokens_.size() && tokens_[eq].text == "[")
        while (eq < tokens_.size() && tokens_[eq++].text != "]") {}
      if (eq < tokens_.size() && tokens_[eq].text == "=" && !t.in_directive && const_double_declaration(k)) {
        int d = 0;
        for (size_t b = eq + 1; b < tokens_.size(); ++b) {
          const std::string& x = tokens_[b].text;
          if (x == "(") ++d;
          if (x == ")") --d;
          if (x == ";" || (x == "," && d == 0)) break;
          out.push_back(b);
        }
        return out;
      }
    }
    return out;
  }

  // Whether the declaration holding the name at token `k` is `const` with a double type.
  bool const_double_declaration(size_t k) const {
    bool is_const = false, is_double = false;
    for (size_t b = k; b-- > 0;) {
      const std::string& x = tokens_[b].text;
      if (x == ";" || x == "{" || x == "}" || tokens_[b].in_directive) break;
      if (x == "const") is_const = true;
      if (double_type_names().count(x)) is_double = true;
    }
    return is_const && is_double;
  }

  // Reports token `i` when it is a float literal whose value is not a float; true for such a
  // literal (reported now or before).
  bool check_literal(size_t i, const ir::Expr& constant) {
    const Token& t = tokens_[i];
    if (t.kind != Token::Number) return false;
    auto digits = float_literal_digits(t.text);
    if (!digits) return false;
    double as_double = parse_double(*digits);
    double as_float = static_cast<double>(parse_float(*digits));
    if (as_double == as_float || !std::isfinite(as_float)) return false;
    // With #include or #line, a location may belong to another file: only a literal that is
    // itself one of the constant's values is taken to be its source.
    if (foreign_locations_ && std::none_of(constant.values.begin(), constant.values.end(),
                                           [&](const ir::Scalar& v) { return std::abs(v.d) == as_double; }))
      return false;
    if (!reported_literals_.insert(i).second) return true;
    report({t.line, t.column},
           "float literal " + t.text + " becomes " + format_15(as_float) + " as a double; write " + *digits +
               "lf (doublet and glslang read it as " + *digits + "lf, GL drivers as the float)",
           "float-literal");
    return true;
  }

  // A folded float expression meeting a double (`double t = 1.0 / 3.0;`): GLSL
  // computes it in float, so its value is a float widened, while glslang folds it in double.
  // Made of float literals only (no lf literal, no double constructor, no variable), it is
  // float arithmetic; when the folded value is not a float, the two readings differ.
  void check_float_expression(const std::vector<size_t>& extent, const ir::Expr& e) {
    if (extent.size() < 2) return;  // a lone literal is check_literal's
    bool float_literal = false;
    for (size_t k : extent) {
      const Token& t = tokens_[k];
      if (t.kind == Token::Number) {
        if (float_literal_digits(t.text)) float_literal = true;
        else if (t.text.find_first_of(".lL") != std::string::npos) return;  // 0.1lf: double arithmetic
      } else if (t.kind == Token::Identifier) {
        bool call = k + 1 < tokens_.size() && tokens_[k + 1].text == "(";
        if (!call || double_type_names().count(t.text)) return;
      }
    }
    if (!float_literal) return;
    auto is_float = [](const ir::Scalar& v) { return static_cast<double>(static_cast<float>(v.d)) == v.d; };
    auto inexact = std::find_if_not(e.values.begin(), e.values.end(), is_float);
    if (inexact == e.values.end()) return;
    if (!reported_literals_.insert(extent.front()).second) return;
    const Token& first = tokens_[extent.front()];
    const Token& last = tokens_[extent.back()];
    std::string text(source_.substr(first.offset, last.offset + last.text.size() - first.offset));
    std::replace(text.begin(), text.end(), '\n', ' ');
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    // `-(1.0 / 3.0)`: a negation outside the text is in the value.
    size_t before = extent.front();
    while (before > 0 && tokens_[before - 1].text == "(") --before;
    double shown = before > 0 && tokens_[before - 1].text == "-" ? std::abs(inexact->d) : inexact->d;
    report({first.line, first.column},
           "float expression '" + text + "' is folded in double to " + format_15(shown) +
               " (doublet and glslang keep that), but under the GLSL rules it is float arithmetic, which GL "
               "drivers widen; write its literals with lf",
           "float-literal");
  }

  // ---- wasted-double -------------------------------------------------------------
  static bool is_narrow_numeric(const ir::Type& t) {
    return !t.is_array() && (t.base == ir::Base::Float || t.base == ir::Base::Int || t.base == ir::Base::Uint);
  }
  // double(f), dvec3(v), dvec2(a, b): a double built from floats/ints only.
  static bool is_widening(const ir::ExprPtr& e) {
    if (!e || e->kind != ir::Expr::Kind::Construct || !e->type.is_double() || e->type.is_array() || e->args.empty())
      return false;
    return std::all_of(e->args.begin(), e->args.end(), [](const ir::ExprPtr& a) { return a && is_narrow_numeric(a->type); });
  }
  static bool is_demotion(const ir::Expr& e) {
    return e.kind == ir::Expr::Kind::Construct && is_narrow_numeric(e.type);
  }

  // The `float(` of `float(double(x))`, found from the conversion's location (glslang
  // places a conversion at its operand).
  ir::Loc outer_constructor_loc(const ir::Expr& outer, const ir::Expr& inner) const {
    auto i = token_at(outer.loc);
    std::string outer_name = ir::type_name(outer.type), inner_name = ir::type_name(inner.type);
    if (i && *i >= 4 && tokens_[*i - 1].text == "(" && tokens_[*i - 2].text == inner_name &&
        tokens_[*i - 3].text == "(" && tokens_[*i - 4].text == outer_name)
      return {tokens_[*i - 4].line, tokens_[*i - 4].column};
    return outer.loc;
  }

  void wasted_doubles() {
    // float(double(f)), vec3(dvec3(v)): a conversion straight back.
    each_expr([&](const ir::Expr& e, const ir::Expr*) {
      if (!is_demotion(e) || e.args.size() != 1 || !is_widening(e.args[0])) return;
      const ir::Expr& inner = *e.args[0];
      std::string outer_name = ir::type_name(e.type), inner_name = ir::type_name(inner.type);
      report(outer_constructor_loc(e, inner),
             outer_name + "(" + inner_name + "(...)) converts to " + inner_name +
                 " and straight back with no double operation between: the result is the same without the " +
                 inner_name + " conversion, which only costs float-float work; drop it",
             "wasted-double");
    });

    // A double variable that only ever holds widened floats and is only read back as floats.
    struct Use {
      int writes = 0;
      ir::Loc first_read;
      bool other = false;
    };
    std::map<int, Use> uses;  // by Var::id: a stable order
    std::map<int, const ir::Var*> vars;
    auto candidate = [](const ir::Var* v) {
      return v && (v->storage == ir::Storage::Local || v->storage == ir::Storage::Global) &&
             v->declared_type.is_double() && !v->declared_type.is_array();
    };
    each_expr([&](const ir::Expr& e, const ir::Expr* parent) {
      if (e.kind != ir::Expr::Kind::Sym || !candidate(e.var.get())) return;
      Use& u = uses[e.var->id];
      vars[e.var->id] = e.var.get();
      if (parent && parent->kind == ir::Expr::Kind::Binary && parent->op == "=" && parent->args[0].get() == &e) {
        if (is_widening(parent->args[1])) ++u.writes;
        else u.other = true;
      } else if (parent && is_demotion(*parent)) {
        if (u.first_read.line == 0) u.first_read = parent->loc;
      } else {
        u.other = true;
      }
    });
    auto initialised = [&](const ir::VarPtr& v, const ir::ExprPtr& init) {
      if (!candidate(v.get()) || !init) return;
      Use& u = uses[v->id];
      vars[v->id] = v.get();
      if (is_widening(init)) ++u.writes;
      else u.other = true;
    };
    for (size_t i = 0; i < module_.globals.size(); ++i) initialised(module_.globals[i], module_.global_inits[i]);
    std::function<void(const ir::StmtPtr&)> decls = [&](const ir::StmtPtr& s) {
      if (!s) return;
      if (s->kind == ir::Stmt::Kind::Decl) initialised(s->var, s->expr);
      for (const auto& b : s->body) decls(b);
    };
    for (const auto& fn : module_.functions) decls(fn->body);
    for (const auto& [id, u] : uses) {
      const ir::Var* v = vars[id];
      if (u.other || u.writes == 0 || u.first_read.line == 0) continue;
      std::string narrow = ir::type_name(v->declared_type.with_base(ir::Base::Float));
      report(v->storage == ir::Storage::Global ? global_declaration(*v) : v->loc,
             "'" + v->name + "' only ever holds a widened float and is only read back as float (line " +
                 std::to_string(u.first_read.line) +
                 "): no double operation uses it, so its float-float storage and conversions are wasted work; "
                 "declare it " + narrow,
             "wasted-double");
    }
  }

  // Where global `name` is declared: glslang places a global at its first use. The first
  // top-level mention after a double type name in the same declaration, indexed in one pass
  // over the tokens (a scan per global was quadratic).
  ir::Loc global_declaration(const ir::Var& v) {
    if (!declarations_indexed_) {
      declarations_indexed_ = true;
      int depth = 0;
      bool double_declaration = false;  // a double type name since the last ';', '}' or directive
      for (const Token& t : tokens_) {
        if (t.in_directive || t.text == ";" || t.text == "}") double_declaration = false;
        if (t.in_directive) continue;
        if (t.text == "{") ++depth;
        if (t.text == "}") --depth;
        if (depth == 0 && t.kind == Token::Identifier && double_declaration)
          global_declarations_.try_emplace(t.text, ir::Loc{t.line, t.column});
        if (double_type_names().count(t.text)) double_declaration = true;
      }
    }
    auto it = global_declarations_.find(v.name);
    return it != global_declarations_.end() ? it->second : v.loc;
  }

  // ---- smooth-double-varying ----------------------------------------------------
  // A smooth double fragment input is already an error (glslang: "must be qualified as
  // flat"); the vertex side is legal GLSL but cannot meet a valid fragment input on ES
  // 3.00 (interpolation qualifiers must match there), and interpolated hi/lo would keep
  // only float precision.
  void smooth_varyings() {
    if (module_.stage != ir::StageKind::Vertex) return;
    for (const auto& v : module_.globals) {
      if (v->storage != ir::Storage::Out || !v->declared_type.contains_double()) continue;
      if (v->interp == ir::Interp::Flat) {
        // ES 1.00 prints no interpolation qualifier: the flat the user asked for is lost.
        if (ctx_.config.target == Target::Es100)
          report(global_declaration(*v),
                 "'" + v->name + "' is a flat double vertex output, but ES 1.00 has no 'flat': its hi and lo "
                 "are interpolated, which keeps only float precision where the vertices differ; pass the "
                 "value as a uniform, or target es300",
                 "smooth-double-varying");
        continue;
      }
      if (v->type.base == ir::Base::Block && v->type.fields &&
          std::none_of(v->type.fields->begin(), v->type.fields->end(), [](const ir::Field& f) {
            return f.type.contains_double() && f.interp != ir::Interp::Flat;
          }))
        continue;  // an output block whose double members are all flat
      // ES 1.00 (source or target) has no `flat`: a uniform is the only way to keep the precision.
      const bool no_flat = ctx_.config.target == Target::Es100 || (module_.source_es && module_.source_version == 100);
      report(global_declaration(*v),
             "'" + v->name + "' is a double vertex output without 'flat': its fragment input must be flat "
             "(GLSL allows no smooth double input, and ES 3.00 links only matching qualifiers), and "
             "interpolating hi and lo separately would keep only float precision; " +
                 std::string(no_flat ? "ES 1.00 has no 'flat', so pass the value as a uniform"
                                     : "declare it flat, or pass the value as a uniform"),
             "smooth-double-varying");
    }
  }

  const ir::Module& module_;
  std::string_view source_;
  std::vector<Token> tokens_;
  bool declarations_indexed_ = false;
  std::map<std::string, ir::Loc> global_declarations_;  // global_declaration()'s index
  Context& ctx_;
  std::vector<Finding> findings_;
  std::set<size_t> reported_literals_;
  bool foreign_locations_ = false;  // #include/#line: IR locations may name other files' lines
};

}  // namespace

void run_lints(const ir::Module& module, std::string_view source, Context& context) {
  Lints(module, source, context).run();
}

}  // namespace doublet::passes

namespace doublet {
std::vector<std::string_view> lint_names() { return {passes::kLintNames.begin(), passes::kLintNames.end()}; }
}  // namespace doublet
