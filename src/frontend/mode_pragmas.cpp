#include "frontend/mode_pragmas.hpp"

#include <regex>
#include <string>

namespace doublet::frontend {

std::vector<ModePragma> scan_mode_pragmas(std::string_view source, const std::string& file_name,
                                          std::vector<Diagnostic>& diagnostics) {
  std::vector<ModePragma> pragmas;
  static const std::regex pragma_re(R"(^([ \t]*)#[ \t]*pragma[ \t]+doublet\b(.*)$)");
  static const std::regex mode_re(R"(^[ \t]+mode[ \t]*\([ \t]*([^) \t]*)[ \t]*\)[ \t]*(//.*)?$)");
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
    if (has_code) {
      for (size_t k : waiting) {
        pragmas[k].next_line = line_number;
        pragmas[k].next_text = line;
      }
      waiting.clear();
    }
    if (was_in_comment) continue;
    std::smatch m;
    if (!std::regex_match(line, m, pragma_re)) continue;
    int column = static_cast<int>(m[1].length()) + 1;
    std::string rest = m[2].str();
    std::smatch mode;
    if (!std::regex_match(rest, mode, mode_re)) {
      diagnostics.push_back({file_name, line_number, column, Severity::Error,
                             "malformed '#pragma doublet': expected '#pragma doublet mode(MODE)' with MODE one of "
                             "fp32, rte, df64-fast, df64, native"});
      continue;
    }
    std::string name = mode[1].str();
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
