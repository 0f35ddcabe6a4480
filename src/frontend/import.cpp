#include "frontend/import.hpp"
#include "frontend/transcendentals.hpp"

#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include "frontend/builtin_names.hpp"
#include "frontend/declarations.hpp"
#include "frontend/text_scan.hpp"
#include "ir/walk.hpp"

namespace doublet::frontend {
namespace {

using namespace glslang;

std::string demangle(const TString& mangled) {
  std::string s(mangled.c_str());
  auto paren = s.find('(');
  return paren == std::string::npos ? s : s.substr(0, paren);
}


// Where each name is declared at global scope in `text`: its first occurrence outside braces,
// parentheses, comments and preprocessor lines, not followed by '(' (GLSL declares before use).
// glslang gives the globals of its linker-object list no place. One pass over the text.
std::unordered_map<std::string, ir::Loc> global_declarations(std::string_view text) {
  std::unordered_map<std::string, ir::Loc> first;
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  int line = 1, depth = 0;
  size_t line_start = 0;
  bool line_is_directive = false;
  for (size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = ++i;
      line_is_directive = false;
      continue;
    }
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    if (text.compare(i, 2, "/*") == 0) {
      size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) break;
      for (; i < end; ++i)
        if (text[i] == '\n') { ++line; line_start = i + 1; }
      i = end + 2;
      continue;
    }
    if (c == '#' && text.find_first_not_of(" \t", line_start) == i) line_is_directive = true;
    if (c == '{' || c == '(') ++depth;
    if (c == '}' || c == ')') --depth;
    if (!is_word(c)) { ++i; continue; }
    size_t end = i;
    while (end < text.size() && is_word(text[end])) ++end;
    if (depth == 0 && !line_is_directive) {
      size_t next = text.find_first_not_of(" \t\r\n", end);
      if (next == std::string_view::npos || text[next] != '(')
        first.emplace(std::string(text.substr(i, end - i)), ir::Loc{line, static_cast<int>(i - line_start) + 1});
    }
    i = end;
  }
  return first;
}

class Importer {
 public:
  Importer(const Options& options, std::string_view source, ir::Module& module, std::vector<Diagnostic>& diags)
      : options_(options), source_(source), module_(module), diags_(diags) {}

  bool run(TIntermediate& intermediate);

 private:
  // A glslang place as doublet's, naming the #include'd file it is in (one shared name per file).
  ir::Loc loc_of(const TSourceLoc& l) {
    ir::Loc loc{l.line, l.column, nullptr};
    if (l.name && !l.name->empty() && *l.name != "0" && l.name->c_str() != options_.file_name) {
      auto& shared = file_names_[l.name->c_str()];
      if (!shared) shared = std::make_shared<const std::string>(l.name->c_str());
      loc.file = shared;
    }
    return loc;
  }
  std::unordered_map<std::string, std::shared_ptr<const std::string>> file_names_;

  // ---- diagnostics -------------------------------------------------------
  void error(const TSourceLoc& loc, const std::string& message) {
    std::string file = loc.name && !loc.name->empty() ? loc.name->c_str() : options_.file_name;
    if (file == "0") file = options_.file_name;
    diags_.push_back({file, loc.line, loc.column, Severity::Error, message});
    failed_ = true;
  }

  // ---- types -------------------------------------------------------------
  ir::Type import_type(const TType& t, const TSourceLoc& loc) {
    ir::Type out;
    switch (t.getBasicType()) {
      case EbtVoid: out.base = ir::Base::Void; break;
      case EbtBool: out.base = ir::Base::Bool; break;
      case EbtInt: out.base = ir::Base::Int; break;
      case EbtUint: out.base = ir::Base::Uint; break;
      case EbtFloat: out.base = ir::Base::Float; break;
      case EbtDouble: out.base = ir::Base::Double; break;
      case EbtSampler:
        out.base = ir::Base::Opaque;
        out.name = t.getSampler().getString().c_str();
        break;
      case EbtAtomicUint:  // passed through as it is; check_target refuses it where the target lacks it
        out.base = ir::Base::Opaque;
        out.name = "atomic_uint";
        break;
      case EbtStruct:
      case EbtBlock: {
        out.base = t.getBasicType() == EbtStruct ? ir::Base::Struct : ir::Base::Block;
        out.name = t.getTypeName().c_str();
        if (out.base == ir::Base::Struct && out.name.empty()) out.name = anonymous_struct_name(t.getStruct());
        out.fields = struct_fields(t, loc, out.base == ir::Base::Struct);
        break;
      }
      case EbtInt64:
      case EbtUint64:
        // Desktop GLSL 4.x has them (GL_ARB_gpu_shader_int64, which the shader enables itself).
        out.base = t.getBasicType() == EbtInt64 ? ir::Base::Int64 : ir::Base::Uint64;
        if (options_.target != Target::Glsl450 && reported_.insert("int64").second)
          error(loc, "type '" + std::string(t.getBasicTypeString().c_str()) +
                         "' is not supported: 64-bit integers are not available on " +
                         std::string(to_string(options_.target)) +
                         "; glsl450 has them (GL_ARB_gpu_shader_int64); elsewhere split the value into two 32-bit "
                         "ints (high and low words), or carry it as a double when it fits in 48 bits");
        break;
      default:
        error(loc, std::string("type '") + t.getCompleteString().c_str() + "' is not supported by doublet");
        out.base = ir::Base::Void;
    }
    if (t.isMatrix()) {
      out.cols = t.getMatrixCols();
      out.vec = t.getMatrixRows();
    } else if (t.isVector()) {
      out.vec = t.getVectorSize();
    }
    if (t.isArray()) {
      const TArraySizes* sizes = t.getArraySizes();
      for (int i = 0; i < sizes->getNumDims(); ++i) out.array_dims.push_back(sizes->getDimSize(i));
    }
    return out;
  }

