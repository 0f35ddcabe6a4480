// std140 blocks in WGSL: see wgsl_std140.hpp. Offsets follow OpenGL 4.6, 7.6.2.2 (std140, computed by
// the manifest's own block_layout) and W3C WGSL, "Memory Layout" (alignment, size, @align, @size).
#include "emit/wgsl_std140.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "lower/block_layout.hpp"

namespace doublet::emit {
namespace {

using ir::Base;

int round_up(int x, int a) { return (x + a - 1) / a * a; }

bool is_struct(const ir::Type& t) { return (t.base == Base::Struct || t.base == Base::Block) && t.fields; }

ir::Type innermost(ir::Type t) {
  t.array_dims.clear();
  return t;
}

class Planner {
 public:
  explicit Planner(const ir::Module& m) : m_(m) {}

  WgslStd140Plan run() {
    for (const auto& v : m_.globals) {
      const bool block = (v->storage == ir::Storage::Uniform || v->storage == ir::Storage::Buffer) &&
                         v->type.base == Base::Block && v->type.fields;
      if (block && (v->storage == ir::Storage::Uniform || v->layout.packing == "std140"))
        std140_blocks_.push_back(v.get());
      else if (block)
        hold(v->type, "std430 block '" + v->type.name + "'");
      else if (v->storage == ir::Storage::Uniform)
        hold(v->type, "the loose uniform '" + v->name + "'");
    }
    for (const ir::Var* block : std140_blocks_) {
      block_ = block;
      layout_of_struct(block->type, block->type.name);
    }
    return std::move(plan_);
  }

 private:
  // Structs that WGSL must lay out its own way: held by std430 blocks or loose uniforms.
  void hold(const ir::Type& t, const std::string& holder) {
    const ir::Type e = innermost(t);
    if (!is_struct(e) || !held_elsewhere_.emplace(e.name, holder).second) return;
    for (const auto& f : *e.fields) hold(f.type, holder);
  }

  void refuse(const std::string& member, const std::string& what) {
    plan_.refusals.push_back(
        {block_->loc, "block '" + block_->type.name + "' is std140, and WGSL cannot read '" + member + "' at std140's " +
                          "offsets (" + what + "), so the host's data (at the manifest's std140 offsets) would be misread: " +
                          "declare the block std430" + (block_->storage == ir::Storage::Uniform ? " (a storage buffer)" : "")});
  }

  // WGSL's layout of a type as printed: structs in std140 blocks with their @align/@size.
  WgslLayout printed(const ir::Type& t, const std::string& path) {
    if (t.is_array()) {
      const WgslLayout e = printed(t.element(), path);
      return {e.align, round_up(e.size, e.align) * std::max(t.array_dims[0], 1)};
    }
    if (is_struct(t)) return layout_of_struct(t, path);
    return wgsl_layout(t, false);
  }

  // Plans the members of a struct or block held by the current std140 block (once per type) and
  // returns its WGSL layout as printed.
  WgslLayout layout_of_struct(const ir::Type& t, const std::string& path) {
    if (auto it = done_.find(t.name); it != done_.end()) return it->second;
    std::map<std::string, Std140Member> members;
    int offset = 0, align = 4;
    for (const auto& f : *t.fields) {
      const std::string member = path + "." + f.name;
      const passes::StdLayout s = passes::std_layout(f.type, true);
      const ir::Type element = innermost(f.type);
      if (element.is_matrix() && element.vec == 2) {
        refuse(member, "std140 puts a matrix's 2-row columns 16 bytes apart, WGSL 8");
        continue;
      }
      WgslLayout w = printed(f.type, member);
      Std140Member m;
      if (f.type.is_array()) {
        const WgslLayout e = printed(f.type.element(), member);
        if (round_up(e.size, e.align) != s.stride) {
          if (f.type.array_dims.size() > 1) {
            refuse(member, "an inner array of a multi-dimensional array has std140's 16-byte element stride");
            continue;
          }
          m.wrapper = wrapper(f.type.element(), s.stride);
          w = {16, s.stride * std::max(f.type.array_dims[0], 1)};
        }
      }
      if (w.align != s.align) m.align = s.align;
      const bool runtime_sized = f.type.is_array() && f.type.array_dims[0] <= 0;
      if (w.size != s.size && !runtime_sized) m.size = s.size;
      if (m.align || m.size || !m.wrapper.empty()) members[f.name] = m;
      offset = round_up(offset, m.align ? m.align : w.align) + (m.size ? m.size : w.size);
      align = std::max(align, m.align ? m.align : w.align);
    }
    if (!members.empty() && held_elsewhere_.count(t.name)) {
      refuse(path, "struct '" + t.name + "' is also held by " + held_elsewhere_.at(t.name) +
                       ", where WGSL lays it out its own way");
      members.clear();
    }
    if (!members.empty()) plan_.members[t.name] = std::move(members);
    return done_[t.name] = {align, round_up(offset, align)};
  }

  std::string wrapper(const ir::Type& element, int stride) {
    std::string name = "df_std140_" + (is_struct(element) ? element.name : ir::type_name(element));
    for (char& c : name)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    if (wrapper_names_.insert(name).second) plan_.wrappers.push_back({name, element, stride});
    return name;
  }

  const ir::Module& m_;
  const ir::Var* block_ = nullptr;
  std::vector<const ir::Var*> std140_blocks_;
  std::map<std::string, std::string> held_elsewhere_;  // struct name -> who holds it
  std::map<std::string, WgslLayout> done_;
  std::set<std::string> wrapper_names_;
  WgslStd140Plan plan_;
};

}  // namespace

WgslLayout wgsl_layout(const ir::Type& t, bool uniform) {
  if (t.is_array()) {
    const WgslLayout e = wgsl_layout(t.element(), uniform);
    const int stride = round_up(e.size, e.align);
    return {uniform ? std::max(e.align, 16) : e.align, stride * std::max(t.array_dims[0], 1)};
  }
  if (is_struct(t)) {
    int offset = 0, align = 4;
    for (const auto& f : *t.fields) {
      WgslLayout l = wgsl_layout(f.type, uniform);
      if (uniform && (f.type.base == Base::Struct || f.type.is_array())) l.align = std::max(l.align, 16);
      offset = round_up(offset, l.align) + l.size;
      align = std::max(align, l.align);
    }
    if (uniform) align = std::max(align, 16);
    return {align, round_up(offset, align)};
  }
  const int rows = t.vec;
  const int column_align = rows == 1 ? 4 : rows == 2 ? 8 : 16;
  if (t.is_matrix()) return {column_align, t.cols * column_align};
  return {column_align, rows * 4};
}

const Std140Member* WgslStd140Plan::wrapped(const ir::Expr& e) const {
  std::string type, member;
  if (e.kind == ir::Expr::Kind::Member && !e.args.empty() && is_struct(e.args[0]->type)) {
    type = e.args[0]->type.name;
    member = e.name;
  } else if (e.kind == ir::Expr::Kind::Sym && e.var && e.var->block) {
    type = e.var->block->type.name;
    member = e.var->name;
  } else {
    return nullptr;
  }
  const auto t = members.find(type);
  if (t == members.end()) return nullptr;
  const auto m = t->second.find(member);
  return m != t->second.end() && !m->second.wrapper.empty() ? &m->second : nullptr;
}

WgslStd140Plan plan_wgsl_std140(const ir::Module& module) { return Planner(module).run(); }

}  // namespace doublet::emit
