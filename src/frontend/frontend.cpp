#include "frontend/frontend.hpp"
#include "frontend/read_limited.hpp"

#include "support/big_stack.hpp"
#include "frontend/macro_budget.hpp"
#include "frontend/text_scan.hpp"
#include "frontend/transcendentals.hpp"

#include <glslang/Include/ResourceLimits.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "frontend/glslang_stage.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <functional>
#include <mutex>
#include <set>
#include <sstream>

namespace doublet::frontend {

ParsedShader::ParsedShader() = default;
ParsedShader::ParsedShader(ParsedShader&&) noexcept = default;
ParsedShader::~ParsedShader() = default;
void ParsedShader::release_ast() {
  intermediate = nullptr;
  shader.reset();
}

void ensure_glslang_initialized() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

namespace {

// Digits as an int, saturating (a 30-digit #version or line number must not throw).
int saturating_number(std::string_view digits) {
  long long value = 0;
  for (char c : digits) value = std::min<long long>(value * 10 + (c - '0'), 999999999);
  return static_cast<int>(value);
}

std::string_view take_digits(std::string_view& s) {
  size_t n = 0;
  while (n < s.size() && is_digit(s[n])) ++n;
  std::string_view digits = s.substr(0, n);
  s.remove_prefix(n);
  return digits;
}

// `#version N [profile]` (the directive's grammar in the GLSL specs) fills `info`.
void read_version_directive(std::string_view line, SourceInfo& info) {
  std::string_view rest;
  if (directive_name(line, rest) != "version" || skip_blanks(rest) == 0) return;
  std::string_view digits = take_digits(rest);
  if (digits.empty()) return;
  info.version = saturating_number(digits);
  skip_blanks(rest);
  info.es = take_word(rest) == "es" || info.version == 100;
}

}  // namespace

const TBuiltInResource& resource_limits() {
  static const TBuiltInResource limits = [] {
    TBuiltInResource r = *GetDefaultResources();
    constexpr int kAtomicCounterBindings = 8;
    r.maxAtomicCounterBindings = kAtomicCounterBindings;
    r.maxCombinedAtomicCounterBuffers = kAtomicCounterBindings;
    r.maxVertexAtomicCounterBuffers = kAtomicCounterBindings;
    r.maxFragmentAtomicCounterBuffers = kAtomicCounterBindings;
    r.maxComputeAtomicCounterBuffers = kAtomicCounterBindings;
    return r;
  }();
  return limits;
}

SourceInfo scan_version(std::string_view source) {
  SourceInfo info;
  bool in_comment = false;
  while (!source.empty()) {
    const size_t newline = source.find('\n');
    std::string_view rest = source.substr(0, newline);
    source.remove_prefix(newline == std::string_view::npos ? source.size() : newline + 1);
    // Skip blank lines and comments before the directive.
    while (!rest.empty()) {
      if (in_comment) {
        const size_t end = rest.find("*/");
        if (end == std::string_view::npos) { rest = {}; break; }
        rest.remove_prefix(end + 2);
        in_comment = false;
        continue;
      }
      skip_blanks(rest);
      if (rest.substr(0, 2) == "//") { rest = {}; break; }
      if (rest.substr(0, 2) == "/*") { in_comment = true; rest.remove_prefix(2); continue; }
      break;
    }
    if (rest.empty()) continue;
    read_version_directive(rest, info);
    return info;
  }
  return info;
}

namespace {

// One line of glslang's info log: "ERROR: <file>:<line>: <message>".
struct LogLine {
  Severity severity = Severity::Error;
  std::string_view file, message;
  int line = 0;
};

bool parse_log_line(std::string_view text, LogLine& out) {
  if (text.substr(0, 7) == "ERROR: ") out.severity = Severity::Error, text.remove_prefix(7);
  else if (text.substr(0, 9) == "WARNING: ") out.severity = Severity::Warning, text.remove_prefix(9);
  else return false;
  // The file name is the shortest prefix followed by ":<digits>: " (names may hold ':').
  for (size_t colon = text.find(':'); colon != std::string_view::npos; colon = text.find(':', colon + 1)) {
    std::string_view after = text.substr(colon + 1);
    std::string_view digits = take_digits(after);
    if (digits.empty() || after.substr(0, 2) != ": ") continue;
    out.file = text.substr(0, colon);
    out.line = saturating_number(digits);
    out.message = after.substr(2);
    return true;
  }
  return false;
}

// glslang's "'token' : message" → the token, the message after ':'; false when not that shape.
bool split_quoted_token(std::string_view message, std::string_view& token, std::string_view& rest) {
  skip_blanks(message);
  if (message.empty() || message.front() != '\'') return false;
  const size_t close = message.find('\'', 1);
  if (close == std::string_view::npos) return false;
  std::string_view after = message.substr(close + 1);
  skip_blanks(after);
  if (after.empty() || after.front() != ':') return false;
  token = message.substr(1, close - 1);
  rest = trim_blanks(after.substr(1));
  return true;
}

}  // namespace

void append_glslang_log(std::string_view log, const std::string& main_name,
                        const std::vector<std::pair<std::string, std::string>>& files,
                        std::vector<Diagnostic>& out) {
  std::map<std::string, LineIndex, std::less<>> indexes;  // per file, built on its first diagnostic
  while (!log.empty()) {
    const size_t newline = log.find('\n');
    std::string_view text = log.substr(0, newline);
    log.remove_prefix(newline == std::string_view::npos ? log.size() : newline + 1);
    LogLine entry;
    if (!parse_log_line(text, entry)) continue;
    Diagnostic d;
    d.severity = entry.severity;
    d.file = entry.file == "0" || entry.file.empty() ? main_name : std::string(entry.file);
    d.line = entry.line;
    std::string_view token, message = entry.message;
    std::string quoted;
    if (split_quoted_token(entry.message, token, message) && !token.empty())
      quoted = " '" + std::string(token) + "'";
    if (message.find("compilation terminated") != std::string_view::npos) continue;
    skip_blanks(message);
    d.message = std::string(message) + quoted;
    if (message.find("memory exhausted") != std::string_view::npos)  // bison's stack limit (10000 levels)
      d.message = "the code nests too deeply for the GLSL parser (more than 10000 levels of parentheses or blocks)";
    d.column = 1;
    for (const auto& [name, contents] : files) {
      if (name != d.file) continue;
      auto it = indexes.try_emplace(name, contents).first;
      d.column = column_in_row(it->second.line(d.line), token);
      break;
    }
    out.push_back(std::move(d));
  }
}

std::vector<int> error_lines_of_main_string(std::string_view log) {
  std::vector<int> lines;
  while (!log.empty()) {
    const size_t newline = log.find('\n');
    LogLine entry;
    if (parse_log_line(log.substr(0, newline), entry) && entry.severity == Severity::Error && entry.file == "0")
      lines.push_back(entry.line);
    log.remove_prefix(newline == std::string_view::npos ? log.size() : newline + 1);
  }
  return lines;
}

EShLanguage glslang_stage(Stage s) {
  switch (s) {
    case Stage::Vertex: return EShLangVertex;
    case Stage::Fragment: return EShLangFragment;
    case Stage::Compute: return EShLangCompute;
    case Stage::Geometry: return EShLangGeometry;
    case Stage::TessControl: return EShLangTessControl;
    case Stage::TessEvaluation: return EShLangTessEvaluation;
  }
  return EShLangVertex;
}

namespace {

// Resolves #include for glslang via the user's Includer or -I directories, and
// remembers every file read (for depfiles and for column recovery). Each
// (header, includer) is resolved once: the macro budget reads the files before
// glslang's preprocessor and parser ask for them again.
class IncludeAdapter : public glslang::TShader::Includer {
 public:
  // `budget`: how many bytes the included files may add (kMaxSourceBytes less the main source).
  IncludeAdapter(const Options& options, std::vector<std::pair<std::string, std::string>>& files,
                 std::vector<std::string>& included, std::size_t budget)
      : options_(options), files_(files), included_(included), budget_(budget) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    return too_deep(header, depth) ? nullptr : to_glslang(resolve(header, includer ? includer : "", true));
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return too_deep(header, depth) ? nullptr : to_glslang(resolve(header, includer ? includer : "", false));
  }
  void releaseInclude(IncludeResult* result) override { delete result; }

