// The printer's parentheses, checked by a round trip (tests/printer/round_trip.hpp): for many
// generated modules, print → glslang → import gives main the structure it was generated with.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "emit/printer.hpp"
#include "round_trip.hpp"

namespace {

using doublet::Target;
namespace ir = doublet::ir;
namespace roundtrip = doublet::roundtrip;

constexpr int kModules = 400;    // per target
constexpr int kStatements = 6;   // per main, after the local declarations
constexpr int kDepth = 4;        // operators per expression, at most

class PrinterRoundTrip : public ::testing::TestWithParam<Target> {};

TEST_P(PrinterRoundTrip, GeneratedExpressionsReparseToTheSameStructure) {
  int failures = 0;
  for (int seed = 0; seed < kModules && failures < 3; ++seed) {
    std::mt19937 rng(static_cast<uint32_t>(seed));
    roundtrip::Chooser choose = [&](uint32_t bound) { return static_cast<uint32_t>(rng() % bound); };
    ir::Module module = roundtrip::random_module(choose, kStatements, kDepth);
    std::string difference = roundtrip::round_trip_difference(module, GetParam());
    if (!difference.empty()) ++failures;
    EXPECT_EQ(difference, "") << "seed " << seed;
  }
}

// What the round trip would miss if the generator stopped producing it: every expression kind
// and operator, and the placements where parentheses matter.
void collect(const ir::ExprPtr& e, const ir::ExprPtr& parent, std::set<std::string>& seen) {
  using Kind = ir::Expr::Kind;
  seen.insert("kind " + std::to_string(static_cast<int>(e->kind)));
  if (!e->op.empty()) seen.insert("op " + e->op);
  if (parent) {
    const bool in_arguments = parent->kind == Kind::Call || parent->kind == Kind::Builtin || parent->kind == Kind::Construct;
    if (e->kind == Kind::Comma && in_arguments) seen.insert("comma argument");
    if (e->kind == Kind::Binary && e->op.back() == '=' && parent->kind == Kind::Binary) seen.insert("assignment operand");
    if (e->kind == Kind::Ternary && parent->kind == Kind::Ternary) seen.insert("nested ternary");
    if ((e->kind == Kind::Binary || e->kind == Kind::Ternary) && (parent->kind == Kind::Member || parent->kind == Kind::Index) &&
        parent->args[0] == e)
      seen.insert("selection of an operation");
  }
  for (const auto& a : e->args) collect(a, e, seen);
}

void collect(const ir::StmtPtr& s, std::set<std::string>& seen) {
  if (!s) return;
  if (s->kind == ir::Stmt::Kind::Decl && s->expr && s->expr->kind == ir::Expr::Kind::Comma) seen.insert("comma initialiser");
  if (s->step && s->step->kind == ir::Expr::Kind::Comma) seen.insert("comma loop step");
  if (s->expr) collect(s->expr, nullptr, seen);
  if (s->step) collect(s->step, nullptr, seen);
  for (const auto& b : s->body) collect(b, seen);
}

TEST(PrinterRoundTripGenerator, CoversEveryKindOperatorAndPlacement) {
  std::set<std::string> seen;
  for (int seed = 0; seed < kModules; ++seed) {
    std::mt19937 rng(static_cast<uint32_t>(seed));
    roundtrip::Chooser choose = [&](uint32_t bound) { return static_cast<uint32_t>(rng() % bound); };
    for (const auto& f : roundtrip::random_module(choose, kStatements, kDepth).functions) collect(f->body, seen);
  }
  std::vector<std::string> wanted = {"comma argument", "assignment operand", "nested ternary", "selection of an operation",
                                     "comma initialiser", "comma loop step"};
  for (int k = 0; k <= static_cast<int>(ir::Expr::Kind::Comma); ++k) wanted.push_back("kind " + std::to_string(k));
  for (const char* op : {"+", "-", "*", "/", "%", "<<", ">>", "&", "|", "^", "<", ">", "<=", ">=", "==", "!=", "&&", "||",
                         "^^", "!", "~", "++x", "--x", "x++", "x--", "=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=",
                         "<<=", ">>="})
    wanted.push_back(std::string("op ") + op);
  for (const auto& w : wanted) EXPECT_TRUE(seen.count(w)) << w;
}

INSTANTIATE_TEST_SUITE_P(Targets, PrinterRoundTrip, ::testing::Values(Target::Es300, Target::Glsl450),
                         [](const auto& info) { return std::string(doublet::to_string(info.param)); });

ir::ExprPtr constant(ir::Base base, long long i, double d) {
  auto e = ir::Expr::make(ir::Expr::Kind::Const, ir::scalar_type(base));
  ir::Scalar s;
  s.base = base;
  s.i = i;
  s.d = d;
  e->values = {s};
  return e;
}

ir::ExprPtr negate(ir::ExprPtr operand) {
  auto e = ir::make_node(ir::Expr::Kind::Unary, "", operand->type, {operand}, {});
  e->op = "-";
  return e;
}

// glslang folds constants, so the round trip cannot see these: a negated negative literal must
// not print as `--1`, a pre-decrement.
TEST(PrinterLiterals, NegatedNegativeLiteralsKeepTheirParentheses) {
  EXPECT_EQ(doublet::emit::expression_text(negate(constant(ir::Base::Int, -1, 0)), Target::Es300), "-(-1)");
  EXPECT_EQ(doublet::emit::expression_text(negate(constant(ir::Base::Float, 0, -2.5)), Target::Es300), "-(-2.5)");
  EXPECT_EQ(doublet::emit::expression_text(negate(constant(ir::Base::Float, 0, -0.0)), Target::Es300), "-(-0.0)");
  EXPECT_EQ(doublet::emit::expression_text(negate(constant(ir::Base::Int, 3, 0)), Target::Es300), "-3");
}

}  // namespace
