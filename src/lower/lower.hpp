// Lowering passes over the IR. Each has one job:
//   lower_doubles     every double value becomes a df_* struct (hi + lo), every
//                     operation on one a call into the float-float runtime;
//   split_interfaces  a double in/out/uniform X becomes X_hi + X_lo of the
//                     same-shaped float type, joined/split at main's edges;
//   check_target      what the target language lacks (ES 1.00: uint, bit operators,
//                     switch, array constructors, non-float varyings) is diagnosed.
// Double matrices: matrix_helpers.hpp; block layouts for the manifest: block_layout.hpp.
#pragma once

#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"
#include "pipeline/config.hpp"
#include "rules/rule_library.hpp"

namespace doublet::passes {

// A function the lowering generates (compound assignments, matrix operations, exact block access):
// its GLSL, with at most one expression left as IR for the runtime linker to spell in the target's
// syntax (`head` + expression + `tail`); printed before the user's code in request order.
struct Helper {
  std::string head;
  ir::ExprPtr expression;  // null: `head` is the whole definition
  std::string tail;
};

struct Context {
  const pipeline::Config& config;
  std::vector<Diagnostic>& diagnostics;
  std::string_view source;  // the main shader text as given (to read a literal's spelling at a Loc)
  std::vector<rules::RuleRef> rules_used;        // runtime functions called
  std::map<std::string, ir::Loc> rule_first_use; // where each rule is first called (for diagnostics)
  std::vector<std::string> helper_order;         // generated helpers, in dependency order
  std::map<std::string, Helper> helpers;         // name → definition
  std::vector<int> widths_used;                  // df struct widths referenced
  std::vector<std::pair<int, int>> matrices_used;  // df_dmatCxR structs referenced: {cols, rows}
  bool failed = false;
  // Precision modes (apply_modes): functions, and global initialisers, whose double arithmetic
  // uses the cheaper df64-fast rules (rules/fast.glsl) instead of the accurate ones.
  std::set<const ir::Function*> fast_functions;
  bool fast_global_inits = false;
  // Functions whose mode is exact in a float-float shader (lower/exact_functions.cpp).
  std::set<const ir::Function*> exact_functions;
  // flatten_io_blocks: each variable made from an in/out block's member → the block's name.
  std::map<const ir::Var*, std::string> flattened_blocks;
  // exact_block_words: each block's members as the manifest lists them, and the GLSL of the
  // load/store helpers over user struct types (printed after those types).
  std::map<const ir::Var*, std::vector<BlockMember>> exact_block_members;
  std::string struct_helpers;
  std::set<const ir::Var*> exact_struct_uniforms;  // loose uniforms of a STRUCT_words twin type
  // uniform_defaults: each uniform declared with an initializer → its value (Manifest's
  // default_value); split_interfaces initialises X_hi and X_lo from it where the target keeps it.
  std::map<const ir::Var*, std::vector<double>> uniform_defaults;

  // Code outside the rules reads the guard uniform: a float-float constant (guard_constants) or a
  // double uniform's words (split_interfaces, Config::reads_uniforms_through_guard). The linker
  // declares it where no rule does.
  bool guard_read_outside_rules = false;

  // #extension lines the generated helpers need beyond the shader's own (subgroup reductions).
  std::set<std::string> extensions;

