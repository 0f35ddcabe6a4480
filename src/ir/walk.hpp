// Generic traversals over the IR.
#pragma once

#include <functional>

#include "ir/ir.hpp"

namespace doublet::ir {

using ExprVisitor = std::function<void(const ExprPtr&)>;
// Pre-order over an expression tree.
void visit(const ExprPtr& e, const ExprVisitor& f);
// Every expression of a statement tree (conditions, steps, initialisers).
void visit(const StmtPtr& s, const ExprVisitor& f);

// Pre-order over a statement tree: every statement, nested ones included (null ones skipped).
void visit_statements(const StmtPtr& s, const std::function<void(const StmtPtr&)>& f);

// Post-order rewrite: children first, then `f` may return a replacement.
using ExprRewriter = std::function<ExprPtr(const ExprPtr&)>;
ExprPtr rewrite(const ExprPtr& e, const ExprRewriter& f);
void rewrite(const StmtPtr& s, const ExprRewriter& f);

// Number of references to `v` under a statement / expression.
int count_uses(const StmtPtr& s, const Var* v);
int count_uses(const ExprPtr& e, const Var* v);

}  // namespace doublet::ir