  // glslang follows an include cycle forever; stop at a depth no real shader needs.
  static constexpr size_t kMaxIncludeDepth = 32;
  std::string limit_error;  // the first include refused for depth or size
  bool too_deep(const char* header, size_t depth) {
    if (depth <= kMaxIncludeDepth) return false;
    if (limit_error.empty())
      limit_error = "#include nested more than " + std::to_string(kMaxIncludeDepth) + " deep at \"" +
                    std::string(header) + "\" (an include cycle?)";
    return true;
  }

  // The file `header` names from `includer` (the including file's resolved name), or null.
  const doublet::IncludeResult* resolve(const std::string& header, const std::string& includer, bool local) {
    auto [it, added] = cache_.try_emplace({header, includer, local});
    if (!added) return it->second ? &*it->second : nullptr;
    it->second = read(header, includer, local);
    if (it->second) {
      included_.push_back(it->second->resolved_path);
      files_.emplace_back(it->second->resolved_path, it->second->contents);
    }
    return it->second ? &*it->second : nullptr;
  }

 private:
  static IncludeResult* to_glslang(const doublet::IncludeResult* found) {
    if (!found) return nullptr;
    return new IncludeResult(found->resolved_path, found->contents.data(), found->contents.size(), nullptr);
  }

  // Every file read counts against budget_ (the bytes kMaxSourceBytes leaves after the shader):
  // a file over what is left is refused without being read whole.
  std::optional<doublet::IncludeResult> read(const std::string& header, const std::string& includer, bool local) {
    std::optional<doublet::IncludeResult> found;
    if (options_.includer) {
      found = options_.includer->include(header, includer);
    } else {
      namespace fs = std::filesystem;
      std::vector<fs::path> dirs;
      if (local) dirs.push_back(fs::path(includer.empty() ? options_.file_name : includer).parent_path());
      for (const auto& d : options_.include_dirs) dirs.emplace_back(d);
      for (const auto& dir : dirs) {
        fs::path candidate = dir / header;
        std::error_code ec;
        if (!fs::is_regular_file(candidate, ec)) continue;
        std::string text;
        ReadResult read = read_file_limited(candidate.string(), budget_, text);
        if (read.status == ReadStatus::TooLarge) return refuse_too_large(header);
        if (read.status == ReadStatus::Failed) continue;
        found = doublet::IncludeResult{candidate.lexically_normal().string(), std::move(text)};
        break;
      }
    }
    if (found && found->contents.size() > budget_) return refuse_too_large(header);  // from options_.includer
    if (found) budget_ -= found->contents.size();
    return found;
  }

