// Line-level reduction of a failing program; see reduce.hpp.
#include "difftest/reduce.hpp"

#include <algorithm>
#include <chrono>
#include <regex>
#include <vector>

namespace doublet::difftest {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    lines.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

// The line that closes the block opened at `open` (a line ending in '{'), or `open` when none does.
size_t block_end(const std::vector<std::string>& lines, size_t open) {
  int depth = 0;
  for (size_t i = open; i < lines.size(); ++i) {
    for (char c : lines[i]) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (depth <= 0 && i > open) return i;
  }
  return open;
}

}  // namespace

bool keeps_loop_steps(const std::string& glsl) {
  static const std::regex loop(R"(while \((\w+) <)");
  for (std::sregex_iterator it(glsl.begin(), glsl.end(), loop), end; it != end; ++it)
    if (glsl.find((*it)[1].str() + "++") == std::string::npos) return false;
  return true;
}

Reduction reduce(const std::string& glsl, const std::string& spec_json, const std::string& stage, const std::string& oracle,
                 CheckOptions options,
                 double seconds, const std::function<void(const std::string&)>& progress) {
  if (oracle != "lowering") options.oracles = {oracle};
  Reduction r;
  std::vector<std::string> lines = split_lines(glsl);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  auto interesting = [&](const std::vector<std::string>& candidate) {
    if (std::chrono::steady_clock::now() > deadline && !r.finding.oracle.empty()) return false;
    const std::string text = join_lines(candidate);
    if (!keeps_loop_steps(text)) return false;
    ++r.checks;
    bool timed_out = false;
    const CheckResult c = check_in_child(text, spec_json, stage, options, 120, &timed_out);
    if (timed_out || !c.invalid.empty()) return false;
    for (const Finding& f : c.findings)
      if (f.oracle == oracle) {
        r.finding = f;
        return true;
      }
    return false;
  };
  // Whole blocks first (a function, a loop, an if with its body), outermost first.
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i].back() != '{') continue;
    const size_t end = block_end(lines, i);
    if (end == i) continue;
    std::vector<std::string> candidate(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(i));
    candidate.insert(candidate.end(), lines.begin() + static_cast<std::ptrdiff_t>(end) + 1, lines.end());
    if (interesting(candidate)) {
      lines = std::move(candidate);
      progress(std::to_string(lines.size()) + " lines");
      --i;  // the line now at i is new (unsigned wrap-around, undone by the loop's ++i)
    }
  }
  // Then ddmin over single lines: remove chunks of decreasing size while the finding stays.
  size_t chunks = 2;
  while (lines.size() >= 2) {
    const size_t size = (lines.size() + chunks - 1) / chunks;
    bool removed = false;
    for (size_t start = 0; start < lines.size(); start += size) {
      std::vector<std::string> candidate(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(start));
      candidate.insert(candidate.end(), lines.begin() + static_cast<std::ptrdiff_t>(std::min(lines.size(), start + size)),
                       lines.end());
      if (interesting(candidate)) {
        lines = std::move(candidate);
        progress(std::to_string(lines.size()) + " lines");
        chunks = std::max<size_t>(chunks - 1, 2);
        removed = true;
        break;
      }
    }
    if (removed) continue;
    if (chunks >= lines.size()) break;
    chunks = std::min(lines.size(), chunks * 2);
  }
  r.program = join_lines(lines);
  if (r.finding.oracle.empty()) interesting(lines);  // the original's finding, for the report
  return r;
}

}  // namespace doublet::difftest
