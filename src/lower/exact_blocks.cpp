// exact_block_words (mode exact): a uniform or storage block keeps the byte layout the original
// block had with doubles, so that a host's std140/std430 buffer of IEEE doubles is read unchanged.
// Each double member becomes its binary64 words, low word first (exact_interface.hpp):
//   double -> uvec2, dvec2 -> uvec4 (a double's and a dvec2's std140/std430 size and alignment);
//   dvec3/dvec4 -> NAME_xy (uvec4) + NAME_z (uvec2) / NAME_zw (uvec4), 24/32 bytes as before;
//   an array of dvec3/dvec4 -> an array of struct ex_dvecN_words {uvec4 xy; uvec2 z|uvec4 zw;}
//   (stride 32, as the doubles'); a struct holding doubles -> its twin STRUCT_words.
// The words align to at most 16 bytes where a dvec3/dvec4 aligns to 32: `ex_padN` members (uint/uvecN)
// fill the difference, so every member keeps its original offset and every struct its size (the
// pass checks both). In/out blocks (desktop targets) get the same word types, flat, without pads.
// Reads of a double member load its words into the df_* value the shader computes with
// (ex_load_*), writes assign its words (ex_words_*; a split dvec3/dvec4 through ex_store_*'s two
// out parameters); a member passed to an out/inout parameter goes through a temporary loaded
// before and stored after the statement.
// Runs after lower_doubles; the df_* values inside the shader are unchanged.
#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "lower/block_layout.hpp"
#include "lower/exact_interface.hpp"
#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"

namespace doublet::passes {
namespace {

using ir::Expr;
using ir::ExprPtr;
using Kind = ir::Expr::Kind;

int round_up(int x, int a) { return a ? (x + a - 1) / a * a : x; }

struct Shape {
  int size = 0, align = 4, stride = 0;  // stride: arrays only
};

// std140/std430 (OpenGL 4.6, 7.6.2.2) of the lowered IR's types, where a df_* struct stands for the
// double or dvecN it holds (so the original block's layout is computed from the lowered type).
class Layout {
 public:
  explicit Layout(bool std140) : std140_(std140) {}

  Shape whole(const ir::Type& t) const {
    if (!t.is_array()) return element(t);
    Shape e = whole(t.element());
    Shape a;
    a.align = std140_ ? round_up(e.align, 16) : e.align;
    a.stride = round_up(e.size, a.align);
    a.size = std::max(t.array_dims[0], 0) * a.stride;
    return a;
  }
  // Byte offset of each field of a struct or block; explicit offsets (declared) win.
  std::vector<int> offsets(const std::vector<ir::Field>& fields, const std::vector<ir::Field>* declared = nullptr) const {
    std::vector<int> out;
    int offset = 0;
    for (size_t i = 0; i < fields.size(); ++i) {
      Shape s = whole(fields[i].type);
      offset = round_up(offset, s.align);
      if (declared && i < declared->size() && (*declared)[i].layout.offset >= 0) offset = (*declared)[i].layout.offset;
      out.push_back(offset);
      offset += s.size;
    }
    return out;
  }

 private:
  Shape element(const ir::Type& t) const {
    if (matrix::is_matrix(t)) {  // column-major dmatCxR: C columns, each a dvecR at the array stride
      const int stride = matrix::rows(t) == 2 ? 16 : 32;
      return {matrix::cols(t) * stride, stride};
    }
    if (is_df(t)) {
      const int w = df_width(t);
      return {8 * w, w == 1 ? 8 : w == 2 ? 16 : 32};
    }
    if ((t.base == ir::Base::Struct || t.base == ir::Base::Block) && t.fields) {
      int end = 0, align = 4;
      std::vector<int> at = offsets(*t.fields);
      for (size_t i = 0; i < at.size(); ++i) {
        Shape s = whole((*t.fields)[i].type);
        end = at[i] + s.size;
        align = std::max(align, s.align);
      }
      if (std140_) align = round_up(align, 16);
      return {round_up(end, align), align};
    }
    const int scalar = t.base == ir::Base::Double ? 8 : 4;
    auto vector = [&](int n) -> Shape { return {scalar * n, scalar * (n == 1 ? 1 : n == 2 ? 2 : 4)}; };
    if (t.is_matrix()) {
      Shape column = vector(t.vec);
      const int stride = std140_ ? round_up(column.align, 16) : column.align;
      return {t.cols * stride, stride};
    }
    return vector(t.vec);
  }

  bool std140_;
};

ir::Type uint_type(int n) { return ir::scalar_type(ir::Base::Uint, n); }

std::string spelled(const ir::Type& t) {  // df_dvec3[4] -> dvec3[4]
  std::string n = ir::type_name(t);
  if (n.rfind("df_d", 0) == 0) n = n.substr(3);
  return n + ir::array_suffix(t);
}

// What one member of a block or struct became.
struct FieldPlan {
  enum Kind { Same, Words, Split, Twin, Matrix } kind = Same;
  ir::Type original;                 // the lowered (df_*/struct) type the shader computes with
  ir::Type word;                     // Words/Twin: the word type (arrays kept); Split: part 0's
  std::vector<std::string> names;    // the emitted members: one, or NAME_xy + NAME_z(w) for Split
  std::vector<ir::Type> part_types;  // Split: uvec4 and uvec2/uvec4
};

struct TypePlan {
  std::map<std::string, FieldPlan> fields;
};

class BlockWords {
 public:
  BlockWords(ir::Module& m, Context& c) : module_(m), ctx_(c) {}

  void run() {
    if (ctx_.failed) return;  // an interface already refused (e.g. a struct uniform holding a dmat) has no plan
    for (const auto& g : module_.globals)
      if (g->type.base == ir::Base::Block && holds_doubles(g->type)) plan_block(*g);
    struct_uniforms();
    if (ctx_.failed) return;
    if (blocks_.empty()) return finish();
    for (size_t i = 0; i < module_.global_inits.size(); ++i) {
      if (!module_.global_inits[i]) continue;
      module_.global_inits[i] = rw(module_.global_inits[i]);
      no_temporaries_here(module_.global_inits[i]->loc);
    }
    for (const auto& f : module_.functions) {
      function_ = f.get();
      statement_list(f->body);
    }
    finish();
  }

