// Upper bounds on what glslang's preprocessor will make of a shader, computed
// before it runs. glslang expands macros eagerly and without limit, so a
// "billion laughs" chain (#define A1 A0 A0, #define A2 A1 A1, ...) or a
// function-like macro that repeats its argument, nested, would run for hours
// and exhaust memory, whether the macros sit in the shader, in an #included
// file or in a -D value.
//
// The bound is sound for object-like and function-like macros: every
// definition of a name counts (#if and #undef are ignored, so the bound may be
// high, never low), a macro inside its own expansion counts once (it is not
// re-expanded), and the arguments of a function-like macro count as many times
// as its body names a parameter. Token pasting (##) can make the name of any
// macro (CAT(B,26) -> B26), so a paste counts as the largest macro there is,
// and as repeating a following argument list as much as any macro does; a
// paste that makes the name of another pasting macro is followed
// kPasteRounds deep. Linear in the text and definitions; no recursion.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace doublet::frontend {

struct MacroOrigin {
  std::string file;
  int line = 0;
};

class MacroBudget {
 public:
  // Every #define in `text` (a shader or an included file).
  void add_definitions(std::string_view text, const std::string& file);
  // One -D NAME=VALUE.
  void add_definition(std::string_view name, std::string_view body, const MacroOrigin& origin);

  struct Weight {
    double spelled = 0;   // tokens as written
    double expanded = 0;  // upper bound after macro expansion
  };
  // The tokens glslang will see for `text` (its lines outside directives, and
  // #if/#elif conditions), each macro name weighed by what it expands to.
  // Meaningful once every definition is added.
  Weight weigh(std::string_view text);

  struct Largest {
    std::string name;  // empty when no macro is defined
    MacroOrigin origin;
    double tokens = 0;
  };
  Largest largest_macro();
  bool has_definitions() const { return !definitions_.empty(); }

 private:
  struct Item {
    enum Kind : std::uint8_t { Plain, Ident, Open, Close, Paste } kind;
    int value;  // Plain: how many tokens; Ident: interned name
  };
  struct Definition {
    bool function_like = false;
    std::vector<int> params;
    std::vector<Item> body;
    MacroOrigin origin;
  };
  enum class State : std::uint8_t { Unknown, InProgress, Done };
  class Weigher;

  int intern(std::string_view name);
  // Identifiers become Ident items; with `intern_names` false, only names some definition uses.
  void tokenize(std::string_view text, std::vector<Item>& out, bool intern_names);
  void size_tables();
  void define(std::string_view rest, const MacroOrigin& origin);
  bool is_macro(int id) const { return id < static_cast<int>(definitions_.size()) && !definitions_[id].empty(); }
  bool is_function_like(int id) const {
    return is_macro(id) && definitions_[id].back().function_like;
  }
  // Some definition of `id` pastes tokens (its expansion may end in any macro's name).
  bool pastes_in(int id) const { return id < static_cast<int>(pastes_.size()) && pastes_[id]; }
  void measure(int id);  // fills size_/repeat_ for `id` and everything it names
  void measure_definitions(int id);
  // Fixes paste_size_/paste_repeat_ once the definitions are known (see the header comment).
  void settle_pastes();
  // Marks each ## whose chain can name no macro (Paste value 0; see macro_budget.cpp).
  void mark_pastes();
  static constexpr int kPasteRounds = 8;

  struct NameHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::unordered_map<std::string, int, NameHash, std::equal_to<>> ids_;
  std::vector<std::string> names_;
  std::vector<std::vector<Definition>> definitions_;  // by id; empty: not a macro
  std::vector<State> state_;
  std::vector<double> size_;    // tokens one use expands to
  std::vector<double> repeat_;  // how often the body repeats an argument (function-like)
  std::vector<bool> pastes_;  // by id: some definition's body has ##
  bool has_paste_ = false, pastes_settled_ = false;
  double paste_size_ = 1, paste_repeat_ = 0;  // what one ## result may expand to
};

}  // namespace doublet::frontend
