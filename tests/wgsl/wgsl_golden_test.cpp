// `--target wgsl` beyond its golden files (tests/golden/cases with `wgsl` in the targets line,
// expected in tests/golden/expected/<name>.<stage>.wgsl): the manifest, refusals by position, the
// std140 layout. The expected WGSL is compiled by a real WGSL front end (Chromium's WebGPU) in
// wgsl_browser_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "file_text.hpp"

namespace {
namespace fs = std::filesystem;

const fs::path kCases = DOUBLET_GOLDEN_CASES_DIR;

// The golden cases lowered for wgsl: `wgsl` in their targets line.
std::vector<std::string> wgsl_cases() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kCases)) {
    if (!e.is_regular_file()) continue;
    const std::string text = doublet::test::file_text(e.path());
    const std::string first = text.substr(0, text.find('\n'));
    if (std::regex_search(first, std::regex(R"(^//\s*targets\s*:.*\bwgsl\b)"))) names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The loose uniforms (the guard among them) are one uniform buffer whose place the manifest gives.
TEST(WgslManifest, UniformBufferBindingAndOffsets) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Wgsl;
  doublet::Result result = doublet::lower(doublet::test::file_text(kCases / "add_dvec2.comp"), options);
  ASSERT_TRUE(result.ok);
  const auto& vars = result.manifest.variables;
  auto it = std::find_if(vars.begin(), vars.end(), [](const auto& v) { return v.name == "df_uniforms"; });
  ASSERT_NE(it, vars.end()) << result.manifest.to_json();
  EXPECT_EQ(it->group, 0);
  EXPECT_EQ(it->binding, 1);  // after the storage buffer at binding 0
  ASSERT_EQ(it->members.size(), 5u);  // a_hi a_lo b_hi b_lo df_guard
  const int offsets[] = {0, 8, 16, 24, 32};
  for (size_t k = 0; k < 5; ++k) EXPECT_EQ(it->members[k].offset, offsets[k]) << it->members[k].name;
  EXPECT_EQ(it->members[4].name, "df_guard");
  EXPECT_NE(result.manifest.to_json().find("\"binding\": 1"), std::string::npos);
}

// Every input and output's locations are in the manifest (a WebGPU host builds its vertex buffer
// layout from it), and they are the @location(N) the WGSL entry point declares: read back from the
// text, independently of how the compiler chose them. Split doubles list hi then lo.
TEST(WgslManifest, EveryInterfaceVariableHasTheLocationsOfTheText) {
  int checked = 0;
  for (const std::string& file : wgsl_cases()) {
    const std::string stage_name = file.substr(file.rfind('.') + 1);
    if (stage_name == "comp") continue;
    doublet::Options options;
    options.stage = doublet::parse_stage(stage_name);
    options.target = doublet::Target::Wgsl;
    doublet::Result result = doublet::lower(doublet::test::file_text(kCases / file), options);
    if (!result.ok) continue;  // a case the target refuses (its .errors golden)
    for (const auto& v : result.manifest.variables) {
      if (v.storage != "in" && v.storage != "out") continue;
      ASSERT_EQ(v.locations.size(), v.lowered_names.size()) << file << ": " << v.name << "\n" << result.manifest.to_json();
      for (size_t k = 0; k < v.lowered_names.size(); ++k) {
        const std::string name = v.storage == "in" ? "df_in_" + v.lowered_names[k] : v.lowered_names[k];
        const std::regex declared("@location\\(([0-9]+)\\)( @interpolate\\(flat\\))? " + name + ":");
        std::smatch m;
        ASSERT_TRUE(std::regex_search(result.output, m, declared)) << file << ": no @location for " << name;
        EXPECT_EQ(std::stoi(m[1]), v.locations[k]) << file << ": " << name;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 4);  // orbit.vert: position_hi, position_lo, color; deepzoom.frag: its output
}

TEST(WgslTarget, PreciseGuardAndNativeModeAreRefused) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Wgsl;
  options.guard = doublet::GuardKind::Precise;
  auto r = doublet::lower("#version 450\nlayout(local_size_x=1) in;\nvoid main(){}\n", options);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("no 'precise'"), std::string::npos);
  options.guard = doublet::GuardKind::Auto;
  options.mode = doublet::Mode::Native;
  r = doublet::lower("#version 450\nlayout(local_size_x=1) in;\nvoid main(){}\n", options);
  EXPECT_FALSE(r.ok);
}

}  // namespace