  void finish() {
    for (auto& [var, plan] : members_) {  // anonymous blocks' member variables take their word types
      if (plan->kind == FieldPlan::Words || plan->kind == FieldPlan::Twin) var->type = plan->word;
    }
    // Word structs first (the twins use them), then the twins after the user structs they mirror.
    module_.structs.insert(module_.structs.begin(), word_structs_.begin(), word_structs_.end());
    module_.structs.insert(module_.structs.end(), twins_.begin(), twins_.end());
    for (const auto& name : helper_order_) ctx_.struct_helpers += helpers_[name] + "\n";
  }

 private:
  // A loose uniform of a struct type holding doubles: `uniform S_words s` (the twin: its doubles as
  // words, low word first, like every other interface double), loaded into the private `S s_value`
  // at the start of main.
  void struct_uniforms() {
    auto main = std::find_if(module_.functions.begin(), module_.functions.end(),
                             [](const ir::FunctionPtr& f) { return f->name == "main"; });
    std::set<std::string> names;
    for (const auto& g : module_.globals) names.insert(g->name);
    std::vector<ir::StmtPtr> loads;
    for (size_t i = 0; i < module_.globals.size(); ++i) {
      const ir::VarPtr v = module_.globals[i];
      ir::Type element = v->type;
      element.array_dims.clear();
      if (v->storage != ir::Storage::Uniform || v->block || element.base != ir::Base::Struct || is_df(element) ||
          !element.fields || !holds_doubles(element))
        continue;
      if (v->type.array_dims.size() > 1 || (v->type.is_array() && v->type.array_dims[0] <= 0)) {
        ctx_.error(v->loc, "'" + v->name + "': a multi-dimensional or unsized array of structs with doubles cannot be "
                           "a uniform in --mode exact");
        continue;
      }
      ir::Type words = twin(element, false, v->loc);
      words.array_dims = v->type.array_dims;
      auto u = std::make_shared<ir::Var>(*v);  // the interface keeps the name
      u->type = words;
      v->name = ir::join_identifier(v->name, "_value");
      if (names.count(v->name))
        ctx_.error(v->loc, "--mode exact needs the name '" + v->name + "' for the value of uniform '" + u->name +
                               "', which the shader already uses; rename it");
      v->storage = ir::Storage::Global;
      v->layout = {};
      module_.globals.insert(module_.globals.begin() + static_cast<std::ptrdiff_t>(i), u);
      module_.global_inits.insert(module_.global_inits.begin() + static_cast<std::ptrdiff_t>(i), nullptr);
      ++i;
      ctx_.exact_struct_uniforms.insert(u.get());
      ir::Type twin_element = words;
      twin_element.array_dims.clear();
      const std::string load = struct_accessor(twin_element, true, v->loc);
      const int count = v->type.is_array() ? v->type.array_dims[0] : 1;
      for (int k = 0; k < count; ++k) {
        ExprPtr from = ir::make_sym(u), to = ir::make_sym(v);
        if (v->type.is_array()) from = ir::make_index(from, k), to = ir::make_index(to, k);
        auto stmt = ir::Stmt::make(ir::Stmt::Kind::Expr, v->loc);
        stmt->expr = ir::make_assign(to, ir::make_node(Kind::Call, load, to->type, {from}, v->loc));
        loads.push_back(stmt);
      }
    }
    if (loads.empty()) return;
    if (main == module_.functions.end()) return ctx_.error({}, "the shader has no main function");
    auto& body = (*main)->body->body;
    body.insert(body.begin(), loads.begin(), loads.end());
  }

  // ---- word types and layouts ------------------------------------------------------------
  // ex_dvec3_words / ex_dvec4_words: one element of an array of dvec3/dvec4 (32 bytes).
  ir::Type word_struct(int width) {
    const std::string name = "ex_dvec" + std::to_string(width) + "_words";
    for (const auto& t : word_structs_)
      if (t.name == name) return t;
    ir::Type t;
    t.base = ir::Base::Struct;
    t.name = name;
    t.fields = std::make_shared<std::vector<ir::Field>>();
    t.fields->push_back({"xy", uint_type(4), {}, {}});
    t.fields->push_back({width == 3 ? "z" : "zw", uint_type(width == 3 ? 2 : 4), {}, {}});
    word_structs_.push_back(t);
    return t;
  }

  // ex_dmatCxR_words { COLUMN c[C]; }, COLUMN = uvec4 (R = 2) or ex_dvecR_words (R = 3, 4): in
  // std140 and std430 a column-major dmatCxR is laid out as an array of C dvecR (16- or 32-byte
  // stride), which these words repeat; a struct keeps an array of matrices one element per matrix.
  ir::Type matrix_words(int cols, int rows) {
    const std::string name = "ex_dmat" + std::to_string(cols) + "x" + std::to_string(rows) + "_words";
    for (const auto& t : word_structs_)
      if (t.name == name) return t;
    ir::Type column = rows == 2 ? uint_type(4) : word_struct(rows);
    column.array_dims = {cols};
    ir::Type t;
    t.base = ir::Base::Struct;
    t.name = name;
    t.fields = std::make_shared<std::vector<ir::Field>>();
    t.fields->push_back({"c", column, {}, {}});
    word_structs_.push_back(t);
    return t;
  }

  // The word type of one element (no array dimensions) of a member in an array, or nullopt when
  // the element holds no doubles.
  std::optional<ir::Type> word_element(const ir::Type& t, bool std140, ir::Loc loc) {
    if (is_df(t)) {
      const int w = df_width(t);
      return w == 1 ? uint_type(2) : w == 2 ? uint_type(4) : word_struct(w);
    }
    if (t.base == ir::Base::Struct && t.fields && holds_doubles(t)) return twin(t, std140, loc);
    if (holds_doubles(t)) {
      ctx_.error(loc, "a " + spelled(t) + " member of a block cannot be laid out as binary64 words by --mode exact yet");
      return t;
    }
    return std::nullopt;
  }

  ir::Type with_dims(ir::Type t, const ir::Type& of) {
    t.array_dims = of.array_dims;
    return t;
  }

