// Small hand-written scanners for untrusted text. std::regex is not used on
// user input: libstdc++'s matcher recurses once per character, so a 4 MB line
// (a long comment, millions of blanks) overflows any stack. Everything here
// runs in time linear in its input and uses no recursion.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace doublet::frontend {

inline bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Drops leading blanks (space, tab, CR, FF, VT) of `s`; returns how many.
std::size_t skip_blanks(std::string_view& s);
// Drops the word `word` from the front of `s` when it is there as a whole word.
bool consume_word(std::string_view& s, std::string_view word);
// Drops and returns the leading identifier/number characters of `s` ("" when none).
std::string_view take_word(std::string_view& s);
// `s` without leading and trailing blanks.
std::string_view trim_blanks(std::string_view s);

// Where each line of a text starts, built once: line lookups cost O(1) instead
// of a rescan per diagnostic.
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  // Line `number` (1-based) without its '\n' (and '\r'); empty when out of range.
  std::string_view line(int number) const;
  // 1-based line holding byte `offset`.
  int line_of(std::size_t offset) const;
  int line_count() const { return static_cast<int>(starts_.size()); }

 private:
  std::string_view text_;
  std::vector<std::size_t> starts_;
};

// Column (1-based) of `token` as a whole word in `row`, or of the row's first
// non-blank character when absent.
int column_in_row(std::string_view row, std::string_view token);

}  // namespace doublet::frontend

namespace doublet::frontend {

// The preprocessor's view of a text, one logical line at a time: comments
// become a blank, backslash-newline joins lines. Linear, one buffer reused.
class LogicalLines {
 public:
  explicit LogicalLines(std::string_view text) : text_(text) {}
  // The next logical line in `out` (valid until the next call); false at the end.
  bool next(std::string_view& out);
  int line() const { return first_line_; }  // 1-based physical line where `out` began

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int physical_line_ = 1, first_line_ = 1;
  bool in_block_comment_ = false;
  std::string buffer_;
};

// A directive's name when `line` is one (`# define X` → "define", rest = " X"), else "".
std::string_view directive_name(std::string_view line, std::string_view& rest);

}  // namespace doublet::frontend