namespace {

// What WGSL cannot express is a positioned error, never a crash or WGSL that does not compile.
std::vector<doublet::Diagnostic> wgsl_errors(const std::string& body) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Wgsl;
  options.file_name = "e.comp";
  const std::string source = "#version 450\nlayout(local_size_x = 1) in;\nstruct S { double a; };\n"
                             "layout(std430, binding = 0) buffer B { float v[]; };\nvoid main() {\n" + body + "\n}\n";
  auto r = doublet::lower(source, options);
  EXPECT_FALSE(r.ok) << r.output;
  std::vector<doublet::Diagnostic> errors;
  for (const auto& d : r.diagnostics)
    if (d.severity == doublet::Severity::Error) errors.push_back(d);
  return errors;
}

TEST(WgslRefusals, AreErrorsWithPositions) {
  const std::pair<const char*, const char*> cases[] = {
      // In a loop's step (v[i++] = 1.0 as a statement, or under &&, lowers).
      {"for (int i = 0; i < 2; v[i++] = 1.0) {}", "'x++' inside an expression"},
      {"S s = S(1.0lf); S t = s; v[0] = s == t ? 1.0 : 0.0;", "comparing structs"},
      {"int i = int(v[0]); switch (i) { case 0: v[1] = 1.0; case 1: v[2] = 2.0; break; }", "falls through"},
  };
  for (const auto& [body, fragment] : cases) {
    auto errors = wgsl_errors(body);
    ASSERT_FALSE(errors.empty()) << body;
    EXPECT_NE(errors[0].message.find(fragment), std::string::npos) << body << "\n" << errors[0].message;
    EXPECT_GT(errors[0].line, 0) << body;
    EXPECT_GT(errors[0].column, 0) << body;
    EXPECT_EQ(errors[0].message.find("internal error"), std::string::npos) << errors[0].message;
  }
}

}  // namespace

namespace {

TEST(WgslRefusals, BuiltInVariableWithoutCounterpartIsPositioned) {
  doublet::Options options;
  options.stage = doublet::Stage::Vertex;
  options.target = doublet::Target::Wgsl;
  options.file_name = "p.vert";
  auto r = doublet::lower("#version 450\nuniform double s;\nvoid main() {\n  gl_Position = vec4(float(s));\n"
                          "  gl_PointSize = 2.0;\n}\n", options);
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("'gl_PointSize' has no WGSL translation"), std::string::npos)
      << r.diagnostics[0].message;
  EXPECT_GT(r.diagnostics[0].line, 0);
}

}  // namespace

namespace {

// The WGSL printer works on an intermediate ES 3.10 text; its refusals must still name the user's
// file, line and column (pipeline/wgsl_tail.cpp maps them back), not the intermediate text's.
TEST(WgslRefusals, NameTheUsersLineAndColumn) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Wgsl;
  options.file_name = "user.comp";
  const std::string source =
      "#version 450\n"
      "layout(local_size_x = 1) in;\n"
      "layout(std430, binding = 0) buffer B { double x; float v[]; };\n"
      "void main() {\n"
      "  x = x * 2.0lf;\n"
      "  int i = int(v[0]);\n"
      "  switch (i) {\n"
      "    case 0: v[1] = 1.0;\n"
      "      case 1: v[2] = 2.0; break;\n"  // line 9: the case fallen into, at column 7
      "  }\n"
      "}\n";
  const auto r = doublet::lower(source, options);
  ASSERT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  const doublet::Diagnostic& d = r.diagnostics[0];
  EXPECT_NE(d.message.find("falls through"), std::string::npos) << d.message;
  EXPECT_EQ(d.file, "user.comp");
  EXPECT_EQ(d.message.find("intermediate"), std::string::npos) << d.message;
  EXPECT_EQ(doublet::format_diagnostic(d).substr(0, 15), "user.comp:8:5: ") << doublet::format_diagnostic(d);
}

}  // namespace

