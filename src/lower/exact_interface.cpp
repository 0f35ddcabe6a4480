#include "lower/exact_interface.hpp"

namespace doublet::passes::exact_io {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

ir::Type uint_type(int n) { return ir::scalar_type(ir::Base::Uint, n); }

ExprPtr member(const ExprPtr& base, const std::string& name, int components) {
  auto e = Expr::make(Kind::Member, uint_type(components), base->loc);
  e->name = name;
  e->args = {base};
  return e;
}

ExprPtr construct(const ir::Type& type, std::vector<ExprPtr> args) {
  auto e = Expr::make(Kind::Construct, type);
  e->args = std::move(args);
  return e;
}

const char* kLetters = "xyzw";

}  // namespace

std::vector<std::string> part_suffixes(int width) {
  if (width <= 2) return {""};
  return {"_xy", width == 3 ? "_z" : "_zw"};
}

ir::Type part_type(int width, int part) {
  const int doubles = width == 1 ? 1 : width == 3 && part == 1 ? 1 : 2;
  return uint_type(2 * doubles);
}

ExprPtr words_of(const ExprPtr& value, int width, int part) {
  ExprPtr hi = member(value, "hi", width), lo = member(value, "lo", width);
  if (width == 1) return construct(uint_type(2), {lo, hi});
  std::vector<ExprPtr> words;
  for (int c = 2 * part; c < 2 * part + 2 && c < width; ++c) {
    const std::string letter(1, kLetters[c]);
    words.push_back(member(ir::clone(lo), letter, 1));
    words.push_back(member(ir::clone(hi), letter, 1));
  }
  const ir::Type type = uint_type(static_cast<int>(words.size()));
  return construct(type, std::move(words));
}

ExprPtr value_of(const std::vector<ExprPtr>& parts, int width) {
  if (width == 1) return construct(df_type(1), {member(parts[0], "y", 1), member(ir::clone(parts[0]), "x", 1)});
  if (width == 2) return construct(df_type(2), {member(parts[0], "yw", 2), member(ir::clone(parts[0]), "xz", 2)});
  // dvec3/dvec4: the high words of both parts (odd components), then their low words (even ones);
  // dvec3's second part is one uvec2 (low z, high z).
  const bool one_more = width == 3;
  auto words = [&](const char* from_first, const char* from_second) {
    return construct(uint_type(width), {member(ir::clone(parts[0]), from_first, 2),
                                        member(ir::clone(parts[1]), from_second, one_more ? 1 : 2)});
  };
  return construct(df_type(width), {words("yw", one_more ? "y" : "yw"), words("xz", one_more ? "x" : "xz")});
}

}  // namespace doublet::passes::exact_io