  // Word fields for `fields` (a block's or struct's lowered members) at the offsets `native`
  // gives them, padded to `native_size` (structs; -1: no trailing padding). Fills `plan`.
  std::vector<ir::Field> word_fields(const std::vector<ir::Field>& fields, const std::vector<int>& native,
                                     int native_size, bool std140, bool pad, bool flat, TypePlan& plan, ir::Loc loc) {
    const Layout layout(std140);
    std::vector<ir::Field> out;
    int offset = 0;
    auto add = [&](ir::Field f) {
      const Shape s = layout.whole(f.type);
      offset = round_up(offset, s.align) + s.size;
      if (flat && f.type.base == ir::Base::Uint) f.interp = ir::Interp::Flat;
      out.push_back(std::move(f));
    };
    auto pad_to = [&](int target) {  // the widest uint vectors that fit, each at its alignment
      while (pad && offset < target) {
        const int gap = target - offset;
        const int n = gap >= 16 && offset % 16 == 0 ? 4 : gap >= 8 && offset % 8 == 0 ? 2 : 1;
        add({"ex_pad" + std::to_string(pads_++), uint_type(n), {}, {}});
      }
    };
    for (size_t i = 0; i < fields.size(); ++i) {
      const ir::Field& f = fields[i];
      pad_to(native[i]);
      FieldPlan fp;
      fp.original = f.type;
      ir::Type element = f.type;
      element.array_dims.clear();
      if (is_df(f.type) && df_width(f.type) > 2) {  // a lone dvec3/dvec4: two members, 24/32 bytes
        fp.kind = FieldPlan::Split;
        const int w = df_width(f.type);
        fp.names = {ir::join_identifier(f.name, "_xy"), ir::join_identifier(f.name, w == 3 ? "_z" : "_zw")};
        fp.part_types = {uint_type(4), uint_type(w == 3 ? 2 : 4)};
        fp.word = fp.part_types[0];
        for (size_t k = 0; k < 2; ++k) {
          ir::Field part = f;
          part.name = fp.names[k];
          part.type = fp.part_types[k];
          add(part);
        }
      } else if (matrix::is_matrix(element)) {  // ex_dmatCxR_words: the columns' words at the column stride
        fp.kind = FieldPlan::Matrix;
        fp.word = with_dims(matrix_words(matrix::cols(element), matrix::rows(element)), f.type);
        fp.names = {f.name};
        ir::Field part = f;
        part.type = fp.word;
        add(part);
      } else if (std::optional<ir::Type> word = word_element(element, std140, loc)) {
        fp.kind = is_df(element) ? FieldPlan::Words : FieldPlan::Twin;
        fp.word = with_dims(*word, f.type);
        fp.names = {f.name};
        ir::Field part = f;
        part.type = fp.word;
        add(part);
      } else {
        fp.names = {f.name};
        add(f);
      }
      plan.fields[f.name] = fp;
    }
    if (native_size >= 0) pad_to(native_size);
    // The words must sit where the doubles were: checked, not assumed.
    const std::vector<int> at = layout.offsets(out);
    size_t k = 0;
    for (size_t i = 0; i < fields.size(); ++i) {
      while (k < out.size() && out[k].name.rfind("ex_pad", 0) == 0) ++k;
      if (pad && (k >= out.size() || at[k] != native[i]))
        ctx_.error(loc, "internal error: the binary64 words of member '" + fields[i].name +
                            "' do not land on its original offset; please report this with the input");
      k += plan.fields[fields[i].name].kind == FieldPlan::Split ? 2 : 1;
    }
    return out;
  }

  // STRUCT_words: the struct with its doubles as words, laid out as the original struct.
  ir::Type twin(const ir::Type& s, bool std140, ir::Loc loc) {
    const std::string key = s.name + (std140 ? "/std140" : "/std430");
    if (auto it = twin_types_.find(key); it != twin_types_.end()) return it->second;
    const Layout layout(std140);
    ir::Type t;
    t.base = ir::Base::Struct;
    // STRUCT_words; a struct in both a std140 and a std430 block needs a second twin.
    const bool taken = std::any_of(twins_.begin(), twins_.end(), [&](const ir::Type& x) { return x.name == s.name + "_words"; });
    t.name = s.name + (taken ? (std140 ? "_words_std140" : "_words_std430") : "_words");
    if (std::any_of(module_.structs.begin(), module_.structs.end(), [&](const ir::Type& x) { return x.name == t.name; }))
      ctx_.error(loc, "--mode exact needs the struct name '" + t.name + "' for the binary64 words of " + s.name +
                          ", which the shader already uses; rename it");
    TypePlan& plan = struct_plans_[t.name];
    plan_of_type_[t.name] = &plan;
    original_of_twin_[t.name] = s;
    t.fields = std::make_shared<std::vector<ir::Field>>(
        word_fields(*s.fields, layout.offsets(*s.fields), layout.whole(s).size, std140, true, false, plan, loc));
    twins_.push_back(t);
    twin_types_[key] = t;
    return t;
  }

  void plan_block(ir::Var& block) {
    const bool memory = block.storage == ir::Storage::Uniform || block.storage == ir::Storage::Buffer;
    const bool std140 = block.layout.packing != "std430";
    const bool flat = exact_io::between_stages(block.storage, module_.stage);
    const Layout layout(std140);
    const std::vector<ir::Field> fields = *block.type.fields;  // a copy: the block's fields are replaced below
    const std::vector<ir::Field>* declared = block.declared_type.fields ? block.declared_type.fields.get() : nullptr;
    std::vector<int> native = layout.offsets(fields, declared);
    if (!memory) native.assign(fields.size(), 0);
    TypePlan& plan = block_plans_[&block];
    auto words = word_fields(fields, native, -1, std140, memory, flat, plan, block.loc);
    block.type.fields = std::make_shared<std::vector<ir::Field>>(std::move(words));
    blocks_.insert(&block);
    std::vector<BlockMember>& listed = ctx_.exact_block_members[&block];  // in/out blocks: listed, no members
    if (memory) manifest_members(plan, fields, native, layout, "", listed);
  }