  std::nullopt_t refuse_too_large(const std::string& header) {
    if (limit_error.empty()) limit_error = source_too_large_message("#include \"" + header + "\"");
    return std::nullopt;
  }

  const Options& options_;
  std::vector<std::pair<std::string, std::string>>& files_;
  std::vector<std::string>& included_;
  std::map<std::tuple<std::string, std::string, bool>, std::optional<doublet::IncludeResult>> cache_;
  std::size_t budget_;
};

// The `#include "name"` / `#include <name>` directives of `text`, as (name, local).
std::vector<std::pair<std::string, bool>> include_directives(std::string_view text) {
  std::vector<std::pair<std::string, bool>> found;
  LogicalLines lines(text);
  for (std::string_view line; lines.next(line);) {
    std::string_view rest;
    if (directive_name(line, rest) != "include") continue;
    skip_blanks(rest);
    if (rest.empty() || (rest.front() != '"' && rest.front() != '<')) continue;
    const char close = rest.front() == '"' ? '"' : '>';
    const size_t end = rest.find(close, 1);
    if (end != std::string_view::npos) found.emplace_back(std::string(rest.substr(1, end - 1)), close == '"');
  }
  return found;
}

// Every file the shader can #include (whatever #if says), resolved once each,
// with the files each includes: the graph glslang's preprocessor will walk.
struct IncludeGraph {
  struct File {
    std::string name;
    std::string_view text;
    std::vector<size_t> includes;  // indexes into files, once per directive
    MacroBudget::Weight own;
  };
  std::vector<File> files;  // [0]: the shader itself
};

IncludeGraph read_include_graph(std::string_view source, const std::string& file_name, IncludeAdapter& includer) {
  IncludeGraph graph;
  graph.files.push_back({file_name, source, {}, {}});
  std::map<std::string, size_t> index{{file_name, 0}};
  for (size_t next = 0; next < graph.files.size(); ++next) {
    for (const auto& [header, local] : include_directives(graph.files[next].text)) {
      const doublet::IncludeResult* found = includer.resolve(header, graph.files[next].name, local);
      if (!found) continue;  // glslang reports it where it matters
      auto [it, added] = index.try_emplace(found->resolved_path, graph.files.size());
      if (added) graph.files.push_back({found->resolved_path, found->contents, {}, {}});
      graph.files[next].includes.push_back(it->second);
    }
  }
  return graph;
}

// Tokens glslang will see for file `f` read at include depth `depth`, with
// everything it includes (an include cycle stops at the depth limit, as glslang does).
MacroBudget::Weight weight_from(const IncludeGraph& graph, size_t f, size_t depth,
                                std::vector<std::vector<std::optional<MacroBudget::Weight>>>& memo) {
  auto& slot = memo[f][depth];
  if (slot) return *slot;
  MacroBudget::Weight total = graph.files[f].own;
  if (depth < IncludeAdapter::kMaxIncludeDepth)
    for (size_t child : graph.files[f].includes) {
      const MacroBudget::Weight w = weight_from(graph, child, depth + 1, memo);
      total.spelled += w.spelled;
      total.expanded += w.expanded;
    }
  return *(slot = total);
}

// Macros may add this many tokens to what the shader and its includes spell out:
// glslang's preprocessor and parser then run in bounded time and memory.
constexpr double kMaxAddedTokens = 1 << 22;

// An error when macro expansion (in the shader, its #includes or -D values)
// would grow the shader by more than kMaxAddedTokens.
std::optional<Diagnostic> check_macro_budget(std::string_view source, const Options& options,
                                             IncludeAdapter& includer, bool& needs_preprocessing) {
  IncludeGraph graph = read_include_graph(source, options.file_name, includer);
  MacroBudget budget;
  for (const auto& [name, value] : options.defines)
    budget.add_definition(name, value.empty() ? "1" : value, {options.file_name, 1});
  for (const auto& file : graph.files) budget.add_definitions(file.text, file.name);
  for (auto& file : graph.files) file.own = budget.weigh(file.text);
  std::vector<std::vector<std::optional<MacroBudget::Weight>>> memo(
      graph.files.size(), std::vector<std::optional<MacroBudget::Weight>>(IncludeAdapter::kMaxIncludeDepth + 1));
  const MacroBudget::Weight total = weight_from(graph, 0, 0, memo);
  needs_preprocessing = budget.has_definitions() || graph.files.size() > 1;  // included text: unseen by lower()'s check
  double written = 0;  // each file once
  for (const auto& file : graph.files) written += file.own.spelled;
  auto count = [](double n) { return std::to_string(static_cast<long long>(std::min(n, 1e18))); };
  if (total.spelled > written + kMaxAddedTokens)
    return Diagnostic{options.file_name, 1, 1, Severity::Error,
                      "the #include directives read the same files again and again: about " + count(total.spelled) +
                          " tokens in all, from files holding " + count(written) + " (doublet allows " +
                          count(kMaxAddedTokens) + " more); include each file once"};
  if (total.expanded <= written + kMaxAddedTokens) return std::nullopt;
  const MacroBudget::Largest largest = budget.largest_macro();
  return Diagnostic{largest.origin.file, largest.origin.line, 1, Severity::Error,
                    "macro '" + largest.name + "' expands to about " + count(largest.tokens) +
                        " tokens: with it the shader would grow to about " + count(total.expanded) + " tokens, " +
                        count(total.expanded - written) + " more than written (doublet allows " +
                        count(kMaxAddedTokens) + " more); expand fewer macros or write the code out"};
}

bool known_version(const SourceInfo& info) {
  static const int es[] = {100, 300, 310, 320};
  static const int desktop[] = {110, 120, 130, 140, 150, 330, 400, 410, 420, 430, 440, 450, 460};
  const int* first = info.es ? std::begin(es) : std::begin(desktop);
  const int* last = info.es ? std::end(es) : std::end(desktop);
  return std::find(first, last, info.version) != last;
}

int version_line(std::string_view source) {
  auto pos = source.find("#version");
  if (pos == std::string_view::npos) return 1;
  return 1 + static_cast<int>(std::count(source.begin(), source.begin() + static_cast<long>(pos), '\n'));
}

// Vulkan-only GLSL names glslang refuses with messages about Vulkan or SPIR-V (or a bare
// syntax error, for subpassInput): each with what an OpenGL / OpenGL ES shader writes instead.
struct VulkanOnly {
  const char* word;  // as it appears in the source line
  const char* advice;
};
constexpr VulkanOnly kVulkanOnly[] = {
    {"push_constant", "'layout(push_constant)' is Vulkan GLSL; OpenGL has no push constants: remove 'push_constant' "
                      "to make it an ordinary uniform block"},
    {"subpassInput", "subpass inputs (subpassInput, subpassLoad) are Vulkan GLSL; read the attachment as a texture: "
                     "'uniform sampler2D' and texelFetch(tex, ivec2(gl_FragCoord.xy), 0)"},
    {"input_attachment_index", "subpass inputs (layout(input_attachment_index)) are Vulkan GLSL; read the attachment "
                               "as a texture: 'uniform sampler2D' and texelFetch(tex, ivec2(gl_FragCoord.xy), 0)"},
    {"constant_id", "specialization constants (layout(constant_id)) are Vulkan GLSL; make it a plain const, or a "
                    "macro set with -D NAME=VALUE"},
    {"gl_VertexIndex", "'gl_VertexIndex' is Vulkan GLSL; OpenGL spells it gl_VertexID"},
    {"gl_InstanceIndex", "'gl_InstanceIndex' is Vulkan GLSL; OpenGL spells it gl_InstanceID"},
    {"set", "descriptor sets (layout(set = N)) are Vulkan GLSL; remove 'set = N' and keep 'binding = M' (OpenGL has "
            "one binding space per resource kind)"},
};

bool has_word(std::string_view text, std::string_view word) {
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t pos = text.find(word); pos != std::string_view::npos; pos = text.find(word, pos + 1))
    if ((pos == 0 || !is_word(text[pos - 1])) && (pos + word.size() >= text.size() || !is_word(text[pos + word.size()])))
      return true;
  return false;
}