  std::shared_ptr<std::vector<ir::Field>> struct_fields(const TType& t, const TSourceLoc& loc, bool is_struct) {
    std::string name = t.getTypeName().c_str();
    if (is_struct && name.empty()) name = anonymous_struct_name(t.getStruct());
    if (is_struct) {
      auto it = structs_.find(name);
      if (it != structs_.end()) return it->second;
    }
    auto fields = std::make_shared<std::vector<ir::Field>>();
    for (const TTypeLoc& member : *t.getStruct()) {
      ir::Field f;
      f.name = member.type->getFieldName().c_str();
      f.type = import_type(*member.type, member.loc);
      f.layout = import_layout(member.type->getQualifier());
      f.interp = import_interp(member.type->getQualifier());
      fields->push_back(std::move(f));
    }
    if (is_struct) {
      structs_[name] = fields;
      ir::Type st;
      st.base = ir::Base::Struct;
      st.name = name;
      st.fields = fields;
      module_.structs.push_back(st);  // after its member structs: declaration order is valid
    }
    return fields;
  }

  // glslang keeps no name for the built-ins doublet does not import (subgroupBarrier(),
  // memoryBarrierAtomicCounter(), textureProjLodOffset(...): "unsupported built-in operation" named
  // none, for 56 of glslang's test files). Its place is the call's closing parenthesis (or, with
  // one argument, the argument): the name is the identifier before the '(' on that line.
  std::string unsupported_call_message(const TSourceLoc& loc, const char* fallback) {
    const std::string file = loc.name ? loc.name->c_str() : "";
    if ((!file.empty() && file != "0" && file != options_.file_name) || loc.line <= 0 || loc.column <= 0)
      return fallback;  // in an #included file
    if (!line_index_) line_index_.emplace(source_);
    const std::string_view row = line_index_->line(loc.line);
    const size_t at = static_cast<size_t>(loc.column - 1);
    if (at >= row.size()) return fallback;
    size_t open = at + 1;
    if (row[at] == ')') {  // a call of several arguments (or none): at its ')'
      int depth = 0;
      for (size_t i = at + 1; i-- > 0;) {
        if (row[i] == ')') ++depth;
        if (row[i] == '(' && --depth == 0) { open = i; break; }
      }
    } else if (at > 0 && row[at - 1] == '(') {  // a call of one argument: at the argument
      open = at - 1;
    }
    if (open > at) return fallback;
    size_t end = open;
    while (end > 0 && is_blank(row[end - 1])) --end;
    size_t begin = end;
    while (begin > 0 && is_word_char(row[begin - 1])) --begin;
    if (begin == end || is_digit(row[begin])) return fallback;
    return "built-in function '" + std::string(row.substr(begin, end - begin)) + "' is not supported by doublet";
  }
  std::optional<LineIndex> line_index_;

  // `struct { float r; } parts[2];` has no type name: printed as an empty name (`uniform void
  // parts[2]`, spv.uniformInitializerStruct.frag), and every anonymous struct shared the first
  // one's fields. Each gets a name of its own that the main file does not use.
  std::string anonymous_struct_name(const TTypeList* members) {
    auto it = anonymous_structs_.find(members);
    if (it != anonymous_structs_.end()) return it->second;
    std::string name;
    for (int n = static_cast<int>(anonymous_structs_.size()) + 1;; ++n) {
      name = "anonymous_struct" + std::to_string(n);
      if (source_.find(name) == std::string_view::npos) break;
    }
    return anonymous_structs_[members] = name;
  }
  std::map<const TTypeList*, std::string> anonymous_structs_;

  static ir::Layout import_layout(const TQualifier& q) {
    ir::Layout l;
    if (q.hasLocation()) l.location = static_cast<int>(q.layoutLocation);
    if (q.hasBinding()) l.binding = static_cast<int>(q.layoutBinding);
    if (q.hasSet()) l.set = static_cast<int>(q.layoutSet);
    if (q.hasOffset()) l.offset = q.layoutOffset;
    switch (q.layoutPacking) {
      case ElpStd140: l.packing = "std140"; break;
      case ElpStd430: l.packing = "std430"; break;
      case ElpShared: l.packing = "shared"; break;
      case ElpPacked: l.packing = "packed"; break;
      default: break;
    }
    if (q.layoutMatrix == ElmRowMajor) l.matrix = "row_major";
    if (q.hasFormat()) l.format = TQualifier::getLayoutFormatString(q.layoutFormat);
    l.passthrough = q.layoutPassthrough;
    return l;
  }