  // The manifest's members: where each original member's words are (its original place).
  void manifest_members(const TypePlan& plan, const std::vector<ir::Field>& fields, const std::vector<int>& at,
                        const Layout& layout, const std::string& prefix, std::vector<BlockMember>& out, int base = 0) {
    for (size_t i = 0; i < fields.size(); ++i) {
      const ir::Field& f = fields[i];
      const FieldPlan& fp = plan.fields.at(f.name);
      const Shape s = layout.whole(f.type);
      BlockMember m;
      m.name = prefix + f.name;
      m.type = spelled(f.type);
      m.offset = base + at[i];
      m.size = s.size;
      m.array_stride = f.type.is_array() ? s.stride : 0;
      if (fp.kind == FieldPlan::Matrix) {
        ir::Type element = f.type;
        element.array_dims.clear();
        m.matrix_stride = matrix::rows(element) == 2 ? 16 : 32;
      }
      if (fp.kind == FieldPlan::Split)
        m.lowered_type = ir::type_name(fp.part_types[0]) + " " + fp.names[0] + ", " + ir::type_name(fp.part_types[1]) +
                         " " + fp.names[1];
      else
        m.lowered_type = ir::type_name(fp.kind == FieldPlan::Same ? f.type : fp.word) +
                         ir::array_suffix(fp.kind == FieldPlan::Same ? f.type : fp.word);
      if (fp.kind != FieldPlan::Same) m.encoding = "binary64-words";
      if (fp.kind == FieldPlan::Twin) {
        ir::Type element = f.type;
        element.array_dims.clear();
        const TypePlan& inner = *plan_of_type_.at(fp.word.name);
        const std::vector<int> inner_at = layout.offsets(*element.fields);
        if (!f.type.is_array()) {
          manifest_members(inner, *element.fields, inner_at, layout, m.name + ".", out, m.offset);
          continue;
        }
        out.push_back(m);  // the array, then element 0's members
        manifest_members(inner, *element.fields, inner_at, layout, m.name + "[0].", out, m.offset);
        continue;
      }
      out.push_back(m);
    }
  }

  // ---- places: accesses to block members, as word expressions ------------------------------
  struct Place {
    ir::Type type;               // what the shader computes with (lowered type)
    std::vector<ExprPtr> parts;  // word expressions: one, or NAME_xy and NAME_z(w)
    const TypePlan* fields = nullptr;  // a (non-array) twin struct: its members' plans
    bool doubles = false;
  };

  Place place_of(const FieldPlan& fp, const ExprPtr& base, const ir::VarPtr& anonymous_member, ir::Loc loc) {
    if (fp.kind == FieldPlan::Split && base && ir::has_side_effects(base))  // both parts name the base
      ctx_.error(loc, "a dvec3/dvec4 block member reached through an expression with side effects (a call, ++, an "
                      "assignment) cannot be lowered by --mode exact: use a temporary index");
    Place p;
    p.type = fp.original;
    p.doubles = fp.kind != FieldPlan::Same;
    for (size_t k = 0; k < fp.names.size(); ++k) {
      ir::Type type = fp.kind == FieldPlan::Split ? fp.part_types[k] : fp.kind == FieldPlan::Same ? fp.original : fp.word;
      ExprPtr e;
      if (anonymous_member) {
        e = Expr::make(Kind::Sym, type, loc);
        e->var = member_var(anonymous_member, fp, k);
      } else {
        e = Expr::make(Kind::Member, type, loc);
        e->name = fp.names[k];
        e->args = {base};
      }
      p.parts.push_back(e);
    }
    if (fp.kind == FieldPlan::Twin && !fp.word.is_array()) p.fields = plan_of_type_.at(fp.word.name);
    return p;
  }

  // An anonymous block's member variable: itself, or new variables NAME_xy and NAME_z(w) when split.
  ir::VarPtr member_var(const ir::VarPtr& original, const FieldPlan& fp, size_t part) {
    if (fp.kind != FieldPlan::Split) return original;
    auto& vars = split_vars_[original.get()];
    for (size_t k = vars.size(); k < fp.names.size(); ++k) {
      auto v = std::make_shared<ir::Var>(*original);
      v->name = fp.names[k];
      v->type = v->declared_type = fp.part_types[k];
      vars.push_back(v);
    }
    return vars[part];
  }

  const ir::Var* block_of(const ExprPtr& e) const {
    if (e->kind == Kind::Sym && blocks_.count(e->var.get())) return e->var.get();
    if (e->kind == Kind::Index && e->args[0]->kind == Kind::Sym && blocks_.count(e->args[0]->var.get()))
      return e->args[0]->var.get();  // an array of blocks
    return nullptr;
  }

  // The place `e` names, when it is (a part of) a block member; commits (rewrites index
  // expressions) only when it returns one.
  std::optional<Place> place(const ExprPtr& e) {
    if (e->kind == Kind::Sym && e->var->block && blocks_.count(e->var->block.get())) {
      const TypePlan& plan = block_plans_.at(e->var->block.get());
      auto it = plan.fields.find(e->var->name);
      if (it == plan.fields.end()) return std::nullopt;
      members_[e->var.get()] = &it->second;
      return place_of(it->second, nullptr, e->var, e->loc);
    }
    if (e->kind == Kind::Member) {
      const ExprPtr& base = e->args[0];
      if (const ir::Var* block = block_of(base)) {
        if (base->kind == Kind::Index) base->args[1] = rw(base->args[1]);
        return place_of(block_plans_.at(block).fields.at(e->name), base, nullptr, e->loc);
      }
      if (is_df(base->type) || matrix::is_matrix(base->type) || base->type.is_array())
        return std::nullopt;  // hi/lo of a value: the member is loaded whole (rw)
      std::optional<Place> outer = place(base);
      if (!outer) return std::nullopt;
      if (outer->fields) return place_of(outer->fields->fields.at(e->name), outer->parts[0], nullptr, e->loc);
      return same(e, outer->parts[0]);  // a member or swizzle of something holding no doubles
    }
    if (e->kind == Kind::Index) {
      const ExprPtr& base = e->args[0];
      if (!base->type.is_array()) return std::nullopt;
      std::optional<Place> outer = place(base);
      if (!outer) return std::nullopt;
      auto index = Expr::make(Kind::Index, e->type, e->loc);
      index->args = {outer->parts[0], rw(e->args[1])};
      if (!outer->doubles) return same(e, outer->parts[0], index);
      Place p;
      p.type = outer->type.element();
      p.doubles = true;
      index->type = outer->parts[0]->type.element();
      p.parts = {index};
      if (!p.type.is_array() && !is_df(p.type) && !matrix::is_matrix(p.type)) p.fields = plan_of_type_.at(index->type.name);
      return p;
    }
    return std::nullopt;
  }

  // `e` with its base replaced by `base` (Member) or `index` (Index): no doubles involved.
  static Place same(const ExprPtr& e, const ExprPtr& base, ExprPtr index = nullptr) {
    Place p;
    p.type = e->type;
    if (index) {
      p.parts = {index};
      return p;
    }
    auto m = Expr::make(Kind::Member, e->type, e->loc);
    m->name = e->name;
    m->args = {base};
    p.parts = {m};
    return p;
  }