// Rewrites glslang's errors on lines that use Vulkan-only GLSL (from diagnostic `first` on) into
// one error per line that says so, names the target and what to write instead.
void explain_vulkan_only(std::vector<Diagnostic>& diags, size_t first,
                         const std::vector<std::pair<std::string, std::string>>& files, Target target) {
  std::vector<Diagnostic> kept(diags.begin(), diags.begin() + static_cast<long>(first));
  std::set<std::pair<std::string, int>> explained;
  std::map<std::string, LineIndex, std::less<>> indexes;  // per file, built on its first error
  for (size_t i = first; i < diags.size(); ++i) {
    Diagnostic d = diags[i];
    const VulkanOnly* found = nullptr;
    for (const auto& [name, text] : files) {
      if (name != d.file || d.severity != Severity::Error) continue;
      const std::string_view row = indexes.try_emplace(name, text).first->second.line(d.line);
      for (const auto& v : kVulkanOnly)
        if (!found && has_word(row, v.word) && (std::string_view(v.word) != "set" || has_word(row, "layout"))) {
          found = &v;
          d.column = column_in_row(row, v.word);
        }
    }
    if (!found) {
      kept.push_back(std::move(d));
      continue;
    }
    if (!explained.insert({d.file, d.line}).second) continue;  // one explanation per line
    const std::string name(to_string(target));
    std::string advice = found->advice;
    if (target == Target::Wgsl && std::string_view(found->word) == "set")  // (the main file's are read: parse)
      advice = "a descriptor set (layout(set = N)) in an #include'd file: wgsl reads the main file's as @group(N); "
               "declare the block there";
    d.message = advice + " (target " + name +
                (target == Target::Wgsl ? ": doublet reads OpenGL GLSL for WGSL output too)"
                                        : std::string(" is ") + (target_is_es(target) ? "OpenGL ES" : "OpenGL") + " GLSL)");
    kept.push_back(std::move(d));
  }
  diags = std::move(kept);
}

