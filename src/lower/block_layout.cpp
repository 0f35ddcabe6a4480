// std140/std430 offsets (OpenGL 4.6 core spec, section 7.6.2.2, "Standard Uniform Block Layout";
// std430 is std140 without rounding array strides and struct alignments up to vec4).
#include "lower/block_layout.hpp"

#include <algorithm>

#include "lower/lower.hpp"
#include "lower/matrix_helpers.hpp"

namespace doublet::passes {
namespace {

int round_up(int x, int a) { return a ? (x + a - 1) / a * a : x; }

struct Shape {
  int size = 0, align = 4;
  int matrix_stride = 0;       // matrices
  int hi_offset = -1, lo_offset = -1;  // df_* structs
};

class Layout {
 public:
  explicit Layout(bool std140) : std140_(std140) {}

  Shape vector(int n) const {
    Shape s;
    s.size = 4 * n;
    s.align = n == 1 ? 4 : n == 2 ? 8 : 16;
    return s;
  }
  Shape float_matrix(int cols, int rows) const {
    Shape column = vector(rows);
    int stride = std140_ ? round_up(column.align, 16) : column.align;
    Shape s;
    s.size = cols * stride;
    s.align = stride;
    s.matrix_stride = stride;
    return s;
  }
  // A df_* struct {T hi; T lo;} with T = floatW or matCxR.
  Shape df(const ir::Type& t) const {
    Shape word = matrix::is_matrix(t) ? float_matrix(matrix::cols(t), matrix::rows(t)) : vector(df_width(t));
    Shape s;
    s.align = std140_ ? round_up(word.align, 16) : word.align;
    s.hi_offset = 0;
    s.lo_offset = round_up(word.size, word.align);
    s.size = round_up(s.lo_offset + word.size, s.align);
    s.matrix_stride = word.matrix_stride;
    return s;
  }
  // One element (no array dimensions).
  Shape element(const ir::Type& t) const {
    if (is_df(t) || matrix::is_matrix(t)) return df(t);
    if (t.base == ir::Base::Struct || t.base == ir::Base::Block) {
      int offset = 0, align = 4;
      for (const auto& f : *t.fields) {
        Shape m = whole(f.type);
        offset = round_up(offset, m.align) + m.size;
        align = std::max(align, m.align);
      }
      if (std140_) align = round_up(align, 16);
      Shape s;
      s.align = align;
      s.size = round_up(offset, align);
      return s;
    }
    if (t.is_matrix()) return float_matrix(t.cols, t.vec);
    return vector(t.vec);
  }
  int stride(const ir::Type& t) const {
    ir::Type e = t;
    e.array_dims.clear();
    Shape s = element(e);
    int stride = round_up(s.size, s.align);
    return std140_ ? round_up(stride, 16) : stride;
  }
  Shape whole(const ir::Type& t) const {
    if (!t.is_array()) return element(t);
    ir::Type e = t;
    e.array_dims.clear();
    Shape s = element(e);
    int count = 1;
    for (int d : t.array_dims) count *= std::max(d, 0);
    Shape a = s;
    a.align = std140_ ? round_up(s.align, 16) : s.align;
    a.size = count * stride(t);
    return a;
  }

 private:
  bool std140_;
};

// The user's spelling of a lowered type: df_dvec3 -> dvec3, df_dmat4 -> dmat4.
std::string original_name(const ir::Type& t) {
  std::string n = ir::type_name(t);
  if (n.rfind("df_d", 0) == 0) n = n.substr(3);
  return n + ir::array_suffix(t);
}

void members(const Layout& layout, const ir::Type& type, const std::string& prefix, int base,
             std::vector<BlockMember>& out) {
  int offset = 0;
  for (const auto& f : *type.fields) {
    Shape whole = layout.whole(f.type);
    offset = round_up(offset, whole.align);
    ir::Type elem = f.type;
    elem.array_dims.clear();
    bool plain_struct = elem.base == ir::Base::Struct && !is_df(elem) && !matrix::is_matrix(elem);
    if (plain_struct && !f.type.is_array()) {
      members(layout, elem, prefix + f.name + ".", base + offset, out);
    } else {
      if (plain_struct) {  // an array of structs: the array (with its stride), then element 0's members
        BlockMember array;
        array.name = prefix + f.name;
        array.type = original_name(f.type);
        array.lowered_type = ir::type_name(f.type) + ir::array_suffix(f.type);
        array.offset = base + offset;
        array.size = whole.size;
        array.array_stride = layout.stride(f.type);
        out.push_back(array);
        members(layout, elem, prefix + f.name + "[0].", base + offset, out);
        offset += whole.size;
        continue;
      }
      BlockMember m;
      m.name = prefix + f.name;
      m.type = original_name(f.type);
      m.lowered_type = ir::type_name(f.type) + ir::array_suffix(f.type);
      m.offset = base + offset;
      m.size = whole.size;
      if (f.type.is_array()) m.array_stride = layout.stride(f.type);
      Shape e = layout.element(elem);
      m.matrix_stride = e.matrix_stride;
      m.hi_offset = e.hi_offset;
      m.lo_offset = e.lo_offset;
      out.push_back(m);
    }
    offset += whole.size;
  }
}

}  // namespace

bool holds_doubles(const ir::Type& t) {
  if (t.base == ir::Base::Double || t.name.rfind("df_d", 0) == 0) return true;
  if (t.fields)
    for (const auto& f : *t.fields)
      if (holds_doubles(f.type)) return true;
  return false;
}

StdLayout std_layout(const ir::Type& t, bool std140) {
  const Layout layout(std140);
  const Shape whole = layout.whole(t);
  return {whole.size, whole.align, t.is_array() ? layout.stride(t) : 0};
}

std::vector<BlockMember> block_layout(const ir::Type& block, const std::string& packing) {
  std::vector<BlockMember> out;
  members(Layout(packing != "std430"), block, "", 0, out);
  return out;
}

}  // namespace doublet::passes
