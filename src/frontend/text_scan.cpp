#include "frontend/text_scan.hpp"

#include <algorithm>

namespace doublet::frontend {

std::size_t skip_blanks(std::string_view& s) {
  std::size_t n = 0;
  while (n < s.size() && is_blank(s[n])) ++n;
  s.remove_prefix(n);
  return n;
}

bool consume_word(std::string_view& s, std::string_view word) {
  if (s.substr(0, word.size()) != word) return false;
  if (s.size() > word.size() && is_word_char(s[word.size()])) return false;
  s.remove_prefix(word.size());
  return true;
}

std::string_view take_word(std::string_view& s) {
  std::size_t n = 0;
  while (n < s.size() && is_word_char(s[n])) ++n;
  std::string_view word = s.substr(0, n);
  s.remove_prefix(n);
  return word;
}

std::string_view trim_blanks(std::string_view s) {
  skip_blanks(s);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

LineIndex::LineIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  for (std::size_t i = text.find('\n'); i != std::string_view::npos; i = text.find('\n', i + 1))
    starts_.push_back(i + 1);
}

std::string_view LineIndex::line(int number) const {
  if (number < 1 || number > line_count()) return {};
  const std::size_t start = starts_[static_cast<std::size_t>(number - 1)];
  std::size_t end = number < line_count() ? starts_[static_cast<std::size_t>(number)] - 1 : text_.size();
  if (end > start && text_[end - 1] == '\r') --end;
  return text_.substr(start, end - start);
}

int LineIndex::line_of(std::size_t offset) const {
  return static_cast<int>(std::upper_bound(starts_.begin(), starts_.end(), offset) - starts_.begin());
}

int column_in_row(std::string_view row, std::string_view token) {
  if (!token.empty()) {
    for (std::size_t pos = row.find(token); pos != std::string_view::npos; pos = row.find(token, pos + 1)) {
      const bool left_ok = pos == 0 || !is_word_char(row[pos - 1]) || !is_word_char(token.front());
      const std::size_t after = pos + token.size();
      const bool right_ok = after >= row.size() || !is_word_char(row[after]) || !is_word_char(token.back());
      if (left_ok && right_ok) return static_cast<int>(pos) + 1;
    }
  }
  std::string_view rest = row;
  const std::size_t blanks = skip_blanks(rest);
  return rest.empty() ? 1 : static_cast<int>(blanks) + 1;
}

}  // namespace doublet::frontend

namespace doublet::frontend {

bool LogicalLines::next(std::string_view& out) {
  if (pos_ >= text_.size()) return false;
  buffer_.clear();
  first_line_ = physical_line_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    const char after = pos_ + 1 < text_.size() ? text_[pos_ + 1] : '\0';
    if (in_block_comment_) {
      if (c == '*' && after == '/') {
        in_block_comment_ = false;
        pos_ += 2;
        continue;
      }
      if (c == '\n') ++physical_line_;  // a block comment spans lines inside one logical line
      ++pos_;
      continue;
    }
    if (c == '\n') {
      ++pos_;
      ++physical_line_;
      break;
    }
    if (c == '\\' && (after == '\n' || (after == '\r' && pos_ + 2 < text_.size() && text_[pos_ + 2] == '\n'))) {
      pos_ += after == '\n' ? 2 : 3;
      ++physical_line_;
      continue;
    }
    if (c == '/' && after == '/') {
      const std::size_t end = text_.find('\n', pos_);
      pos_ = end == std::string_view::npos ? text_.size() : end;  // a continuation inside: glslang ends it here too
      continue;
    }
    if (c == '/' && after == '*') {
      in_block_comment_ = true;
      buffer_ += ' ';
      pos_ += 2;
      continue;
    }
    buffer_ += c;
    ++pos_;
  }
  out = buffer_;
  return true;
}

std::string_view directive_name(std::string_view line, std::string_view& rest) {
  skip_blanks(line);
  if (line.empty() || line.front() != '#') return {};
  line.remove_prefix(1);
  skip_blanks(line);
  std::string_view name = take_word(line);
  rest = line;
  return name.empty() ? std::string_view("#") : name;
}

}  // namespace doublet::frontend