  static ir::Interp import_interp(const TQualifier& q) {
    if (q.flat) return ir::Interp::Flat;
    if (q.nopersp) return ir::Interp::NoPerspective;
    if (q.centroid) return ir::Interp::Centroid;
    if (q.smooth) return ir::Interp::Smooth;
    return ir::Interp::Default;
  }

  static ir::Storage import_storage(const TQualifier& q, const std::string& name) {
    if (name.rfind("gl_", 0) == 0) return ir::Storage::BuiltIn;
    switch (q.storage) {
      case EvqTemporary: return ir::Storage::Local;
      case EvqGlobal: return ir::Storage::Global;
      case EvqConst: return ir::Storage::Const;
      case EvqVaryingIn: return ir::Storage::In;
      case EvqVaryingOut: return ir::Storage::Out;
      case EvqUniform: return ir::Storage::Uniform;
      case EvqBuffer: return ir::Storage::Buffer;
      case EvqShared: return ir::Storage::Shared;
      case EvqIn:
      case EvqConstReadOnly: return ir::Storage::ParamIn;
      case EvqOut: return ir::Storage::ParamOut;
      case EvqInOut: return ir::Storage::ParamInOut;
      default: return ir::Storage::BuiltIn;
    }
  }

  // ---- variables ---------------------------------------------------------
  ir::VarPtr var_for(const TIntermSymbol& sym) {
    // An unnamed parameter (`float bar(int) { ... }`) has no symbol id of its own: every one
    // shared the first one's variable, so bar's int parameter was printed as the float of an
    // earlier function's (glslang's recurse1.vert: an internal error on ES). Each gets its own.
    const bool unnamed = sym.getName().empty();
    auto it = unnamed ? vars_.end() : vars_.find(sym.getId());
    if (it != vars_.end()) {
      if (it->second->loc.line == 0) it->second->loc = loc_of(sym.getLoc());  // linker objects carry no place
      return it->second;
    }
    auto v = std::make_shared<ir::Var>();
    v->id = next_id_++;
    v->name = sym.getName().c_str();
    v->type = import_type(sym.getType(), sym.getLoc());
    v->declared_type = v->type;
    const TQualifier& q = sym.getQualifier();
    v->storage = import_storage(q, v->name);
    // glslang marks `const T x = <not a constant expression>;` EvqConstReadOnly, as it marks
    // const parameters: outside a parameter list it is a variable written once.
    if (q.storage == EvqConstReadOnly && !importing_params_) v->storage = ir::Storage::Local;
    v->layout = import_layout(q);
    v->interp = import_interp(q);
    v->invariant = q.invariant;
    v->patch = q.patch;
    v->precise = q.isNoContraction();
    v->readonly = q.readonly;
    v->writeonly = q.writeonly;
    v->coherent = q.coherent;
    v->volatile_ = q.volatil;
    v->restrict_ = q.restrict;
    v->loc = loc_of(sym.getLoc());
    if (v->loc.line == 0 && sym.getType().isStruct() && !sym.getType().getStruct()->empty())
      v->loc = loc_of(sym.getType().getStruct()->front().loc);  // a block from the linker objects: its first member
    else if (v->loc.line == 0)
      v->loc = global_declaration(v->name);
    if (!unnamed) vars_[sym.getId()] = v;
    if (v->storage == ir::Storage::Const && sym.getConstArray().size() > 0) {
      // A constant array/struct indexed dynamically: glslang keeps the symbol
      // but not the declaration; declare it from its folded value.
      global_index_.emplace(v.get(), module_.globals.size());
      module_.globals.push_back(v);
      module_.global_inits.push_back(constant(sym.getConstArray(), sym.getType(), sym.getLoc()));
    }
    return v;
  }

  ir::VarPtr block_member(const TIntermSymbol& block, int index, const TSourceLoc& loc) {
    auto key = std::make_pair(block.getId(), index);
    auto it = members_.find(key);
    if (it != members_.end()) return it->second;
    ir::VarPtr block_var = var_for(block);
    const TTypeLoc& member = (*block.getType().getStruct())[index];
    auto v = std::make_shared<ir::Var>();
    v->id = next_id_++;
    v->name = member.type->getFieldName().c_str();
    v->type = import_type(*member.type, loc);
    v->declared_type = v->type;
    v->storage = v->name.rfind("gl_", 0) == 0 ? ir::Storage::BuiltIn : block_var->storage;
    v->layout = import_layout(member.type->getQualifier());
    v->block = block_var;
    members_[key] = v;
    return v;
  }

