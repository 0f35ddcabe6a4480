#include "support/big_stack.hpp"

#include <pthread.h>

#include <string_view>

namespace doublet {
namespace {
void* trampoline(void* arg) {
  (*static_cast<const std::function<void()>*>(arg))();
  return nullptr;
}
}  // namespace

bool run_with_big_stack(const std::function<void()>& work, std::size_t stack_bytes) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return false;
  pthread_t thread;
  bool started = pthread_attr_setstacksize(&attr, stack_bytes) == 0 &&
                 pthread_create(&thread, &attr, trampoline, const_cast<std::function<void()>*>(&work)) == 0;
  pthread_attr_destroy(&attr);
  if (started) pthread_join(thread, nullptr);
  return started;
}

std::size_t max_statement_operators(std::string_view source) {
  std::size_t best = 0, current = 0;
  for (std::size_t i = 0; i < source.size(); ++i) {
    char c = source[i];
    // Comments and preprocessor lines are not expressions.
    if (c == '/' && i + 1 < source.size() && source[i + 1] == '/') c = '#';
    if (c == '#') {
      i = source.find('\n', i);
      if (i == std::string_view::npos) break;
      continue;
    }
    if (c == '/' && i + 1 < source.size() && source[i + 1] == '*') {
      i = source.find("*/", i + 2);
      if (i == std::string_view::npos) break;
      ++i;
      continue;
    }
    switch (c) {
      case ';': case '{': case '}': current = 0; break;
      case '+': case '-': case '*': case '/': case '%': case '(': case '[': case '?': case '&': case '|':
      case '^': case '<': case '>': case '=': case '!': case ',': case '.':
        if (++current > best) best = current;
        break;
      default: break;
    }
  }
  return best;
}

std::string too_many_operators_message(std::size_t operators, bool after_macros) {
  return std::string("a statement with ") + std::to_string(operators) + " operators" +
         (after_macros ? " once its macros and #includes are expanded" : "") + " is nested too deeply for doublet (limit " +
         std::to_string(kMaxStatementOperators) + "); split it up";
}

}  // namespace doublet