// `layout(... set = N ...)` with N > 0 rewritten as set = 0, padded to the same length (columns
// kept), each recorded. One pass, no regex (a 4 MB line stays linear and shallow); comments are not
// told apart (a rewritten comment changes nothing).
std::string parse_descriptor_sets_as_zero(std::string text, std::vector<ParsedShader::DescriptorSet>& sets) {
  const size_t n = text.size();
  auto word_end = [&](size_t i) {
    while (i < n && is_word_char(text[i])) ++i;
    return i;
  };
  auto skip_blanks = [&](size_t i) {
    while (i < n && (is_blank(text[i]) || text[i] == '\n')) ++i;
    return i;
  };
  int line = 1;
  size_t line_start = 0;
  bool after_layout = false, inside = false;  // the word `layout` seen, its '(' not yet / open
  for (size_t i = 0; i < n; ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = i + 1;
    } else if (is_word_char(c)) {
      const size_t end = word_end(i);
      const std::string_view word(text.data() + i, end - i);
      after_layout = !inside && word == "layout";
      if (inside && word == "set") {
        const size_t equals = skip_blanks(end);
        const size_t first = equals < n && text[equals] == '=' ? skip_blanks(equals + 1) : n;
        size_t last = first;
        while (last < n && is_digit(text[last])) ++last;
        if (last > first) {
          const int value = last - first > 6 ? 1000000 : std::stoi(text.substr(first, last - first));
          if (value != 0) {
            sets.push_back({line, static_cast<int>(i - line_start) + 1, value});
            text.replace(first, last - first, "0" + std::string(last - first - 1, ' '));
          }
        }
      }
      i = end - 1;
    } else if (!is_blank(c)) {
      if (c == '(' && after_layout) inside = true;
      else if (c == ')') inside = false;
      after_layout = false;
    }
  }
  return text;
}