  // ---- expressions -------------------------------------------------------
  ir::ExprPtr constant(const TConstUnionArray& values, const TType& type, const TSourceLoc& loc) {
    if (type.getBasicType() == EbtStruct || type.getBasicType() == EbtBlock) return struct_constant(values, type, loc);
    auto e = ir::Expr::make(ir::Expr::Kind::Const, import_type(type, loc), loc_of(loc));
    for (int i = 0; i < values.size(); ++i) {
      ir::Scalar s;
      const TConstUnion& c = values[i];
      // glslang stores float constants as EbtDouble unions: the node's type decides.
      TBasicType kind = c.getType() == EbtDouble ? type.getBasicType() : c.getType();
      switch (kind) {
        case EbtDouble:
          s.base = ir::Base::Double;
          s.d = c.getDConst();
          break;
        case EbtFloat:
          // glslang folds float expressions in double; the driver works in float.
          s.base = ir::Base::Float;
          s.d = static_cast<double>(static_cast<float>(c.getDConst()));
          break;
        case EbtInt: s.base = ir::Base::Int; s.i = c.getIConst(); break;
        case EbtUint: s.base = ir::Base::Uint; s.i = c.getUConst(); break;
        case EbtInt64: s.base = ir::Base::Int64; s.i = c.getI64Const(); break;
        case EbtUint64: s.base = ir::Base::Uint64; s.i = static_cast<long long>(c.getU64Const()); break;
        case EbtBool: s.base = ir::Base::Bool; s.b = c.getBConst(); break;
        default: error(loc, "unsupported constant type"); break;
      }
      e->values.push_back(s);
    }
    return e;
  }

  // glslang folds `S(1.0lf, 2)` (and arrays of such) into one flat list of
  // scalars: rebuild the constructors, member by member, so the passes see
  // each double member as a value of its own.
  ir::ExprPtr struct_constant(const TConstUnionArray& values, const TType& type, const TSourceLoc& loc) {
    auto e = ir::Expr::make(ir::Expr::Kind::Construct, import_type(type, loc), loc_of(loc));
    int start = 0;
    auto take = [&](const TType& part) {
      const int size = part.computeNumComponents();
      e->args.push_back(constant(TConstUnionArray(values, start, size), part, loc));
      start += size;
    };
    if (type.isArray()) {
      const TType element(type, 0);
      for (int i = 0; i < type.getOuterArraySize(); ++i) take(element);
    } else {
      for (const TTypeLoc& member : *type.getStruct()) take(*member.type);
    }
    return e;
  }

  ir::ExprPtr make(ir::Expr::Kind k, TIntermTyped* node) {
    return ir::Expr::make(k, import_type(node->getType(), node->getLoc()), loc_of(node->getLoc()));
  }

  ir::ExprPtr expr(TIntermNode* node) {
    if (auto* s = node->getAsSymbolNode()) {
      if (s->getBasicType() == EbtBlock && std::string(s->getName().c_str()).rfind("anon@", 0) == 0) {
        error(s->getLoc(), "an anonymous block cannot be used as a value");
      }
      auto e = make(ir::Expr::Kind::Sym, s);
      e->var = var_for(*s);
      return e;
    }
    if (auto* c = node->getAsConstantUnion()) return constant(c->getConstArray(), c->getType(), c->getLoc());
    if (auto* b = node->getAsBinaryNode()) return binary(b);
    if (auto* u = node->getAsUnaryNode()) return unary(u);
    if (auto* a = node->getAsAggregate()) return aggregate(a);
    if (auto* sel = node->getAsSelectionNode()) {
      auto e = make(ir::Expr::Kind::Ternary, sel);
      if (!sel->getFalseBlock() || !sel->getTrueBlock()) {
        error(sel->getLoc(), "malformed conditional expression");
        return e;
      }
      e->args = {expr(sel->getCondition()), expr(sel->getTrueBlock()), expr(sel->getFalseBlock())};
      return e;
    }
    auto* typed = node->getAsTyped();
    error(typed ? typed->getLoc() : TSourceLoc{}, "unsupported expression");
    return ir::Expr::make(ir::Expr::Kind::Const, ir::scalar_type(ir::Base::Int));
  }

  ir::ExprPtr binary(TIntermBinary* b) {
    TOperator op = b->getOp();
    if (op == EOpIndexDirectStruct) {
      int index = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
      auto* sym = b->getLeft()->getAsSymbolNode();
      if (sym && sym->getBasicType() == EbtBlock && std::string(sym->getName().c_str()).rfind("anon@", 0) == 0) {
        auto e = make(ir::Expr::Kind::Sym, b);
        e->var = block_member(*sym, index, b->getLoc());
        return e;
      }
      auto e = make(ir::Expr::Kind::Member, b);
      e->name = (*b->getLeft()->getType().getStruct())[index].type->getFieldName().c_str();
      e->args = {expr(b->getLeft())};
      return e;
    }
    if (op == EOpVectorSwizzle) {
      auto e = make(ir::Expr::Kind::Member, b);
      static const char* letters = "xyzw";
      for (TIntermNode* n : b->getRight()->getAsAggregate()->getSequence())
        e->name += letters[n->getAsConstantUnion()->getConstArray()[0].getIConst()];
      e->args = {expr(b->getLeft())};
      return e;
    }
    if (op == EOpIndexDirect || op == EOpIndexIndirect) {
      auto e = make(ir::Expr::Kind::Index, b);
      e->args = {expr(b->getLeft()), expr(b->getRight())};
      return e;
    }
    if (op == EOpMatrixSwizzle) {
      error(b->getLoc(), "matrix swizzles are not supported");
      return make(ir::Expr::Kind::Const, b);
    }
    if (op == EOpMul && b->getLeft()->getType().isMatrix() && b->getRight()->getType().isMatrix()) {
      // glslang spells matrixCompMult(a, b) as a component-wise EOpMul; `*` would be the product.
      auto e = make(ir::Expr::Kind::Builtin, b);
      e->name = "matrixCompMult";
      e->args = {expr(b->getLeft()), expr(b->getRight())};
      return e;
    }
    const char* spelling = binary_operator_spelling(op);
    if (!spelling) {
      error(b->getLoc(), "unsupported binary operation (glslang operator " + std::to_string(static_cast<int>(op)) + ")");
      return make(ir::Expr::Kind::Const, b);
    }
    auto e = make(op == EOpComma ? ir::Expr::Kind::Comma : ir::Expr::Kind::Binary, b);
    e->op = spelling;
    e->args = {expr(b->getLeft()), expr(b->getRight())};
    return e;
  }