  // ---- load and store helpers ---------------------------------------------------------------
  // ex_load_T(words) -> value; ex_words_T(value) -> words (a plain assignment stores them: Mesa's
  // GLES compiler refuses a struct of a writeonly buffer as an out argument); ex_store_T(out
  // NAME_xy, out NAME_z, value) -> value for a split dvec3/dvec4, whose two members one
  // assignment cannot write.
  enum class Access { Load, Words, StoreSplit };

  void helper(const std::string& name, const std::string& text) {
    if (helpers_.emplace(name, text).second) helper_order_.push_back(name);
  }

  static std::string df_suffix(const ir::Type& t) { return ir::type_name(t).substr(3); }  // "double", "dvec3"

  // uvec2(v.lo, v.hi) or uvec4(v.lo.x, v.hi.x, v.lo.y, v.hi.y) for components first.. of `v`.
  static std::string pack_words(int width, int first, int count) {
    std::string s = count == 1 ? "uvec2(" : "uvec4(";
    for (int c = first; c < first + count; ++c) {
      const std::string at = width == 1 ? "" : std::string(".") + "xyzw"[c];
      s += std::string(c > first ? ", " : "") + "v.lo" + at + ", v.hi" + at;
    }
    return s + ")";
  }

  // The helper for a df width; returns its name.
  std::string df_accessor(const ir::Type& type, Access access) {
    const int w = df_width(type);
    const std::string df = ir::type_name(type), suffix = df_suffix(type);
    const std::string words = w == 1 ? "uvec2" : w == 2 ? "uvec4" : "ex_dvec" + std::to_string(w) + "_words";
    const std::string rest = w == 3 ? "uvec2" : "uvec4", rest_name = w == 3 ? "z" : "zw";
    if (w > 2) word_struct(w);
    std::string name, text;
    switch (access) {
      case Access::Load:
        name = "ex_load_" + suffix;
        if (w <= 2) {
          text = df + " " + name + "(" + words + " w) {\n  return " + df + (w == 1 ? "(w.y, w.x);\n}\n" : "(w.yw, w.xz);\n}\n");
        } else {
          const std::string high = w == 3 ? "uvec3(xy.yw, z.y)" : "uvec4(xy.yw, zw.yw)";
          const std::string low = w == 3 ? "uvec3(xy.xz, z.x)" : "uvec4(xy.xz, zw.xz)";
          text = df + " " + name + "(uvec4 xy, " + rest + " " + rest_name + ") {\n  return " + df + "(" + high + ", " + low +
                 ");\n}\n" + df + " " + name + "(" + words + " w) {\n  return " + name + "(w.xy, w." + rest_name + ");\n}\n";
        }
        break;
      case Access::Words:
        name = "ex_words_" + suffix;
        text = words + " " + name + "(" + df + " v) {\n  return " +
               (w <= 2 ? pack_words(w, 0, w) : words + "(" + pack_words(w, 0, 2) + ", " + pack_words(w, 2, w - 2) + ")") +
               ";\n}\n";
        break;
      case Access::StoreSplit:
        name = "ex_store_" + suffix;
        text = df + " " + name + "(out uvec4 xy, out " + rest + " " + rest_name + ", " + df + " v) {\n  xy = " +
               pack_words(w, 0, 2) + ";\n  " + rest_name + " = " + pack_words(w, 2, w - 2) + ";\n  return v;\n}\n";
        break;
    }
    helper(name, text);
    return name;
  }

  std::string accessor(const Place& p, Access access, ir::Loc loc) {
    if (is_df(p.type)) return df_accessor(p.type, access);
    if (matrix::is_matrix(p.type)) return matrix_accessor(p.type, access);
    if (!p.fields) {
      ctx_.error(loc, std::string(access == Access::Load ? "reading" : "writing") + " a whole array of doubles in a "
                      "block is not supported by --mode exact: access its elements");
      return "";
    }
    return struct_accessor(p.parts[0]->type, access == Access::Load, loc);
  }

  // df_dmatCxR ex_load_dmatCxR(ex_dmatCxR_words w) / ex_dmatCxR_words ex_words_dmatCxR(df_dmatCxR v),
  // column by column through the dvecR accessors.
  std::string matrix_accessor(const ir::Type& type, Access access) {
    const int c = matrix::cols(type), r = matrix::rows(type);
    const std::string df = ir::type_name(type), words = ir::type_name(matrix_words(c, r));
    const std::string suffix = df.substr(3), column = df_type_name(r);
    const std::string column_accessor = df_accessor(df_type(r), access == Access::Load ? Access::Load : Access::Words);
    const std::string name = (access == Access::Load ? "ex_load_" : "ex_words_") + suffix;
    const std::string uvec = "uvec" + std::to_string(r), col_words = r == 2 ? "uvec4" : "ex_dvec" + std::to_string(r) + "_words";
    std::string text;
    if (access == Access::Load) {
      text = df + " " + name + "(" + words + " w) {\n";
      std::string hi, lo;
      for (int j = 0; j < c; ++j) {
        const std::string v = "c" + std::to_string(j);
        text += "  " + column + " " + v + " = " + column_accessor + "(w.c[" + std::to_string(j) + "]);\n";
        hi += (j ? ", " : "") + v + ".hi";
        lo += (j ? ", " : "") + v + ".lo";
      }
      const std::string array = uvec + "[" + std::to_string(c) + "]";
      text += "  return " + df + "(" + array + "(" + hi + "), " + array + "(" + lo + "));\n}\n";
    } else {
      text = words + " " + name + "(" + df + " v) {\n  return " + words + "(" + col_words + "[" + std::to_string(c) + "](";
      for (int j = 0; j < c; ++j)
        text += (j ? ", " : "") + column_accessor + "(" + column + "(v.hi[" + std::to_string(j) + "], v.lo[" +
                std::to_string(j) + "]))";
      text += "));\n}\n";
    }
    helper(name, text);
    return name;
  }

