#include "frontend/mode_pragmas.hpp"

#include <string>

#include "frontend/text_scan.hpp"

namespace doublet::frontend {
namespace {

// `#pragma doublet<rest>` → rest and the column of '#'; false for any other line.
bool doublet_pragma(std::string_view line, std::string_view& rest, int& column) {
  std::string_view text = line;
  column = static_cast<int>(skip_blanks(text)) + 1;
  if (text.empty() || text.front() != '#') return false;
  text.remove_prefix(1);
  skip_blanks(text);
  if (!consume_word(text, "pragma") || skip_blanks(text) == 0 || !consume_word(text, "doublet")) return false;
  rest = text;
  return true;
}

// ` mode(NAME)` with an optional trailing // comment → NAME; false when malformed.
bool mode_argument(std::string_view rest, std::string_view& name) {
  if (skip_blanks(rest) == 0 || !consume_word(rest, "mode")) return false;
  skip_blanks(rest);
  if (rest.empty() || rest.front() != '(') return false;
  rest.remove_prefix(1);
  skip_blanks(rest);
  size_t end = 0;
  while (end < rest.size() && rest[end] != ')' && !is_blank(rest[end])) ++end;
  name = rest.substr(0, end);
  rest.remove_prefix(end);
  skip_blanks(rest);
  if (rest.empty() || rest.front() != ')') return false;
  rest.remove_prefix(1);
  skip_blanks(rest);
  return rest.empty() || rest.substr(0, 2) == "//";
}

}  // namespace

std::vector<ModePragma> scan_mode_pragmas(std::string_view source, const std::string& file_name,
                                          std::vector<Diagnostic>& diagnostics) {
  std::vector<ModePragma> pragmas;
  bool in_block_comment = false;
  int depth = 0;  // of { }
  int line_number = 0;
  std::vector<size_t> waiting;  // pragmas whose next code line is not known yet
  size_t start = 0;
  while (start <= source.size()) {
    size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    std::string line(source.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    // A directive inside a /* */ comment is no directive. Track block comments roughly: enough
    // for commented-out pragmas; a pragma never follows code on its own line.
    bool was_in_comment = in_block_comment;
    bool has_code = false;
    const bool directive = !was_in_comment && line.find_first_not_of(" \t") != std::string::npos &&
                           line[line.find_first_not_of(" \t")] == '#';
    for (size_t i = 0; i < line.size(); ++i) {
      if (!in_block_comment && line.compare(i, 2, "//") == 0) break;
      if (!in_block_comment && line.compare(i, 2, "/*") == 0) {
        in_block_comment = true, ++i;
      } else if (in_block_comment && line.compare(i, 2, "*/") == 0) {
        in_block_comment = false, ++i;
      } else if (!in_block_comment && !directive) {
        if (line[i] == '{') ++depth;
        if (line[i] == '}') --depth;
        has_code |= line[i] != ' ' && line[i] != '\t';
      }
    }
    if (has_code && !waiting.empty()) {
      // One copy of the line for all the pragmas before it (20,000 copies of a long line took 20 GB).
      auto text = std::make_shared<const std::string>(line);
      for (size_t k : waiting) {
        pragmas[k].next_line = line_number;
        pragmas[k].next_text = text;
      }
      waiting.clear();
    }
    if (was_in_comment) continue;
    std::string_view rest, name_text;
    int column = 0;
    if (!doublet_pragma(line, rest, column)) continue;
    if (!mode_argument(rest, name_text)) {
      diagnostics.push_back({file_name, line_number, column, Severity::Error,
                             "malformed '#pragma doublet': expected '#pragma doublet mode(MODE)' with MODE one of "
                             "fp32, rte, df64-fast, df64, native"});
      continue;
    }
    const std::string name(name_text);
    std::optional<Mode> parsed = parse_mode(name);
    if (!parsed) {
      int name_column = static_cast<int>(line.find(name, line.find("mode"))) + 1;
      diagnostics.push_back({file_name, line_number, name_column, Severity::Error,
                             "unknown mode '" + name + "' in '#pragma doublet mode': expected fp32, rte, df64-fast, "
                             "df64 or native"});
      continue;
    }
    ModePragma pragma;
    pragma.line = line_number;
    pragma.column = column;
    pragma.mode = *parsed;
    pragma.top_level = depth <= 0;
    waiting.push_back(pragmas.size());
    pragmas.push_back(pragma);
  }
  return pragmas;
}

}  // namespace doublet::frontend