  ir::ExprPtr unary(TIntermUnary* u) {
    TOperator op = u->getOp();
    if (is_conversion(op) || op == EOpCopyObject) {
      auto e = make(ir::Expr::Kind::Construct, u);
      e->args = {expr(u->getOperand())};
      return e;
    }
    if (const char* spelling = unary_operator_spelling(op)) {
      auto e = make(ir::Expr::Kind::Unary, u);
      e->op = spelling;
      e->args = {expr(u->getOperand())};
      return e;
    }
    if (const char* name = builtin_function_name(op, 1)) {
      auto e = make(ir::Expr::Kind::Builtin, u);
      e->name = name;
      e->args = {expr(u->getOperand())};
      return e;
    }
    if (op == EOpArrayLength) {
      // `.length()` of a runtime-sized array (glslang folds the sized ones to constants): the IR's
      // "length" built-in on an array, printed as a.length() (GLSL) and arrayLength (WGSL).
      auto e = make(ir::Expr::Kind::Builtin, u);
      e->name = "length";
      e->args = {expr(u->getOperand())};
      return e;
    }
    error(u->getLoc(), unsupported_call_message(u->getLoc(), (std::string("unsupported operation (glslang operator ") +
                                                              std::to_string(static_cast<int>(op)) + ")").c_str()));
    return make(ir::Expr::Kind::Const, u);
  }

  ir::ExprPtr aggregate(TIntermAggregate* a) {
    TOperator op = a->getOp();
    std::vector<ir::ExprPtr> args;
    for (TIntermNode* n : a->getSequence()) args.push_back(expr(n));
    if (op == EOpFunctionCall) {
      auto e = make(ir::Expr::Kind::Call, a);
      e->name = demangle(a->getName());
      e->args = std::move(args);
      calls_.emplace(a->getName().c_str(), std::make_pair(a->getLoc(), e));  // the first call of each overload
      return e;
    }
    if (op > EOpConstructGuardStart && op < EOpConstructGuardEnd) {
      auto e = make(ir::Expr::Kind::Construct, a);
      e->args = std::move(args);
      return e;
    }
    if (op == EOpComma || op == EOpSequence) {
      auto e = make(ir::Expr::Kind::Comma, a);
      e->args = std::move(args);
      return e;
    }
    const char* name = builtin_function_name(op, static_cast<int>(args.size()));
    if (!name) {
      std::string mangled = a->getName().c_str();
      error(a->getLoc(), mangled.empty() ? unsupported_call_message(a->getLoc(), "unsupported built-in operation")
                                         : "built-in function '" + demangle(a->getName()) + "' is not supported");
      return make(ir::Expr::Kind::Const, a);
    }
    auto e = make(ir::Expr::Kind::Builtin, a);
    e->name = name;
    e->args = std::move(args);
    return e;
  }

  // ---- statements --------------------------------------------------------
  static bool is_assignment_list(TIntermAggregate* a) {
    if (a->getSequence().empty()) return false;
    for (TIntermNode* n : a->getSequence()) {
      auto* b = n->getAsBinaryNode();
      if (!b || b->getOp() != EOpAssign || !b->getLeft()->getAsSymbolNode()) return false;
    }
    return true;
  }

  ir::StmtPtr block(TIntermNode* node) {
    auto blk = ir::Stmt::make(ir::Stmt::Kind::Block);
    if (!node) return blk;
    auto* a = node->getAsAggregate();
    if (a && a->getOp() == EOpSequence && !is_for_loop(a)) {
      blk->loc = loc_of(a->getLoc());
      for (TIntermNode* n : a->getSequence()) stmt(n, blk->body);
    } else {
      stmt(node, blk->body);
    }
    return blk;
  }

  static bool is_for_loop(TIntermAggregate* a) {
    auto& seq = a->getSequence();
    return !seq.empty() && seq.size() <= 2 && seq.back()->getAsLoopNode() && seq.back()->getAsLoopNode()->testFirst() &&
           (seq.size() == 1 || !seq.front()->getAsLoopNode());
  }