  // S ex_load_S_words(S_words w) / S_words ex_words_S_words(S v), member by member.
  std::string struct_accessor(const ir::Type& twin_type, bool load, ir::Loc loc) {
    const ir::Type& s = original_of_twin_.at(twin_type.name);
    const TypePlan& plan = *plan_of_type_.at(twin_type.name);
    const std::string name = std::string(load ? "ex_load_" : "ex_words_") + twin_type.name;
    if (helpers_.count(name)) return name;
    std::vector<std::string> loads, stores;
    for (const ir::Field& f : *s.fields) {
      const FieldPlan& fp = plan.fields.at(f.name);
      ir::Type element = f.type;
      element.array_dims.clear();
      if (f.type.array_dims.size() > 1 || (f.type.is_array() && f.type.array_dims[0] <= 0)) {
        ctx_.error(loc, "member '" + f.name + "' of struct " + s.name + ": multi-dimensional or unsized arrays of "
                        "doubles in a block are not supported by --mode exact");
        return name;
      }
      const int count = f.type.is_array() ? f.type.array_dims[0] : 1;
      std::vector<std::string> element_loads;
      for (int i = 0; i < count; ++i) {
        const std::string at = f.type.is_array() ? "[" + std::to_string(i) + "]" : "";
        const std::string word = "w." + f.name + at, value = "v." + f.name + at;
        if (fp.kind == FieldPlan::Same) {
          element_loads.push_back(word);
          stores.push_back(word + " = " + value + ";");
        } else if (fp.kind == FieldPlan::Split) {
          const std::string parts = "w." + fp.names[0] + ", w." + fp.names[1];
          element_loads.push_back(df_accessor(element, Access::Load) + "(" + parts + ")");
          stores.push_back(df_accessor(element, Access::StoreSplit) + "(" + parts + ", " + value + ");");
        } else if (fp.kind == FieldPlan::Words) {
          element_loads.push_back(df_accessor(element, Access::Load) + "(" + word + ")");
          stores.push_back(word + " = " + df_accessor(element, Access::Words) + "(" + value + ");");
        } else if (fp.kind == FieldPlan::Matrix) {  // ex_dmatCxR_words, column by column
          element_loads.push_back(matrix_accessor(element, Access::Load) + "(" + word + ")");
          stores.push_back(word + " = " + matrix_accessor(element, Access::Words) + "(" + value + ");");
        } else {  // a nested twin
          ir::Type we = fp.word;
          we.array_dims.clear();
          element_loads.push_back(struct_accessor(we, true, loc) + "(" + word + ")");
          stores.push_back(word + " = " + struct_accessor(we, false, loc) + "(" + value + ");");
        }
      }
      if (!f.type.is_array()) {
        loads.push_back(element_loads[0]);
        continue;
      }
      std::string array = ir::type_name(element) + "[" + std::to_string(count) + "](";
      for (size_t i = 0; i < element_loads.size(); ++i) array += (i ? ", " : "") + element_loads[i];
      loads.push_back(array + ")");
    }
    for (const ir::Field& f : *twin_type.fields)
      if (f.name.rfind("ex_pad", 0) == 0)
        stores.push_back("w." + f.name + " = " + (f.type.vec == 1 ? "0u" : ir::type_name(f.type) + "(0u)") + ";");
    std::string text;
    if (!load) {
      text = twin_type.name + " " + name + "(" + s.name + " v) {\n  " + twin_type.name + " w;\n";
      for (const auto& line : stores) text += "  " + line + "\n";
      text += "  return w;\n}\n";
    } else {
      text = s.name + " " + name + "(" + twin_type.name + " w) {\n  return " + s.name + "(";
      for (size_t i = 0; i < loads.size(); ++i) text += (i ? ", " : "") + loads[i];
      text += ");\n}\n";
    }
    helper(name, text);
    return name;
  }

  ExprPtr load(const Place& p, ir::Loc loc) {
    return ir::make_node(Kind::Call, accessor(p, Access::Load, loc), p.type, p.parts, loc);
  }

  // The place's words assigned `value`; an expression of the value's type when `used`.
  ExprPtr store(const Place& p, const ExprPtr& value, ir::Loc loc, bool used = true) {
    if (p.parts.size() == 2) {
      // (t = value, X_xy = ex_words_dvec3_xy(t), X_z = ex_words_dvec3_z(t), t): one evaluation of
      // the value, two plain assignments (an out argument would be read first by Mesa's GLES).
      auto t = std::make_shared<ir::Var>();
      t->name = "ex_member" + std::to_string(temporaries_++);
      t->type = t->declared_type = p.type;
      pending_.push_back({t, p, loc, true});
      auto comma = Expr::make(Kind::Comma, p.type, loc);
      comma->args.push_back(ir::make_assign(ir::make_sym(t), value));
      const int w = df_width(p.type);
      for (size_t k = 0; k < 2; ++k) {
        const std::string name = "ex_words_" + df_suffix(p.type) + (k == 0 ? "_xy" : w == 3 ? "_z" : "_zw");
        helper(name, ir::type_name(p.parts[k]->type) + " " + name + "(" + ir::type_name(p.type) + " v) {\n  return " +
                         pack_words(w, 2 * static_cast<int>(k), k == 0 ? 2 : w - 2) + ";\n}\n");
        auto part = ir::make_node(Kind::Call, name, p.parts[k]->type, {ir::make_sym(t)}, loc);
        comma->args.push_back(ir::make_assign(p.parts[k], part));
      }
      if (used) comma->args.push_back(ir::make_sym(t));
      return comma;
    }
    const ir::Type word = p.parts[0]->type;
    auto words = ir::make_node(Kind::Call, accessor(p, Access::Words, loc), word, {value}, loc);
    auto assign = ir::make_assign(p.parts[0], words);
    if (!used) return assign;
    return ir::make_node(Kind::Call, accessor(p, Access::Load, loc), p.type, {assign}, loc);
  }

  // ---- expressions -----------------------------------------------------------------------
  // Which arguments of a call the callee writes (out/inout).
  std::vector<bool> written_arguments(const ExprPtr& call) const {
    std::vector<bool> out(call->args.size(), false);
    const std::string& n = call->name;
    for (const auto& f : module_.functions) {
      if (f->name != n || f->params.size() != call->args.size()) continue;
      for (size_t i = 0; i < f->params.size(); ++i)
        out[i] = ir::is_out_parameter(f->params[i]->storage);
      return out;
    }
    if (auto it = ctx_.helpers.find(n); it != ctx_.helpers.end()) {  // generated: read its parameter list
      const std::string& text = it->second.head;  // the parameter list is in the head
      size_t open = text.find(n + "(");
      if (open == std::string::npos) return out;
      size_t i = 0, pos = open + n.size() + 1;
      while (i < out.size() && pos < text.size()) {
        while (text[pos] == ' ') ++pos;
        out[i] = text.compare(pos, 4, "out ") == 0 || text.compare(pos, 6, "inout ") == 0;
        pos = text.find_first_of(",)", pos);
        if (pos == std::string::npos || text[pos] == ')') break;
        ++pos, ++i;
      }
      return out;
    }
    if ((n == "ex_modf" || n == "ex_frexp") && out.size() == 2) out[1] = true;
    return out;
  }