namespace {

// WebGPU has no writable storage buffers in vertex shaders: a buffer the vertex shader only reads is
// declared `var<storage, read>` (it was printed read_write, which Dawn rejects, with exit 0), and one
// it writes is refused at the write.
TEST(WgslRefusals, VertexStorageBuffersAreReadOnlyOrRefused) {
  doublet::Options options;
  options.stage = doublet::Stage::Vertex;
  options.target = doublet::Target::Wgsl;
  options.file_name = "p.vert";
  const std::string head = "#version 450\nlayout(std430, binding = 0) buffer Pos { uint count; dvec4 p[]; };\n"
                           "layout(location = 0) out vec4 c;\nvoid main() {\n  dvec4 q = p[gl_VertexID];\n";
  auto reads = doublet::lower(head + "  gl_Position = vec4(q);\n  c = vec4(1.0);\n}\n", options);
  ASSERT_TRUE(reads.ok) << (reads.diagnostics.empty() ? "" : reads.diagnostics[0].message);
  EXPECT_NE(reads.output.find("var<storage, read> "), std::string::npos) << reads.output;
  EXPECT_EQ(reads.output.find("read_write"), std::string::npos) << reads.output;
  auto writes = doublet::lower(head + "  gl_Position = vec4(q);\n  c = vec4(1.0);\n  p[gl_VertexID] = q * 2.0lf;\n}\n",
                               options);
  ASSERT_FALSE(writes.ok) << writes.output;
  ASSERT_FALSE(writes.diagnostics.empty());
  EXPECT_NE(writes.diagnostics[0].message.find("WebGPU has no writable storage buffers in vertex shaders"),
            std::string::npos) << writes.diagnostics[0].message;
  EXPECT_EQ(writes.diagnostics[0].line, 8);
  auto counts = doublet::lower(head + "  gl_Position = vec4(q);\n  c = vec4(1.0);\n  atomicAdd(count, 1u);\n}\n", options);
  EXPECT_FALSE(counts.ok) << counts.output;
}

}  // namespace

namespace {

// std140 rounds array strides and struct alignments up to 16 bytes; WGSL's storage layout does not
// (and its uniform layout rejects such strides). doublet prints std140 blocks with std140's offsets
// (@align, @size, padded array elements: docs/web.md, "std140 blocks in WGSL"); what that cannot
// express is refused by member. Before, a std140 storage array of doubles was read with an 8-byte
// stride where the host (following the manifest) wrote 16: wrong values in Chromium's WebGPU, exit 0
// (the differential tester's seed 6103); then every such block was refused.
TEST(WgslStd140, BlocksLowerWithStd140OffsetsOrAreRefusedByMember) {
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = doublet::Target::Wgsl;
  options.file_name = "b.comp";
  auto lower_block = [&](const std::string& block, const std::string& use = "s + double(x.length())") {
    return doublet::lower("#version 450\nlayout(local_size_x = 1) in;\n" + block +
                              "\nlayout(std430, binding = 1) buffer Out { double r; };\nvoid main() { r = " + use + "; }\n",
                          options);
  };
  struct Case {
    std::string block, member, use;
    int line;  // of the std140 block
  };
  for (const Case& c :
       {Case{"layout(std140, binding = 0) buffer In { dmat2 x; double s; };", "'In.x.hi'", "s + x[1][0]", 3},
        Case{"struct P { double d; float w; };\nlayout(std140, binding = 0) buffer In { P x; double s; };\n"
             "layout(std430, binding = 2) buffer Q { P q; };",
             "'P' is also held by std430 block 'Q'", "s + x.d + q.d", 4}}) {
    const auto r = lower_block(c.block, c.use);
    ASSERT_FALSE(r.ok) << c.block << "\n" << r.output;
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_NE(r.diagnostics[0].message.find(c.member), std::string::npos) << r.diagnostics[0].message;
    EXPECT_NE(r.diagnostics[0].message.find("std430"), std::string::npos) << r.diagnostics[0].message;
    EXPECT_EQ(r.diagnostics[0].line, c.line) << r.diagnostics[0].message;
  }
  const auto whole = lower_block("layout(std140, binding = 0) buffer In { double x[4]; double s; };",
                                 "s; double y[4] = x; r += y[1]");
  ASSERT_FALSE(whole.ok) << whole.output;
  EXPECT_NE(whole.diagnostics.at(0).message.find("read as a whole"), std::string::npos) << whole.diagnostics[0].message;
  for (const std::string& lowers : {"layout(std430, binding = 0) buffer In { double x[4]; double s; };",
                                    "layout(std140, binding = 0) buffer In { dvec2 x[4]; double s; };",
                                    "layout(std140, binding = 0) buffer In { double x[4]; double s; };",
                                    "layout(std140, binding = 0) uniform In { double x[4]; double s; };",
                                    "layout(std140, binding = 0) buffer In { dvec2 x[4]; float f; double s; };",
                                    "struct P { double d; float w[2]; };\n"
                                    "layout(std140, binding = 0) buffer In { P x[3]; double s; };"}) {
    const auto r = lower_block(lowers);
    EXPECT_TRUE(r.ok) << lowers << "\n" << (r.diagnostics.empty() ? "" : r.diagnostics[0].message);
  }
}

}  // namespace