  void stmt(TIntermNode* node, std::vector<ir::StmtPtr>& out) {
    if (!node) return;
    if (auto* a = node->getAsAggregate(); a && a->getOp() == EOpSequence) {
      if (is_for_loop(a)) {
        auto loop = loop_stmt(a->getSequence().back()->getAsLoopNode());
        if (a->getSequence().size() == 2) {
          std::vector<ir::StmtPtr> init;
          stmt(a->getSequence().front(), init);
          if (init.size() == 1 && init[0]->kind == ir::Stmt::Kind::Expr) {
            loop->body[0] = init[0];
          } else {
            for (auto& s : init) out.push_back(s);
          }
        }
        out.push_back(loop);
        return;
      }
      if (is_assignment_list(a)) {  // `float a = 1.0, b = 2.0;` is not a scope
        for (TIntermNode* n : a->getSequence()) stmt(n, out);
        return;
      }
      out.push_back(block(a));
      return;
    }
    if (auto* br = node->getAsBranchNode()) {
      ir::Stmt::Kind k;
      switch (br->getFlowOp()) {
        case EOpKill: k = ir::Stmt::Kind::Discard; break;
        case EOpReturn: k = ir::Stmt::Kind::Return; break;
        case EOpBreak: k = ir::Stmt::Kind::Break; break;
        case EOpContinue: k = ir::Stmt::Kind::Continue; break;
        case EOpCase: k = ir::Stmt::Kind::Case; break;
        case EOpDefault: k = ir::Stmt::Kind::Default; break;
        default: error(br->getLoc(), "unsupported jump statement"); return;
      }
      auto s = ir::Stmt::make(k, loc_of(br->getLoc()));
      if (br->getExpression()) s->expr = expr(br->getExpression());
      out.push_back(s);
      return;
    }
    if (auto* sel = node->getAsSelectionNode(); sel && sel->getBasicType() == EbtVoid) {
      auto s = ir::Stmt::make(ir::Stmt::Kind::If, loc_of(sel->getLoc()));
      s->expr = expr(sel->getCondition());
      s->body.push_back(block(sel->getTrueBlock()));
      if (sel->getFalseBlock()) s->body.push_back(block(sel->getFalseBlock()));
      out.push_back(s);
      return;
    }
    if (auto* loop = node->getAsLoopNode()) {
      out.push_back(loop_stmt(loop));
      return;
    }
    if (auto* sw = node->getAsSwitchNode()) {
      auto s = ir::Stmt::make(ir::Stmt::Kind::Switch, loc_of(sw->getLoc()));
      s->expr = expr(sw->getCondition());
      s->body.push_back(block(sw->getBody()));
      out.push_back(s);
      return;
    }
    if (auto* typed = node->getAsTyped()) {
      auto s = ir::Stmt::make(ir::Stmt::Kind::Expr, loc_of(typed->getLoc()));
      s->expr = expr(typed);
      out.push_back(s);
      return;
    }
    error(TSourceLoc{}, "unsupported statement");
  }

  ir::StmtPtr loop_stmt(TIntermLoop* loop) {
    auto s = ir::Stmt::make(ir::Stmt::Kind::Loop, loc_of(loop->getLoc()));
    s->test_first = loop->testFirst();
    if (loop->getTest()) s->expr = expr(loop->getTest());
    if (loop->getTerminal()) s->step = expr(loop->getTerminal());
    s->body = {nullptr, block(loop->getBody())};
    return s;
  }

  // ---- functions and globals ---------------------------------------------
  void function(TIntermAggregate* a) {
    auto f = std::make_shared<ir::Function>();
    f->name = demangle(a->getName());
    f->return_type = import_type(a->getType(), a->getLoc());
    f->loc = loc_of(a->getLoc());
    auto& seq = a->getSequence();
    if (!seq.empty())
      if (auto* params = seq[0]->getAsAggregate())
        for (TIntermNode* p : params->getSequence())
          if (auto* sym = p->getAsSymbolNode()) {
            importing_params_ = true;
            f->params.push_back(var_for(*sym));
            importing_params_ = false;
          }
    f->body = seq.size() > 1 ? block(seq[1]) : ir::Stmt::make(ir::Stmt::Kind::Block);
    module_.functions.push_back(f);
    defined_.insert(a->getName().c_str());
  }

  // glslang accepts a call of a function that is only declared (its body may come from another
  // compilation unit at link time, as in its own link.* tests); the lowered shader stands alone, so
  // that call would only fail doublet's re-validation (an internal error before).
  void refuse_calls_without_bodies() {
    std::vector<std::pair<TSourceLoc, ir::ExprPtr>> missing;
    for (const auto& [mangled, call] : calls_)
      if (!defined_.count(mangled) && !(transcendentals && is_transcendental_name(call.second->name)))
        missing.push_back(call);  // the transcendental prototypes are doublet's (mark_transcendental_calls)
    std::sort(missing.begin(), missing.end(), [](const auto& a, const auto& b) {
      return std::make_pair(a.first.line, a.first.column) < std::make_pair(b.first.line, b.first.column);
    });
    for (const auto& call : missing) {
      const ir::Expr& e = *call.second;
      std::string signature = e.name + "(";
      for (size_t i = 0; i < e.args.size(); ++i) signature += (i ? ", " : "") + ir::type_name(e.args[i]->type);
      signature += ")";
      error(call.first, "'" + signature + "' is declared but has no body in this shader: doublet lowers a "
                        "shader on its own, so a function's body cannot come from another compilation unit");
    }
  }

