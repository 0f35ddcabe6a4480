// std140 blocks in WGSL (docs/web.md, "std140 blocks in WGSL"). WGSL lays host-shareable structs out
// by its own rules (W3C WGSL, "Memory Layout"), which are std430's for the types doublet prints; the
// host writes a std140 block (every uniform block, and storage blocks declared std140) at the
// manifest's std140 offsets. So the members of a std140 block, and of the structs only std140 blocks
// hold, are printed with @align/@size where WGSL's own would differ, and an array whose element
// stride differs (16 against 4 or 8 for floats, 2-vectors and df_double) becomes an array of a
// wrapper struct whose one member `v` is padded to std140's stride; the printer reads `a[i].v`.
// What cannot be expressed that way is refused by member: a matrix with 2-row columns, a
// multi-dimensional array whose inner stride differs, a struct that std430 blocks or loose uniforms
// hold too and whose layout differs, an array read as a whole.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ir/ir.hpp"

namespace doublet::emit {

struct WgslLayout {
  int align = 4, size = 4;
};

// WGSL's own layout of a type; `uniform` adds the uniform address space's rounding of array and
// struct alignment to 16 bytes.
WgslLayout wgsl_layout(const ir::Type& t, bool uniform);

// How one member is printed; 0 and "" mean WGSL's own.
struct Std140Member {
  int align = 0, size = 0;
  std::string wrapper;  // the element type of an array whose stride is padded
};

struct Std140Wrapper {
  std::string name;
  ir::Type element;
  int stride = 16;
};

struct WgslStd140Plan {
  // struct or block name -> member name -> how it is printed, for types printed with std140's
  // layout (absent: WGSL's own layout is std140's, or the type is not in a std140 block).
  std::map<std::string, std::map<std::string, Std140Member>> members;
  std::vector<Std140Wrapper> wrappers;
  struct Refusal {
    ir::Loc loc;
    std::string message;
  };
  std::vector<Refusal> refusals;

  // The member's plan when `e` names an array member that reads through a wrapper (`blk.a`, or `a`
  // of an anonymous block), else null.
  const Std140Member* wrapped(const ir::Expr& e) const;
};

WgslStd140Plan plan_wgsl_std140(const ir::Module& module);

}  // namespace doublet::emit