bool has_main(glslang::TIntermediate* intermediate) {
  auto* root = intermediate->getTreeRoot() ? intermediate->getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) return false;
  for (TIntermNode* node : root->getSequence())
    if (auto* f = node->getAsAggregate(); f && f->getOp() == glslang::EOpFunction &&
                                          std::string(f->getName().c_str()).rfind("main(", 0) == 0)
      return true;
  return false;
}


// glslang keeps pointers to these arrays (not copies): they must outlive the TShader's parse.
struct ShaderStrings {
  const char* text[1];
  int length[1];
  const char* name[1];
};

void configure(glslang::TShader& shader, ShaderStrings& strings, const std::string& text, const std::string& preamble,
               const Options& options) {
  strings = {{text.c_str()}, {static_cast<int>(text.size())}, {options.file_name.c_str()}};
  shader.setStringsWithLengthsAndNames(strings.text, strings.length, strings.name, 1);
  shader.setPreamble(preamble.c_str());
  shader.setEnvInput(glslang::EShSourceGlsl, glslang_stage(*options.stage), glslang::EShClientNone, 100);
  shader.setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  shader.setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
}

// The operator limit (support/big_stack.hpp) applied to the text glslang's parser
// will see: macros can spell a million operators in one short line. The macro
// budget has bounded what preprocessing produces.
std::optional<Diagnostic> check_expanded_operators(const std::string& text, const std::string& preamble,
                                                   const Options& options, IncludeAdapter& includer) {
  glslang::TShader shader(glslang_stage(*options.stage));
  ShaderStrings strings;
  configure(shader, strings, text, preamble, options);
  std::string expanded;
  if (!shader.preprocess(&resource_limits(), 450, ECompatibilityProfile, true, false,
                         static_cast<EShMessages>(EShMsgCascadingErrors), &expanded, includer))
    return std::nullopt;  // the parse reports the errors
  const std::size_t operators = max_statement_operators(expanded);
  if (operators <= kMaxStatementOperators) return std::nullopt;
  return Diagnostic{options.file_name, 1, 1, Severity::Error, too_many_operators_message(operators, true)};
}

}  // namespace