  void global_symbol(TIntermSymbol* sym) {
    std::string name = sym->getName().c_str();
    if (name.rfind("gl_", 0) == 0) return;
    if (sym->getBasicType() == EbtBlock && std::string(sym->getType().getTypeName().c_str()).rfind("gl_", 0) == 0)
      return;  // built-in blocks (gl_PerVertex)
    // Per-vertex and per-primitive qualifiers (barycentric and mesh extensions) are not in the IR:
    // dropped, `pervertexNV in float a[3]` became an ordinary input whose three locations overlapped
    // the next one's (spv.fragmentShaderBarycentric2.frag), a different shader.
    auto per_qualifier = [](const TQualifier& q) -> const char* {
      return q.pervertexNV ? "pervertexNV" : q.pervertexEXT ? "pervertexEXT" : q.perPrimitiveNV ? "perprimitiveNV"
             : q.perViewNV ? "perviewNV" : q.perTaskNV ? "taskNV" : nullptr;
    };
    auto refuse_per = [&](const char* per, const std::string& what, const TSourceLoc& loc) {
      if (!reported_.insert(std::string(per) + " " + what).second) return;
      const ir::Loc at = loc.line ? loc_of(loc) : global_declaration(name);
      diags_.push_back({ir::file_of(at, options_.file_name), at.line, at.column, Severity::Error,
                        "'" + what + "' is declared '" + per + "', a qualifier doublet does not carry: the lowered "
                        "variable would be an ordinary one"});
      failed_ = true;
    };
    if (const char* per = per_qualifier(sym->getQualifier())) refuse_per(per, name, sym->getLoc());
    if (sym->getBasicType() == EbtBlock && sym->getType().getStruct())
      for (const TTypeLoc& member : *sym->getType().getStruct())
        if (const char* per = per_qualifier(member.type->getQualifier()))
          refuse_per(per, member.type->getFieldName().c_str(), member.loc);
    ir::VarPtr v = var_for(*sym);
    if (!global_index_.emplace(v.get(), module_.globals.size()).second) return;
    if (v->storage == ir::Storage::Local) v->storage = ir::Storage::Global;  // a global `const` with a run-time value
    module_.globals.push_back(v);
    // A uniform's initializer (its value until the application sets one) lives in the symbol's
    // constant, not in the tree (it was silently dropped once: spv.uniformInitializerStruct.frag);
    // the uniform-defaults pass decides what becomes of it.
    const bool initialised_uniform = sym->getQualifier().storage == EvqUniform && sym->getConstArray().size() > 0;
    module_.global_inits.push_back(initialised_uniform ? constant(sym->getConstArray(), sym->getType(), sym->getLoc())
                                                       : nullptr);
  }

  void global_initializer(TIntermBinary* assign) {
    auto* sym = assign->getLeft()->getAsSymbolNode();
    global_symbol(sym);
    module_.global_inits[global_index_.at(var_for(*sym).get())] = expr(assign->getRight());
  }

  void top_level(TIntermNode* node) {
    if (auto* a = node->getAsAggregate()) {
      switch (a->getOp()) {
        case EOpFunction: function(a); return;
        case EOpLinkerObjects: return;  // handled first, for declaration order
        case EOpSequence:
          for (TIntermNode* n : a->getSequence()) top_level(n);
          return;
        default: break;
      }
    }
    if (auto* b = node->getAsBinaryNode(); b && b->getOp() == EOpAssign && b->getLeft()->getAsSymbolNode()) {
      global_initializer(b);
      return;
    }
    auto* typed = node->getAsTyped();
    error(typed ? typed->getLoc() : TSourceLoc{}, "unsupported global statement");
  }

  const Options& options_;
  std::string_view source_;  // the main file's text
  std::optional<std::unordered_map<std::string, ir::Loc>> global_declarations_;  // built on first use

  ir::Loc global_declaration(const std::string& name) {
    if (!global_declarations_) global_declarations_ = global_declarations(source_);
    auto it = global_declarations_->find(name);
    return it == global_declarations_->end() ? ir::Loc{} : it->second;
  }
  ir::Module& module_;
  std::vector<Diagnostic>& diags_;
  bool failed_ = false;
  bool importing_params_ = false;  // var_for is reading a function's parameter list
  int next_id_ = 1;
  std::map<long long, ir::VarPtr> vars_;
  std::map<std::pair<long long, int>, ir::VarPtr> members_;
  std::map<std::string, std::shared_ptr<std::vector<ir::Field>>> structs_;
  std::unordered_map<const ir::Var*, size_t> global_index_;  // position in module_.globals
  std::set<std::string> reported_;  // diagnostics given once per kind
  std::set<std::string> defined_;    // mangled names of the functions with a body
  std::map<std::string, std::pair<TSourceLoc, ir::ExprPtr>> calls_;  // mangled name -> first call