  void error(ir::Loc loc, const std::string& message);
  void warning(ir::Loc loc, const std::string& message);
  void use_rule(const std::string& name, int width);
  void use_width(int width);
  void use_matrix(int cols, int rows);
  // Adds a generated helper once; `definition` is its full GLSL text.
  void add_helper(const std::string& name, const std::string& definition);
  // Adds a generated helper whose body holds `expression`, spelled by the runtime linker.
  void add_helper(const std::string& name, const std::string& head, const ir::ExprPtr& expression,
                  const std::string& tail);
  // Whether a call of doublet's runtime (df_/ex_) may write its arguments: a generated helper
  // declared with an out/inout parameter (df_assign_* for swizzle and column assignments, ...), or
  // the rules with one (frexp's exponent, modf's whole part: rules/common.glsl, rules/exact.glsl).
  bool runtime_call_writes_arguments(const ir::Expr& call) const;
  // The storage of each parameter of such a call (ParamIn, ParamOut or ParamInOut, from the
  // helper's head or the rule's signature); empty for a call of neither.
  std::vector<ir::Storage> runtime_parameters(const ir::Expr& call) const;
};

// A call of doublet's runtime: a rule or a generated helper (the df_/ex_ prefixes are reserved).
bool is_runtime_call(const ir::Expr& e);

// For passes that rewrite each function's body and need temporaries: `rewrite` runs on every
// function's body with an empty list; the declarations it appended (declare_temporary) go to the
// top of that function.
void rewrite_functions_with_temporaries(ir::Module& module, std::vector<ir::StmtPtr>& declarations,
                                        const std::function<void(const ir::StmtPtr& body)>& rewrite);
// A statement whose expression is evaluated once, before anything else of it: an expression
// statement, a declaration's initialiser, a return's value, an if's or a switch's condition (what
// hoist-commas and wgsl-expression-effects may move statements before).
bool has_leading_expression(const ir::StmtPtr& s);
// A local named `name`, uninitialised, its declaration appended to `declarations`.
ir::VarPtr declare_temporary(const std::string& name, const ir::Type& type, ir::Loc loc,
                             std::vector<ir::StmtPtr>& declarations);

// Name of the float-float struct for a vector width: df_double, df_dvec2...
std::string df_type_name(int width);
ir::Type df_type(int width);
bool is_df(const ir::Type& t);  // a df_double/df_dvecN struct (not an array of them, not a matrix)
int df_width(const ir::Type& t);
// df_splat_dvecN(s): the df_double `scalar` in every component of a width-`width` float-float
// vector (the scalar itself for width 1); the helper is generated once.
ir::ExprPtr df_splat(Context& context, const ir::ExprPtr& scalar, int width);
// The components `letters` of a float-float vector `base` without side effects, as a df value:
// `df_dvecN(base.hi.xy, base.lo.xy)` (uint words where the representation is binary64 words).
ir::ExprPtr df_select_pure(const Context& context, const ir::ExprPtr& base, const std::string& letters, ir::Loc loc);

// A component of a double vector or matrix passed to an out/inout parameter goes through a
// temporary (after lowering it is no longer an lvalue); runs before lower_doubles.
bool out_argument_temporaries(ir::Module& module, Context& context);
// The same for --target wgsl, after lowering: out/inout arguments that are not whole local variables.
bool wgsl_out_argument_temporaries(ir::Module& module, Context& context);
bool lower_doubles(ir::Module& module, Context& context);
// Uniform initializers: recorded for the manifest; kept in the text where the target has them
// (desktop), dropped with one warning where it has not (ES, WGSL, and mode exact's words).
bool uniform_defaults(ir::Module& module, Context& context);
// In/out blocks become plain in/out variables (BLOCK_MEMBER) on targets without I/O blocks.
bool flatten_io_blocks(ir::Module& module, Context& context);
// Global initialisers that are not constant expressions become assignments at the top of main.
bool move_global_initialisers(ir::Module& module, Context& context);
// Where the guard is a uniform (guards_constants), every float-float constant in a function body
// (is_float_float_constant: a df_* pair constructed from two float constants) reads the guard.
bool guards_constants(const pipeline::Config& config);
// The guard's value as the rules read it: `df_guard[int(df_guard[1])]` where
// Config::guard_is_indexed(), else `df_guard`; and `word - G`.
ir::ExprPtr guard_value(const pipeline::Config& config, ir::Loc loc);
ir::ExprPtr less_guard(const ir::ExprPtr& word, const pipeline::Config& config);
// A df_* pair or df_dmat* value (not an array of them).
bool is_float_float_value(const ir::Type& t);
bool is_float_float_constant(const ir::ExprPtr& e);
bool guard_constants(ir::Module& module, Context& context);
// Where no rule reads the guard (Config::reads_uniforms_through_guard), every float-float value read
// from a uniform block or a struct uniform reads it: `T(e.hi - G, e.lo - G)` (loose double uniforms:
// split_interfaces, at their join).
bool guard_uniform_reads(ir::Module& module, Context& context);
// GLSL ES 3.00+ and WGSL: several fragment outputs each need a location; the missing ones are given
// in declaration order, with a warning.
bool assign_fragment_output_locations(ir::Module& module, Context& context);
bool split_interfaces(ir::Module& module, Context& context, Manifest& manifest);
// WGSL: every vertex/fragment input and output without a location gets the first free one in
// declaration order (after split-interfaces); the manifest records every one's locations.
bool assign_wgsl_io_locations(ir::Module& module, Manifest& manifest);
// Mode exact: uniform, storage and in/out blocks hold each double as its binary64 words (low word
// first) at the original block's offsets; accesses load and store through helpers (exact_blocks.cpp).
bool exact_block_words(ir::Module& module, Context& context);
// GLSL ES forbids overloading built-in names: user functions named like one are renamed (NAME_user).
bool rename_functions_named_like_builtins(ir::Module& module, Context& context);
// Ternaries on structs become selections through a temporary: all of them on webgl2 (WebGL forbids
// them), those reading a uniform or buffer block elsewhere (glslang 12 miscompiles those).
bool select_structs(ir::Module& module, Context& context);
// hoist_commas.cpp (--target wgsl): a comma inside an expression becomes statements before it, where
// that cannot change what the statement computes.
bool hoist_commas(ir::Module& module, Context& context);
// Whether `evaluated` (parts of `statement`'s expression, `part` the subexpression holding them) may
// be evaluated before the statement instead of where `part` stands: the conditions of
// hoist_commas.cpp, against what the statement evaluates before `part`.
bool can_move_before(const ir::StmtPtr& statement, const ir::ExprPtr& part, const std::vector<ir::ExprPtr>& evaluated,
                     const Context& ctx);
// wgsl_expression_effects.cpp (--target wgsl): an increment or assignment inside an expression
// (`r[n++] = x`) becomes a comma over a temporary, then hoist-commas moves it before its statement.
bool wgsl_expression_effects(ir::Module& module, Context& context);
// Mode exact: the calls of one operation in a run of straight-line statements share one call site
// (a loop over the run), so drivers inline each operation once (share_exact_calls.cpp).
bool share_exact_calls(ir::Module& module, Context& context);
// Diagnoses, by construct and target, what the lowered shader needs but the target lacks.
bool check_target(const ir::Module& module, Context& context);

}  // namespace doublet::passes
