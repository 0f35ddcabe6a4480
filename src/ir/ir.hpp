// doublet's own small GLSL IR. The front end imports glslang's typed AST into
// it; the lowering passes rewrite it; the printer turns it back into text.
// Keeping glslang types out of the passes means glslang's unstable AST headers
// are confined to src/frontend/.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"

namespace doublet::ir {

struct Loc {
  int line = 0;
  int column = 0;
  // The #include'd file the place is in (its resolved name); null: the main source.
  std::shared_ptr<const std::string> file;
};

// The file a diagnostic at `loc` names: the included file, else the main source's name.
inline const std::string& file_of(const Loc& loc, const std::string& main_file) {
  return loc.file ? *loc.file : main_file;
}

// Int64/Uint64: GL_ARB_gpu_shader_int64's int64_t/uint64_t, carried on desktop 4.x targets.
enum class Base { Void, Bool, Int, Uint, Float, Double, Struct, Block, Opaque, Int64, Uint64 };

struct Type;
struct Field;

struct Type {
  Base base = Base::Void;
  int vec = 1;                   // vector size (1 = scalar); for matrices: rows
  int cols = 0;                  // matrix columns; 0 = not a matrix
  std::vector<int> array_dims;   // outermost first; 0 = unsized
  std::string name;              // struct/block/opaque (sampler2D) type name
  std::shared_ptr<std::vector<Field>> fields;  // struct/block members

  bool is_array() const { return !array_dims.empty(); }
  bool is_matrix() const { return cols > 0; }
  bool is_double() const { return base == Base::Double; }
  // True when this type or any member/element holds doubles.
  bool contains_double() const;
  Type element() const;  // type with the outermost array dimension removed
  Type with_base(Base b) const;
};

struct Layout {
  int location = -1;
  int binding = -1;
  int set = -1;
  int offset = -1;
  std::string packing;  // "std140", "std430", "shared", "packed" or empty
  std::string matrix;   // "row_major", "column_major" or empty
  std::string format;   // image format ("rgba32f"), or empty
  bool passthrough = false;  // GL_NV_geometry_shader_passthrough
};

enum class Interp { Default, Smooth, Flat, NoPerspective, Centroid };

struct Field {
  std::string name;
  Type type;
  Layout layout;
  Interp interp = Interp::Default;  // members of in/out blocks
};

enum class Storage {
  Local,     // function-local temporary
  Global,    // private global
  Const,     // compile-time constant (only survives for arrays/structs)
  In,        // stage input (attribute / varying in)
  Out,       // stage output
  Uniform,
  Buffer,    // storage block
  Shared,    // compute shared
  ParamIn,
  ParamOut,
  ParamInOut,
  BuiltIn,   // gl_* variables; printed by name, never declared
};

// A function's own variable (a local or a parameter): what no other function can reach but through
// an out parameter, and what a WGSL pointer argument may point to (function memory).
// A parameter the callee writes (out or inout): its argument must be an lvalue.
inline bool is_out_parameter(Storage s) { return s == Storage::ParamOut || s == Storage::ParamInOut; }

inline bool is_function_local(Storage s) {
  return s == Storage::Local || s == Storage::ParamIn || s == Storage::ParamOut || s == Storage::ParamInOut;
}

struct Var {
  int id = 0;
  std::string name;
  Type type;           // current type (lowered once the passes have run)
  Type declared_type;  // the type the user wrote
  Storage storage = Storage::Local;
  Layout layout;
  Interp interp = Interp::Default;
  bool invariant = false;
  bool patch = false;  // a tessellation per-patch in/out
  bool precise = false;
  bool readonly = false, writeonly = false, coherent = false, restrict_ = false, volatile_ = false;
  std::shared_ptr<Var> block;  // for members of an anonymous block: the block
  Loc loc;
};
using VarPtr = std::shared_ptr<Var>;

struct Expr;
using ExprPtr = std::shared_ptr<Expr>;

// One scalar of a constant. Doubles are kept exactly; floats are rounded to
// float on import so the lowering sees what the driver would.
struct Scalar {
  Base base = Base::Float;
  double d = 0;        // Float, Double
  long long i = 0;     // Int, Uint, Int64, Uint64 (a uint64 value's bits)
  bool b = false;      // Bool
};

struct Expr {
  enum class Kind {
    Sym,        // var
    Const,      // values (type.vec scalars, or flattened for arrays)
    Unary,      // op: "-", "!", "~", "++x", "--x", "x++", "x--"
    Binary,     // op: arithmetic, comparison, logical, bitwise, assignment ("=", "+=", ...)
    Ternary,    // args: cond, then, else
    Call,       // user function: name
    Builtin,    // GLSL builtin function: name
    Construct,  // type constructor: type
    Member,     // args[0].name: struct field or swizzle
    Index,      // args[0][args[1]]
    Comma,      // args joined by ','
  };
  Kind kind;
  Type type;
  Loc loc;
  std::string op;    // Unary/Binary
  std::string name;  // Call/Builtin/Member
  VarPtr var;        // Sym
  std::vector<Scalar> values;  // Const
  std::vector<ExprPtr> args;