  // The words of column `j` of the block matrix `m` (a matrix place), as a dvecR place.
  Place matrix_column_place(const Place& m, const ExprPtr& j, ir::Loc loc) {
    const int rows = matrix::rows(m.type);
    ir::Type columns = rows == 2 ? uint_type(4) : word_struct(rows);
    const ir::Type column_word = columns;
    columns.array_dims = {matrix::cols(m.type)};
    auto index = Expr::make(Kind::Index, column_word, loc);
    index->args = {ir::make_node(Kind::Member, "c", columns, {m.parts[0]}, loc), j};
    Place p;
    p.doubles = true;
    p.type = df_type(rows);
    p.parts = {index};
    return p;
  }

  // m[j] of a block matrix reads only that column's words: lower_doubles wrote it
  // df_dvecR(m.hi[j], m.lo[j]) (constant j) or df_column_dmatCxR(m, j).
  ExprPtr matrix_column_load(const ExprPtr& e) {
    ExprPtr m, j;
    if (e->kind == Kind::Call && e->name.rfind("df_column_dmat", 0) == 0 && e->args.size() == 2) {
      m = e->args[0], j = e->args[1];
    } else if (e->kind == Kind::Construct && is_df(e->type) && e->args.size() == 2) {
      const ExprPtr &hi = e->args[0], &lo = e->args[1];
      auto half = [](const ExprPtr& x, const char* name) {
        return x->kind == Kind::Index && x->args[1]->kind == Kind::Const && x->args[0]->kind == Kind::Member &&
               x->args[0]->name == name && matrix::is_matrix(x->args[0]->args[0]->type);
      };
      if (!half(hi, "hi") || !half(lo, "lo") || hi->args[1]->values.empty() || lo->args[1]->values.empty() ||
          hi->args[1]->values[0].i != lo->args[1]->values[0].i)
        return nullptr;
      m = hi->args[0]->args[0], j = hi->args[1];
    } else {
      return nullptr;
    }
    if (!matrix::is_matrix(m->type)) return nullptr;
    std::optional<Place> p = place(m);
    if (!p) return nullptr;
    return load(matrix_column_place(*p, rw(j), e->loc), e->loc);
  }

  // m[j] = v and m[j][i] = x on a block matrix (lowered to df_assign_column_/df_assign_element_
  // calls with m inout) store only that column's or element's words, as native does: a load and
  // store of the whole matrix would also rewrite the columns other invocations may be writing.
  // An element with a dynamic row index has no swizzle: nullptr, and the generic inout path
  // (the whole matrix loaded before and stored after the statement) takes it.
  ExprPtr matrix_part_store(const ExprPtr& e, bool used) {
    const bool column = e->name.rfind("df_assign_column_", 0) == 0, element = e->name.rfind("df_assign_element_", 0) == 0;
    if ((!column && !element) || e->args.size() != (column ? 3u : 4u) || !matrix::is_matrix(e->args[0]->type)) return nullptr;
    int row = -1;
    if (element) {
      const ExprPtr& i = e->args[2];
      if (i->kind != Kind::Const || i->values.empty()) return nullptr;
      row = static_cast<int>(i->values[0].i);
    }
    std::optional<Place> m = place(e->args[0]);
    if (!m) return nullptr;
    const int rows = matrix::rows(m->type);
    Place p = matrix_column_place(*m, rw(e->args[1]), e->loc);
    if (column) return store(p, rw(e->args[2]), e->loc, used);
    const ExprPtr index = p.parts[0];
    // Element `row`: its two words inside the column's words.
    ExprPtr words = index;
    std::string swizzle = row % 2 == 0 ? "xy" : "zw";
    if (rows > 2) {
      const bool first = row < 2;
      const ir::Type part = first || rows == 4 ? uint_type(4) : uint_type(2);
      words = ir::make_node(Kind::Member, first ? "xy" : rows == 3 ? "z" : "zw", part, {index}, e->loc);
      if (!first && rows == 3) swizzle.clear();  // z is one double: the member itself
    }
    if (!swizzle.empty()) words = ir::make_node(Kind::Member, swizzle, uint_type(2), {words}, e->loc);
    p.type = df_type(1);
    p.parts = {words};
    return store(p, rw(e->args[3]), e->loc, used);
  }

  // `used`: the expression's value is read (false for an expression statement or a loop step).
  ExprPtr rw(const ExprPtr& e, bool used = true) {
    if (!e) return e;
    if (std::optional<Place> p = place(e)) return p->doubles ? load(*p, e->loc) : p->parts[0];
    // `.length()` of a block's array of doubles: the length of its word array (one element each).
    if (ir::is_array_length(*e))
      if (std::optional<Place> p = place(e->args[0]); p && !p->parts.empty()) {  // dvec3/4: the xy words' array
        e->args[0] = p->parts[0];
        return e;
      }
    if (e->kind == Kind::Binary && e->op == "=") {
      if (std::optional<Place> p = place(e->args[0])) {
        if (p->doubles) return store(*p, rw(e->args[1]), e->loc, used);
        e->args[0] = p->parts[0];
        e->args[1] = rw(e->args[1]);
        return e;
      }
    }
    if (ExprPtr column = matrix_column_load(e)) return column;
    if (e->kind == Kind::Call) {
      if (ExprPtr column_store = matrix_part_store(e, used)) return column_store;
      const std::vector<bool> written = written_arguments(e);
      for (size_t i = 0; i < e->args.size(); ++i) {
        if (!written[i]) {
          e->args[i] = rw(e->args[i]);
          continue;
        }
        std::optional<Place> p = place(e->args[i]);
        if (!p) {
          e->args[i] = rw(e->args[i]);
        } else if (!p->doubles) {
          e->args[i] = p->parts[0];
        } else {
          if (ir::has_side_effects(e->args[i]))
            ctx_.error(e->args[i]->loc, "a block member reached through an expression with side effects cannot be "
                                        "passed to an out/inout parameter in --mode exact: use a temporary");
          auto t = std::make_shared<ir::Var>();
          t->name = "ex_member" + std::to_string(temporaries_++);
          t->type = t->declared_type = p->type;
          t->storage = ir::Storage::Local;
          pending_.push_back({t, *p, e->args[i]->loc, false});
          e->args[i] = ir::make_sym(t, e->args[i]->loc);
        }
      }
      return e;
    }
    for (auto& a : e->args) a = rw(a);
    return e;
  }