bool parse(std::string_view source, const Options& options, ParsedShader& out,
           std::vector<Diagnostic>& diagnostics) {
  ensure_glslang_initialized();
  out.info = scan_version(source);
  out.source = std::string(source);
  auto first_non_blank = source.find_first_not_of(" \t\r\n");
  if (first_non_blank == std::string_view::npos) {
    diagnostics.push_back({options.file_name, 1, 1, Severity::Error, "empty shader: no code to lower"});
    return false;
  }
  if (source.find('\0') != std::string_view::npos) {
    int line = 1 + static_cast<int>(std::count(source.begin(), source.begin() + source.find('\0'), '\n'));
    diagnostics.push_back({options.file_name, line, 1, Severity::Error,
                           "input is not GLSL text (it contains a NUL byte)"});
    return false;
  }

  if (!known_version(out.info)) {
    diagnostics.push_back({options.file_name, version_line(source), 1, Severity::Error,
                           "unsupported #version " + std::to_string(out.info.version) + (out.info.es ? " es" : "") +
                               ": doublet reads GLSL ES 1.00, 3.00, 3.10, 3.20 and desktop GLSL 1.10-4.60"});
    return false;
  }

  std::string text(source);
  std::vector<std::pair<std::string, std::string>> files{{options.file_name, text}};
  // WGSL has bind groups (Vulkan's descriptor sets, which glslang allows OpenGL GLSL only as set 0).
  if (options.target == Target::Wgsl) text = parse_descriptor_sets_as_zero(std::move(text), out.descriptor_sets);
  IncludeAdapter includer(options, files, out.included_files, kMaxSourceBytes - std::min(kMaxSourceBytes, source.size()));
  bool needs_preprocessing = false;  // or includes files: then the operator limit applies to the preprocessed text
  if (auto error = check_macro_budget(source, options, includer, needs_preprocessing)) {
    diagnostics.push_back(*error);
    return false;
  }
  std::string preamble = "#extension GL_GOOGLE_include_directive : enable\n";
  for (const auto& [name, value] : options.defines)
    preamble += "#define " + name + " " + (value.empty() ? "1" : value) + "\n";
  // WGSL has Vulkan's vertex and instance indices (vertex_index, instance_index: counted from the
  // draw's first vertex and first instance), which the WGSL printer gives both spellings.
  if (options.target == Target::Wgsl)
    preamble += "#define gl_VertexIndex gl_VertexID\n#define gl_InstanceIndex gl_InstanceID\n";
  if (needs_preprocessing) {
    if (auto error = check_expanded_operators(text, preamble, options, includer)) {
      diagnostics.push_back(*error);
      return false;
    }
  }

  ShaderStrings strings;
  auto attempt = [&](const std::string& with_preamble) {
    out.shader = std::make_unique<glslang::TShader>(glslang_stage(*options.stage));
    configure(*out.shader, strings, text, with_preamble, options);
    auto messages = static_cast<EShMessages>(EShMsgCascadingErrors);
    // Every input is parsed as desktop 4.50 compatibility, whatever its #version says.
    return out.shader->parse(&resource_limits(), 450, ECompatibilityProfile, true, false, messages, includer);
  };
  bool ok = attempt(preamble);
  // The transcendental extension (frontend/transcendentals.hpp): only a shader whose parse fails on
  // a call of exp, sin, ... gets the double prototypes, so every other shader parses as before.
  if (!ok && includer.limit_error.empty() && refuses_transcendental(out.shader->getInfoLog())) {
    ok = attempt(preamble + transcendental_prototypes());
    out.transcendentals = ok;
  }
  if (!includer.limit_error.empty()) {
    diagnostics.push_back({options.file_name, 1, 1, Severity::Error, includer.limit_error});
    return false;
  }
  const size_t first_log_diagnostic = diagnostics.size();
  append_glslang_log(out.shader->getInfoLog(), options.file_name, files, diagnostics);
  explain_vulkan_only(diagnostics, first_log_diagnostic, files, options.target);
  if (!ok) {
    bool any_error = false;
    for (const auto& d : diagnostics) any_error |= d.severity == Severity::Error;
    if (!any_error)
      diagnostics.push_back({options.file_name, 1, 1, Severity::Error, "the shader does not compile"});
    return false;
  }
  out.intermediate = out.shader->getIntermediate();
  if (!has_main(out.intermediate)) {
    diagnostics.push_back({options.file_name, 1, 1, Severity::Error, "the shader has no main() function"});
    return false;
  }
  return true;
}

}  // namespace doublet::frontend
