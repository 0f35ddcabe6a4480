#include "frontend/frontend.hpp"

#include <glslang/Include/ResourceLimits.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <functional>
#include <fstream>
#include <mutex>
#include <regex>
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
  static const std::regex version_re(R"(^\s*#\s*version\s+(\d+)\s*(\w*))");
  std::string text(source);
  std::istringstream lines(text);
  std::string line;
  bool in_comment = false;
  while (std::getline(lines, line)) {
    // Skip blank lines and comments before the directive.
    std::string_view rest = line;
    while (!rest.empty()) {
      if (in_comment) {
        auto end = rest.find("*/");
        if (end == std::string_view::npos) { rest = {}; break; }
        rest.remove_prefix(end + 2);
        in_comment = false;
        continue;
      }
      auto first = rest.find_first_not_of(" \t\r");
      if (first == std::string_view::npos) { rest = {}; break; }
      rest.remove_prefix(first);
      if (rest.substr(0, 2) == "//") { rest = {}; break; }
      if (rest.substr(0, 2) == "/*") { in_comment = true; rest.remove_prefix(2); continue; }
      break;
    }
    if (rest.empty()) continue;
    std::smatch m;
    std::string s(rest);
    if (std::regex_search(s, m, version_re)) {
      info.version = std::stoi(m[1].str());
      std::string profile = m[2].str();
      info.es = profile == "es" || info.version == 100;
    }
    return info;
  }
  return info;
}

int recover_column(std::string_view text, int line, std::string_view token) {
  int current = 1;
  size_t start = 0;
  while (current < line && start < text.size()) {
    size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) return 1;
    start = nl + 1;
    ++current;
  }
  size_t end = text.find('\n', start);
  std::string_view row = text.substr(start, end == std::string_view::npos ? text.size() - start : end - start);
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  if (!token.empty()) {
    for (size_t pos = row.find(token); pos != std::string_view::npos; pos = row.find(token, pos + 1)) {
      bool left_ok = pos == 0 || !is_word(row[pos - 1]) || !is_word(token.front());
      size_t after = pos + token.size();
      bool right_ok = after >= row.size() || !is_word(row[after]) || !is_word(token.back());
      if (left_ok && right_ok) return static_cast<int>(pos) + 1;
    }
  }
  size_t first = row.find_first_not_of(" \t\r");
  return first == std::string_view::npos ? 1 : static_cast<int>(first) + 1;
}

void append_glslang_log(std::string_view log, const std::string& main_name,
                        const std::vector<std::pair<std::string, std::string>>& files,
                        std::vector<Diagnostic>& out) {
  static const std::regex line_re(R"(^(ERROR|WARNING): (.*?):(\d+): (.*)$)");
  static const std::regex token_re(R"(^\s*'([^']*)'\s*:\s*(.*?)\s*$)");
  std::istringstream lines{std::string(log)};
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, line_re)) continue;
    Diagnostic d;
    d.severity = m[1] == "ERROR" ? Severity::Error : Severity::Warning;
    d.file = m[2].str();
    if (d.file == "0" || d.file.empty()) d.file = main_name;
    d.line = std::stoi(m[3].str());
    std::string message = m[4].str();
    std::string token;
    std::smatch t;
    if (std::regex_match(message, t, token_re)) {
      token = t[1].str();
      message = t[2].str();
      if (!token.empty()) message += " '" + token + "'";
    }
    if (message.find("compilation terminated") != std::string::npos) continue;
    if (message.find("memory exhausted") != std::string::npos)  // bison's stack limit (10000 levels)
      message = "the code nests too deeply for the GLSL parser (more than 10000 levels of parentheses or blocks)";
    while (!message.empty() && message.front() == ' ') message.erase(message.begin());
    d.message = message;
    d.column = 1;
    for (const auto& [name, text] : files)
      if (name == d.file) d.column = recover_column(text, d.line, token);
    out.push_back(std::move(d));
  }
}

namespace {

EShLanguage to_glslang(Stage s) {
  switch (s) {
    case Stage::Vertex: return EShLangVertex;
    case Stage::Fragment: return EShLangFragment;
    case Stage::Compute: return EShLangCompute;
  }
  return EShLangVertex;
}

// Resolves #include for glslang via the user's Includer or -I directories, and
// remembers every file read (for depfiles and for column recovery).
class IncludeAdapter : public glslang::TShader::Includer {
 public:
  IncludeAdapter(const Options& options, std::vector<std::pair<std::string, std::string>>& files,
                 std::vector<std::string>& included)
      : options_(options), files_(files), included_(included) {}

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override {
    return too_deep(header, depth) ? nullptr : resolve(header, includer, true);
  }
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
    return too_deep(header, depth) ? nullptr : resolve(header, includer, false);
  }