  // ---- statements --------------------------------------------------------------------------
  struct Temporary {
    ir::VarPtr var;
    Place place;
    ir::Loc loc;
    bool declare_only = false;  // a split store's value: declared before the statement, nothing after
  };

  void no_temporaries_here(ir::Loc loc) {
    if (pending_.empty()) return;
    ctx_.error(loc, "a block member passed to an out/inout parameter here (a condition, a loop step or a global "
                    "initialiser) cannot be lowered by --mode exact: call the function in a statement of its own");
    pending_.clear();
  }

  // Rewrites `s` and returns the statements to run before and after it (temporaries).
  void statement(const ir::StmtPtr& s, std::vector<ir::StmtPtr>& before, std::vector<ir::StmtPtr>& after) {
    if (!s) return;
    const bool own = s->kind == ir::Stmt::Kind::Expr || s->kind == ir::Stmt::Kind::Decl || s->kind == ir::Stmt::Kind::Return;
    if (s->kind == ir::Stmt::Kind::Block) return statement_list(s);
    if (s->expr) {
      s->expr = rw(s->expr, s->kind != ir::Stmt::Kind::Expr);
      if (!own) no_temporaries_here(s->expr->loc);
    }
    const std::vector<Temporary> temporaries = std::move(pending_);
    pending_.clear();
    auto declare = [&](const Temporary& t) {
      auto decl = ir::Stmt::make(ir::Stmt::Kind::Decl, t.loc);
      decl->var = t.var;
      before.push_back(decl);
      return decl;
    };
    for (const Temporary& t : temporaries) {
      auto decl = declare(t);
      if (t.declare_only) continue;
      decl->expr = load(t.place, t.loc);
      Place again = t.place;  // the same place, as its own nodes
      for (auto& part : again.parts) part = ir::clone(part);
      auto write = ir::Stmt::make(ir::Stmt::Kind::Expr, t.loc);
      write->expr = store(again, ir::make_sym(t.var), t.loc, false);
      after.push_back(write);
    }
    for (const Temporary& t : pending_) declare(t);  // the stores' own (split dvec3/dvec4 values)
    pending_.clear();
    if (s->step) {
      s->step = rw(s->step, false);
      no_temporaries_here(s->step->loc);
    }
    for (size_t i = 0; i < s->body.size(); ++i) {
      if (s->kind == ir::Stmt::Kind::Loop && i == 0 && s->body[0]) {  // a for-init stays one statement
        std::vector<ir::StmtPtr> init_before, init_after;
        statement(s->body[0], init_before, init_after);
        if (!init_before.empty())
          ctx_.error(s->body[0]->loc, "a block member passed to an out/inout parameter in a for-loop's initialiser "
                                      "cannot be lowered by --mode exact: move the call before the loop");
        continue;
      }
      wrapped(s->body[i]);
    }
  }

  // A statement that is not directly in a block (an if's branch, a loop body): wrapped in one
  // when it needs temporaries.
  void wrapped(ir::StmtPtr& s) {
    if (!s) return;
    if (s->kind == ir::Stmt::Kind::Block) return statement_list(s);
    std::vector<ir::StmtPtr> before, after;
    statement(s, before, after);
    if (before.empty() && after.empty()) return;
    auto block = ir::Stmt::make(ir::Stmt::Kind::Block, s->loc);
    splice(s, before, after, block->body);
    s = block;
  }

  void statement_list(const ir::StmtPtr& block) {
    std::vector<ir::StmtPtr> body;
    for (auto& s : block->body) {
      std::vector<ir::StmtPtr> before, after;
      statement(s, before, after);
      splice(s, before, after, body);
    }
    block->body = std::move(body);
  }

  // before; s; after — a return keeps its value in a temporary until the stores have run.
  void splice(const ir::StmtPtr& s, std::vector<ir::StmtPtr>& before, std::vector<ir::StmtPtr>& after,
              std::vector<ir::StmtPtr>& out) {
    out.insert(out.end(), before.begin(), before.end());
    if (s && s->kind == ir::Stmt::Kind::Return && s->expr && !after.empty()) {
      auto value = std::make_shared<ir::Var>();
      value->name = "ex_member" + std::to_string(temporaries_++);
      value->type = value->declared_type = function_->return_type;
      auto decl = ir::Stmt::make(ir::Stmt::Kind::Decl, s->loc);
      decl->var = value;
      decl->expr = s->expr;
      out.push_back(decl);
      s->expr = ir::make_sym(value);
      out.insert(out.end(), after.begin(), after.end());
      out.push_back(s);
      return;
    }
    out.push_back(s);
    out.insert(out.end(), after.begin(), after.end());
  }

  ir::Module& module_;
  Context& ctx_;
  const ir::Function* function_ = nullptr;
  std::set<const ir::Var*> blocks_;
  std::map<const ir::Var*, TypePlan> block_plans_;
  std::map<std::string, TypePlan> struct_plans_;        // by twin name
  std::map<std::string, const TypePlan*> plan_of_type_;  // twin name -> its plan
  std::map<std::string, ir::Type> original_of_twin_;
  std::map<std::string, ir::Type> twin_types_;           // "S/std140" -> twin
  std::vector<ir::Type> word_structs_, twins_;
  std::map<ir::Var*, const FieldPlan*> members_;         // anonymous blocks' member variables seen
  std::map<const ir::Var*, std::vector<ir::VarPtr>> split_vars_;
  std::map<std::string, std::string> helpers_;
  std::vector<std::string> helper_order_;
  std::vector<Temporary> pending_;
  int pads_ = 0, temporaries_ = 0;
};

}  // namespace

bool exact_block_words(ir::Module& module, Context& context) {
  if (!context.config.binary64_words()) return true;
  BlockWords(module, context).run();
  return !context.failed;
}

}  // namespace doublet::passes