 public:
  bool transcendentals = false;  // parsed with the transcendental prototypes
  bool failed() const { return failed_; }
  void linker_objects(TIntermAggregate* root) {
    for (TIntermNode* n : root->getSequence())
      if (auto* a = n->getAsAggregate(); a && a->getOp() == EOpLinkerObjects)
        for (TIntermNode* obj : a->getSequence())
          if (auto* sym = obj->getAsSymbolNode()) global_symbol(sym);
  }
  void top(TIntermNode* node) { top_level(node); }
};

// The layout declarations of a geometry or tessellation stage, rebuilt from what glslang recorded
// (the declarations themselves are not in its tree).
std::vector<std::string> stage_layouts(const TIntermediate& in) {
  std::vector<std::string> out;
  auto join = [](const std::vector<std::string>& parts) {
    std::string s;
    for (const auto& p : parts) s += (s.empty() ? "" : ", ") + p;
    return s;
  };
  std::vector<std::string> input, output;
  switch (in.getStage()) {
    case EShLangGeometry:
      if (in.getInputPrimitive() != glslang::ElgNone) input.push_back(glslang::TQualifier::getGeometryString(in.getInputPrimitive()));
      if (in.getInvocations() > 0) input.push_back("invocations = " + std::to_string(in.getInvocations()));
      if (in.getOutputPrimitive() != glslang::ElgNone) output.push_back(glslang::TQualifier::getGeometryString(in.getOutputPrimitive()));
      if (in.getVertices() > 0) output.push_back("max_vertices = " + std::to_string(in.getVertices()));
      break;
    case EShLangTessControl:
      if (in.getVertices() > 0) output.push_back("vertices = " + std::to_string(in.getVertices()));
      break;
    case EShLangTessEvaluation:
      if (in.getInputPrimitive() != glslang::ElgNone) input.push_back(glslang::TQualifier::getGeometryString(in.getInputPrimitive()));
      if (in.getVertexSpacing() != glslang::EvsNone) input.push_back(glslang::TQualifier::getVertexSpacingString(in.getVertexSpacing()));
      if (in.getVertexOrder() != glslang::EvoNone) input.push_back(glslang::TQualifier::getVertexOrderString(in.getVertexOrder()));
      if (in.getPointMode()) input.push_back("point_mode");
      break;
    default: break;
  }
  if (!input.empty()) out.push_back("layout(" + join(input) + ") in;");
  if (!output.empty()) out.push_back("layout(" + join(output) + ") out;");
  return out;
}

bool Importer::run(TIntermediate& intermediate) {
  auto* root = intermediate.getTreeRoot() ? intermediate.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) {
    diags_.push_back({options_.file_name, 1, 1, Severity::Error, "the shader has no code"});
    return false;
  }
  linker_objects(root);
  top_level(root);
  refuse_calls_without_bodies();
  // glslang's hidden `tempReturn` (an out argument converted after the call: `f(x)` with
  // `out int` for a float x) is a global it never declares: the lowered text used it undeclared
  // (spv.functionSemantics.frag, internal error). It lives within one expression: a local, whose
  // declaration place_declarations then hoists.
  for (const auto& f : module_.functions)
    ir::visit(f->body, [&](const ir::ExprPtr& e) {
      if (e->kind == ir::Expr::Kind::Sym && e->var->storage == ir::Storage::Global && !global_index_.count(e->var.get()))
        e->var->storage = ir::Storage::Local;
    });
  if (module_.stage == ir::StageKind::Compute)
    for (int i = 0; i < 3; ++i) module_.local_size[i] = static_cast<int>(intermediate.getLocalSize(i));
  module_.stage_layouts = stage_layouts(intermediate);
  return !failed_;
}

}  // namespace

bool import_module(const ParsedShader& parsed, const Options& options, ir::Module& out,
                   std::vector<Diagnostic>& diagnostics) {
  out.stage = *options.stage;
  out.source_version = parsed.info.version;
  out.source_es = parsed.info.es;
  Importer importer(options, parsed.source, out, diagnostics);
  importer.transcendentals = parsed.transcendentals;
  if (!importer.run(*parsed.intermediate)) return false;
  if (parsed.transcendentals) mark_transcendental_calls(out);
  // A `layout(set = N)` read as set 0 (parse, --target wgsl) qualifies the first global declared
  // after it in the main file.
  for (const ParsedShader::DescriptorSet& s : parsed.descriptor_sets) {
    ir::Var* qualified = nullptr;
    auto before = [](const ir::Loc& a, int line, int column) { return a.line < line || (a.line == line && a.column < column); };
    for (const auto& g : out.globals)
      if (!g->loc.file && !before(g->loc, s.line, s.column) && g->layout.set == 0 &&
          (!qualified || before(g->loc, qualified->loc.line, qualified->loc.column)))
        qualified = g.get();
    if (qualified) qualified->layout.set = s.set;
  }
  return place_declarations(out, options, diagnostics);
}

}  // namespace doublet::frontend