  static ExprPtr make(Kind k, Type t, Loc l = {}) {
    auto e = std::make_shared<Expr>();
    e->kind = k;
    e->type = std::move(t);
    e->loc = l;
    return e;
  }
};

// A node of kind `k` (Call, Builtin, Construct, ...) named `name` over `args`.
ExprPtr make_node(Expr::Kind k, const std::string& name, Type type, std::vector<ExprPtr> args, Loc loc);
// True for an access with no side effects: a variable, a constant, members and indices of those.
bool is_pure(const ExprPtr& e);
// `a.length()` of an array (the importer's "length" built-in on an array; glslang folds sized ones,
// so in practice a runtime-sized buffer array): an int, whatever the elements are lowered to.
bool is_array_length(const Expr& e);
// True when evaluating `e` changes state: an assignment, ++/--, a call of a user function (it may
// write globals or out parameters), a built-in with out parameters or memory effects (modf,
// atomicAdd, imageStore, barrier, ...). Such an expression must be evaluated exactly once.
bool has_side_effects(const ExprPtr& e);
// The built-in itself writes an out parameter or memory, or synchronises (modf, atomicAdd, barrier, ...).
bool builtin_has_side_effects(const std::string& name);
// The variable an access reads or writes through members and indices (`v` of `v.a[i].xy`); null
// when it is not rooted in a variable (a call's result, a constructor).
Var* root_variable(ExprPtr e);
// A deep copy of an expression tree (the variables it names are shared, not copied).
ExprPtr clone(const ExprPtr& e);
// "+=", "-=", "*=", "/=".
bool is_compound_arithmetic(const std::string& op);
// "=", "+=", "<<=", ...: every operator ending in '=' except the comparisons.
bool is_assignment_operator(const std::string& op);
// ++x, --x, x++, x--.
bool is_increment(const Expr& e);
// modf(x, out whole) and frexp(x, out exponent): the built-ins that write their second argument.
bool builtin_writes_second_argument(const Expr& e);
// How many of e's first operands are evaluated whenever e is: 1 for &&, || and ?: (the others
// only sometimes), all of them otherwise.
size_t unconditional_operands(const Expr& e);

struct Stmt;
using StmtPtr = std::shared_ptr<Stmt>;

struct Stmt {
  enum class Kind {
    Expr,      // expr;
    Decl,      // var [= expr];
    Block,     // { body }
    If,        // if (expr) body[0] [else body[1]]
    Loop,      // for/while/do: init (body[0] may be null), expr = cond, step, body[1]
    Switch,    // switch (expr) body[0] (a Block with Case/Default labels)
    Case,      // case expr:
    Default,
    Break,
    Continue,
    Return,    // [expr]
    Discard,
  };
  Kind kind;
  Loc loc;
  ExprPtr expr;
  VarPtr var;                 // Decl
  ExprPtr step;               // Loop
  bool test_first = true;     // Loop: false = do-while
  std::vector<StmtPtr> body;  // Block contents; If: then/else; Loop: init, body

  static StmtPtr make(Kind k, Loc l = {}) {
    auto s = std::make_shared<Stmt>();
    s->kind = k;
    s->loc = l;
    return s;
  }
};

struct Function {
  std::string name;
  Type return_type;
  std::vector<VarPtr> params;
  StmtPtr body;  // a Block
  Loc loc;
};
using FunctionPtr = std::shared_ptr<Function>;

using StageKind = doublet::Stage;  // the public enum, one name for the IR

struct Module {
  StageKind stage = StageKind::Vertex;
  int source_version = 0;        // the user's #version number
  bool source_es = false;
  std::vector<Type> structs;     // user struct types, in declaration order
  std::vector<VarPtr> globals;   // in declaration order, with initialisers in `global_inits`
  std::vector<ExprPtr> global_inits;  // parallel to globals; null when none
  std::vector<FunctionPtr> functions;
  int local_size[3] = {0, 0, 0};  // compute: 0 = not declared
  // Geometry and tessellation: the stage's layout declarations as printed, in order
  // ("layout(triangles, invocations = 2) in;", "layout(triangle_strip, max_vertices = 3) out;").
  std::vector<std::string> stage_layouts;
  bool early_fragment_tests = false;
};

// `name` + `suffix` for a generated identifier, with the underscores where they meet merged into
// one (scale_ + _hi = scale_hi): GLSL reserves every identifier that contains "__", and GLSL ES
// compilers reject them.
std::string join_identifier(const std::string& name, const std::string& suffix);

// Spelling of a type in GLSL (no array suffix).
std::string type_name(const Type& t);
// "[3][2]" etc.
std::string array_suffix(const Type& t);
Type scalar_type(Base b, int vec = 1);

// Nodes the passes build. A reference to `v` (at `loc`; without it, where `v` is declared).
ExprPtr make_sym(const VarPtr& v, Loc loc);
ExprPtr make_sym(const VarPtr& v);
// `a op b` of type `type`, at a's location.
ExprPtr make_binary(const std::string& op, Type type, ExprPtr a, ExprPtr b);
// `target = value`: the target's type, at the value's location.
ExprPtr make_assign(const ExprPtr& target, const ExprPtr& value);
// An int constant.
ExprPtr make_int(int value, Loc loc = {});
// `array[k]`, of the array's element type.
ExprPtr make_index(const ExprPtr& array, int k);
// The statement `e;`, at e's location.
StmtPtr make_statement(const ExprPtr& e);
// The functions of `m` named as `call` is, with as many parameters, whose every parameter
// `param_matches(parameter, argument)`: the overloads the call may resolve to. The caller chooses
// the type rule (declared types before lowering, lowered ones after).
std::vector<const Function*> overloads(const Module& m, const Expr& call,
                                       const std::function<bool(const Var& param, const Expr& arg)>& param_matches);

}  // namespace doublet::ir