  // glslang follows an include cycle forever; stop at a depth no real shader needs.
  static constexpr size_t kMaxIncludeDepth = 32;
  std::string depth_error;
  bool too_deep(const char* header, size_t depth) {
    if (depth <= kMaxIncludeDepth) return false;
    if (depth_error.empty())
      depth_error = "#include nested more than " + std::to_string(kMaxIncludeDepth) + " deep at \"" +
                    std::string(header) + "\" (an include cycle?)";
    return true;
  }
  void releaseInclude(IncludeResult* result) override {
    if (!result) return;
    delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  IncludeResult* resolve(const char* header, const char* includer, bool local) {
    std::optional<doublet::IncludeResult> found;
    if (options_.includer) {
      found = options_.includer->include(header, includer ? includer : "");
    } else {
      namespace fs = std::filesystem;
      std::vector<fs::path> dirs;
      if (local) {
        fs::path from = includer && *includer ? fs::path(includer) : fs::path(options_.file_name);
        dirs.push_back(from.parent_path());
      }
      for (const auto& d : options_.include_dirs) dirs.emplace_back(d);
      for (const auto& dir : dirs) {
        fs::path candidate = dir / header;
        std::error_code ec;
        if (!fs::is_regular_file(candidate, ec)) continue;
        std::ifstream in(candidate, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        found = doublet::IncludeResult{candidate.lexically_normal().string(), buffer.str()};
        break;
      }
    }
    if (!found) return nullptr;
    included_.push_back(found->resolved_path);
    files_.emplace_back(found->resolved_path, found->contents);
    auto* text = new std::string(std::move(found->contents));
    return new IncludeResult(found->resolved_path, text->data(), text->size(), text);
  }

  const Options& options_;
  std::vector<std::pair<std::string, std::string>>& files_;
  std::vector<std::string>& included_;
};

// The largest number of tokens one macro can expand to, following
// object-like and function-like macro bodies (not argument duplication).
// glslang expands macros eagerly and without limit, so a "billion laughs"
// chain (#define A1 A0 A0, #define A2 A1 A1, ...) would run for hours.
std::pair<std::string, double> largest_macro_expansion(std::string_view source) {
  static const std::regex define_re(R"(^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)(\([^)]*\))?(.*)$)");
  static const std::regex token_re(R"([A-Za-z_]\w*|\d[\w.]*|\S)");
  std::map<std::string, std::vector<std::string>> bodies;
  std::istringstream lines{std::string(source)};
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_match(line, m, define_re)) continue;
    std::vector<std::string> tokens;
    std::string body = m[3].str();
    for (std::sregex_iterator it(body.begin(), body.end(), token_re), end; it != end; ++it) tokens.push_back(it->str());
    bodies[m[1].str()] = std::move(tokens);
  }
  std::map<std::string, double> size;
  std::function<double(const std::string&, int)> expand = [&](const std::string& name, int depth) -> double {
    if (auto it = size.find(name); it != size.end()) return it->second;
    size[name] = 1;  // a macro is not re-expanded inside itself
    double total = 0;
    for (const auto& t : bodies[name])
      total += bodies.count(t) && depth < 1000 ? expand(t, depth + 1) : 1;
    return size[name] = std::max(total, 1.0);
  };
  std::pair<std::string, double> worst{"", 0};
  for (const auto& [name, body] : bodies)
    if (double n = expand(name, 0); n > worst.second) worst = {name, n};
  return worst;
}

constexpr double kMaxMacroExpansion = 1e7;

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
  for (size_t i = first; i < diags.size(); ++i) {
    Diagnostic d = diags[i];
    const VulkanOnly* found = nullptr;
    for (const auto& [name, text] : files) {
      if (name != d.file || d.severity != Severity::Error) continue;
      std::string_view row = text;
      for (int l = 1; l < d.line && !row.empty(); ++l) {
        auto nl = row.find('\n');
        row = nl == std::string_view::npos ? std::string_view{} : row.substr(nl + 1);
      }
      row = row.substr(0, row.find('\n'));
      for (const auto& v : kVulkanOnly)
        if (!found && has_word(row, v.word) && (std::string_view(v.word) != "set" || has_word(row, "layout"))) {
          found = &v;
          d.column = recover_column(text, d.line, v.word);
        }
    }
    if (!found) {
      kept.push_back(std::move(d));
      continue;
    }
    if (!explained.insert({d.file, d.line}).second) continue;  // one explanation per line
    d.message = std::string(found->advice) + " (target " + std::string(to_string(target)) +
                " is " + (target_is_es(target) ? "OpenGL ES" : "OpenGL") + " GLSL)";
    kept.push_back(std::move(d));
  }
  diags = std::move(kept);
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

  if (auto [macro, tokens] = largest_macro_expansion(source); tokens > kMaxMacroExpansion) {
    diagnostics.push_back({options.file_name, 1, 1, Severity::Error,
                           "macro '" + macro + "' expands to about " + std::to_string(static_cast<long long>(std::min(tokens, 1e18))) +
                               " tokens (limit " + std::to_string(static_cast<long long>(kMaxMacroExpansion)) + ")"});
    return false;
  }

  std::string preamble = "#extension GL_GOOGLE_include_directive : enable\n";
  for (const auto& [name, value] : options.defines)
    preamble += "#define " + name + " " + (value.empty() ? "1" : value) + "\n";

  out.shader = std::make_unique<glslang::TShader>(to_glslang(*options.stage));
  std::string text(source);
  const char* strings[] = {text.c_str()};
  const int lengths[] = {static_cast<int>(text.size())};
  const char* names[] = {options.file_name.c_str()};
  out.shader->setStringsWithLengthsAndNames(strings, lengths, names, 1);
  out.shader->setPreamble(preamble.c_str());
  out.shader->setEnvInput(glslang::EShSourceGlsl, to_glslang(*options.stage), glslang::EShClientNone, 100);
  out.shader->setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  out.shader->setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));

  std::vector<std::pair<std::string, std::string>> files{{options.file_name, text}};
  IncludeAdapter includer(options, files, out.included_files);
  auto messages = static_cast<EShMessages>(EShMsgCascadingErrors);
  // Every input is parsed as desktop 4.50 compatibility, whatever its #version says.
  bool ok = out.shader->parse(&resource_limits(), 450, ECompatibilityProfile, true, false, messages, includer);
  if (!includer.depth_error.empty()) {
    diagnostics.push_back({options.file_name, 1, 1, Severity::Error, includer.depth_error});
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
