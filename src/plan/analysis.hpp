// Range and error analysis of `doublet plan` (docs/plan.md).
//
// Forward: interval propagation over the imported IR (per vector/matrix component; arrays and
// struct members as one hull), from the scene's input ranges and relations; loops are iterated
// to a fixpoint and widened to ±inf. Backward, once per scene output: the sensitivity of that
// output to an error injected at every expression node and every stored value (linearised with
// the intervals: z = x*y gives x the weight max|y|), summed over uses and call sites; inside a
// loop a nonzero weight becomes infinite (unknown trip count). A candidate plan (function
// arithmetic modes, declarations stored as float) then has an error estimate per output:
//   sum over nodes of weight × the node's rounding in its mode
//   + sum over stored values of weight × storage rounding (float: half an ulp of max|v|).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "ir/ir.hpp"
#include "plan/interval.hpp"
#include "plan/scene.hpp"

namespace doublet::plan {

using Box = std::vector<Interval>;  // one interval per component

// A candidate plan: arithmetic mode per function (absent: `base`), declarations stored as float.
// Mode exact is only ever a whole-shader base (it does not mix with other modes).
struct Candidate {
  Mode base = Mode::Df64;
  std::map<const ir::Function*, Mode> function_mode;
  std::set<const ir::Var*> fp32_vars;
  Mode mode_of(const ir::Function* f) const {
    auto it = function_mode.find(f);
    return it == function_mode.end() ? base : it->second;
  }
};

// A buffer member is read-only (an input) or write-only by its own qualifier or its block's.
inline bool is_readonly(const ir::Var* v) { return v->readonly || (v->block && v->block->readonly); }
inline bool is_writeonly(const ir::Var* v) { return v->writeonly || (v->block && v->block->writeonly); }

// Relative rounding of one double operation per mode (docs/plan.md, "Error model").
inline constexpr double kDf64Rel = 0x1p-44;      // >= every accurate rule's bound (15u^2 + 56u^3 for div)
inline constexpr double kDf64FastRel = 0x1p-40;  // assumed for df64-fast where no operand cancels
inline constexpr double kDf64Repr = 0x1p-48;     // a double input carried as hi + lo
inline constexpr double kExactRel = 0x1p-53;     // binary64, correctly rounded: half an ulp

class Analysis {
 public:
  // Runs both passes. False with diagnostics when the scene names something the shader lacks.
  bool run(const ir::Module& module, const Scene& scene, std::vector<Diagnostic>* diagnostics);

  Box range(const ir::Var* v) const;        // hull of every value v holds (per component)
  Box range(const ir::Expr* e) const;
  static Interval hull(const Box& b);

  // Estimated max absolute error on scene output `output` under `c` (inf: not bounded).
  double error_estimate(const std::string& output, const Candidate& c) const;
  // How much error injected at v (every value it stores) output `output` tolerates: requirement /
  // sensitivity; inf when the output does not depend on v.
  double budget(const std::string& output, const ir::Var* v) const;
  double sensitivity(const std::string& output, const ir::Var* v) const;
  // Double flops of function f's body, or of the assignments to v, under `c` (docs/rules.md).
  double flops(const Candidate& c, const ir::Function* only = nullptr) const;
  double flops_of(const ir::Var* v, const Candidate& c) const;
  // Whether f has a double add/sub whose operands may cancel (no df64-fast there).
  bool may_cancel(const ir::Function* f) const;

  const ir::Module& module() const { return *module_; }
  const std::vector<const ir::Var*>& double_vars() const { return double_vars_; }  // declared doubles
  const ir::Function* owner(const ir::Var* v) const;  // function of a local/parameter, else null
  const std::vector<std::string>& notes() const { return notes_; }
  const ir::Var* output_var(const std::string& name) const;

  struct Node;  // per-expression facts, analysis.cpp

 private:
  friend struct Forward;
  friend struct Backward;
  friend void forward_pass(Analysis&, const ir::Function*, std::map<const ir::Var*, Box>,
                           std::map<std::pair<const ir::Var*, const ir::Var*>, double>);
  friend void backward_pass(Analysis&, const std::string&, const ir::Function*);
  double rounding(const ir::Expr* e, const Node& n, const Candidate& c) const;
  double storage_error(const ir::Var* v, const Candidate& c) const;

  const ir::Module* module_ = nullptr;
  const Scene* scene_ = nullptr;
  std::map<const ir::Var*, Box> var_range_;
  std::map<const ir::Expr*, std::shared_ptr<Node>> nodes_;
  std::map<std::string, const ir::Var*> inputs_, outputs_;
  std::map<std::string, std::map<const ir::Expr*, double>> node_weight_;  // per output
  std::map<std::string, std::map<const ir::Var*, double>> store_weight_;  // per output
  std::map<const ir::Var*, std::vector<ir::ExprPtr>> defs_;  // values assigned to v
  std::map<const ir::Var*, const ir::Function*> owner_;
  std::vector<const ir::Var*> double_vars_;
  std::vector<std::string> notes_;
};

}  // namespace doublet::plan
