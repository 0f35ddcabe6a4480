// Runs a function on a thread with a large stack. glslang's parser and tree
// traversals recurse once per operator of an expression, so a long chain such
// as `u+u+...+u` overflows an 8 MiB stack at about 37,000 terms; a crash is not
// an acceptable answer to bad input. The stack is reserved, not committed:
// only the depth actually used costs memory.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace doublet {

inline constexpr std::size_t kLowerStackBytes = std::size_t{1} << 30;  // 1 GiB reserved

// Returns false when no such thread could be started (then `work` did not run).
bool run_with_big_stack(const std::function<void()>& work, std::size_t stack_bytes = kLowerStackBytes);

// Upper bound of expression nesting in `source`: the most operator and
// bracket tokens between two statement boundaries (; { }). Cheap and
// conservative; used to refuse inputs no stack could parse.
std::size_t max_statement_operators(std::string_view source);

// Deeper expressions than this are refused before glslang sees them: even
// the 1 GiB stack would not hold glslang's recursion much beyond it.
inline constexpr std::size_t kMaxStatementOperators = 200000;

// The refusal of a statement with `operators` operators (`after_macros`: counted
// in the text after macro expansion and #include).
std::string too_many_operators_message(std::size_t operators, bool after_macros);

}  // namespace doublet
