// Mode exact's double matrices across the interface (docs/modes.md, "exact", "Double matrices"):
//  - loose `uniform dmat4` / `uniform dmat3` fed through pack::uniform_words from the host's
//    column-major doubles (one uvec4 array each), a std140 block with dmat3/dmat2x3/dmat2 members,
//    a std430 block whose dmat4 and dmat3x2[2] members are read and written whole, by column and by
//    element, and a runtime array of dmat4 written per invocation: the lowered shader on lavapipe
//    and Mesa GLES must leave the same output bytes as the original on native fp64 (lavapipe).
//  - Sabotages (low/high words swapped in the uniform's load; a column read one column off in a
//    block matrix's load) must change the bytes.
//  - The manifest's member offsets and matrix strides must be glslang's for the original.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "doublet/pack.hpp"
#include "test_util.hpp"

namespace doublet::runner::test {
namespace {

constexpr uint32_t kInvocations = 1024;

const char* kShader = R"(#version 450
layout(local_size_x = 64) in;
uniform dmat4 u_model;
uniform dmat3 r;
layout(std140, binding = 0) readonly buffer Mats { float s; dmat3 a; dmat2x3 b; dmat2 c; double k; };
layout(std430, binding = 1) buffer Io { float f; dmat4 m; dmat3x2 n[2]; dmat4 wm; dmat3x2 wn[2]; dvec4 v[]; } io;
layout(std430, binding = 2) buffer Outs { dmat4 om[]; };
layout(std430, binding = 3) buffer Vecs { dvec4 o[]; };
// One matrix operation per result (their order of operations is exact_matrix_test's business); the
// data come from and go to every kind of place: loose uniforms, block matrices whole, by column
// (constant and dynamic index) and by element, an array of matrices in a block.
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 x = io.v[i];
  o[6u * i] = u_model * x;
  o[6u * i + 1u] = dvec4(a * x.xyz, k);
  o[6u * i + 2u] = dvec4(b * x.zw, c[1][i & 1u] - double(s));
  o[6u * i + 3u] = io.m[i & 3u];
  o[6u * i + 4u] = dvec4(r * x.xyz, r[1][2]);
  o[6u * i + 5u] = dvec4(io.n[i & 1u][2], u_model[3][0], c[0][1]);
  io.v[i] = x * k;
  om[i] = outerProduct(x, io.m[2]);
  om[i][3][i & 3u] = r[1][2] - u_model[3][0];
  if (i == 0u) {  // members no other invocation reads
    io.wm = io.m;
    io.wm[2] = io.m[1] + dvec4(a[0], b[1][2]);
    io.wm[3][1] = io.m[0][3] * k;
    io.wn[1] = c * io.n[0];
    io.wn[0] = io.n[1];
    io.wn[0][2].y += a[2][2];
  }
}
)";

bool is_nan(uint64_t x) { return (x & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

// Finite values near 1 and random patterns (no NaN inputs: which NaN native passes on is its own).
double random_double(std::mt19937_64& rng) {
  for (;;) {
    uint64_t x = rng();
    if (rng() % 4) x = (x & 0x800FFFFFFFFFFFFFull) | (uint64_t(1013 + rng() % 22) << 52);
    if (!is_nan(x)) return bits<double>(x);
  }
}

const InterfaceVariable* find(const Manifest& m, const std::string& name) {
  for (const auto& v : m.variables)
    if (v.name == name) return &v;
  return nullptr;
}

// Doubles per element and column count of a manifest member type ("dmat2x3[2]", "dvec4[]", "double").
void shape(const std::string& type, int* doubles, int* columns) {
  *columns = 1;
  *doubles = type.rfind("double", 0) == 0 ? 1 : type.rfind("dvec", 0) == 0 ? type[4] - '0' : 0;
  if (type.rfind("dmat", 0) == 0) {
    *columns = type[4] - '0';
    const int rows = type.size() > 6 && type[5] == 'x' ? type[6] - '0' : *columns;
    *doubles = *columns * rows;
  }
}

// Random doubles at every double the manifest lists for `block` (runtime arrays: `elements`).
std::vector<uint8_t> fill(const InterfaceVariable& block, uint32_t elements, std::mt19937_64& rng) {
  std::vector<uint8_t> bytes;
  for (const BlockMember& m : block.members) {
    int doubles = 0, columns = 1;
    shape(m.type, &doubles, &columns);
    if (doubles == 0) continue;
    const int rows = doubles / columns;
    const uint32_t count = m.array_stride == 0 ? 1u : m.size ? uint32_t(m.size / m.array_stride) : elements;
    for (uint32_t e = 0; e < count; ++e)
      for (int c = 0; c < columns; ++c)
        for (int w = 0; w < rows; ++w) {
          const double x = random_double(rng);
          const size_t at = size_t(m.offset) + size_t(e) * size_t(m.array_stride) + size_t(c) * size_t(m.matrix_stride) +
                            size_t(w) * 8;
          if (bytes.size() < at + 8) bytes.resize(at + 8, 0);
          std::memcpy(bytes.data() + at, &x, 8);
        }
  }
  bytes.resize((bytes.size() + 15) / 16 * 16, 0);
  return bytes;
}

struct Case {
  Result lowered;
  std::vector<std::vector<uint8_t>> buffers;
  std::vector<double> model, rot;  // the loose uniforms' column-major doubles
  std::map<std::string, std::vector<double>> word_uniforms;
};

Case make_case() {
  Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.mode = Mode::Exact;
  Case c;
  c.lowered = lower(kShader, o);
  if (!c.lowered.ok) return c;
  std::mt19937_64 rng(2027);
  for (const char* name : {"Mats", "io"}) {
    const InterfaceVariable* block = find(c.lowered.manifest, name);
    if (!block) return c;
    c.buffers.push_back(fill(*block, kInvocations, rng));
  }
  c.buffers.push_back(std::vector<uint8_t>(size_t(kInvocations) * 128, 0));     // om[]
  c.buffers.push_back(std::vector<uint8_t>(size_t(kInvocations) * 6 * 32, 0));  // o[]
  for (int k = 0; k < 16; ++k) c.model.push_back(random_double(rng));
  for (int k = 0; k < 9; ++k) c.rot.push_back(random_double(rng));
  const auto manifest = pack::parse_manifest(c.lowered.manifest.to_json());
  if (!manifest) return c;
  for (const auto& [name, value] : {std::pair{"u_model", &c.model}, std::pair{"r", &c.rot}})
    for (const pack::UniformWords& u : pack::uniform_words(*manifest->find(name), *value))
      c.word_uniforms[u.name].assign(u.words.begin(), u.words.end());
  return c;
}

std::vector<std::vector<uint8_t>> run(Backend backend, const std::string& glsl, const Case& c, bool native) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = c.buffers;
  job.groups_x = kInvocations / 64;
  if (native) {
    job.uniforms["u_model"] = c.model;
    job.uniforms["r"] = c.rot;
  } else {
    job.uniforms = c.word_uniforms;
  }
  ComputeResult result = run_compute(backend, job);
  EXPECT_TRUE(result.ok) << backend_name(backend) << ": " << result.error;
  return result.ok ? result.buffers : std::vector<std::vector<uint8_t>>{};
}

std::string diagnostics(const Result& r) {
  std::string s;
  for (const Diagnostic& d : r.diagnostics) s += format_diagnostic(d) + "\n";
  return s;
}

TEST(ExactMatrixInterface, ManifestDescribesTheWords) {
  const Case c = make_case();
  ASSERT_TRUE(c.lowered.ok) << diagnostics(c.lowered);
  const InterfaceVariable* model = find(c.lowered.manifest, "u_model");
  ASSERT_NE(model, nullptr);
  EXPECT_EQ(model->encoding, "binary64-words");
  EXPECT_EQ(model->lowered_names, std::vector<std::string>{"u_model"});
  EXPECT_EQ(model->lowered_types, std::vector<std::string>{"uvec4[8]"});
  const InterfaceVariable* rot = find(c.lowered.manifest, "r");
  ASSERT_NE(rot, nullptr);
  EXPECT_EQ(rot->lowered_types, std::vector<std::string>{"uvec4[5]"});
  // The words are the host's bytes: dmat4 exactly, dmat3 with two zero words after its 72 bytes.
  ASSERT_EQ(c.word_uniforms.at("u_model").size(), 32u);
  ASSERT_EQ(c.word_uniforms.at("r").size(), 20u);
  for (size_t k = 0; k < 18; ++k) {
    uint32_t host;
    std::memcpy(&host, reinterpret_cast<const uint8_t*>(c.rot.data()) + 4 * k, 4);
    EXPECT_EQ(uint32_t(c.word_uniforms.at("r")[k]), host) << k;
  }
  EXPECT_EQ(c.word_uniforms.at("r")[18], 0.0);
  // Offsets and matrix strides are glslang's for the original blocks.
  ShaderInterface native;
  std::string error;
  ASSERT_TRUE(reflect_compute(kShader, &native, &error)) << error;
  int checked = 0;
  for (const auto& m : native.members) {
    const std::string block = native.blocks[size_t(m.block)].name;
    const InterfaceVariable* v = find(c.lowered.manifest, block == "Io" ? "io" : block);
    if (!v) continue;
    std::string name = m.name.rfind("Io.", 0) == 0 ? m.name.substr(3) : m.name;
    if (const size_t bracket = name.find("[0]"); bracket != std::string::npos && bracket + 3 == name.size())
      name = name.substr(0, bracket);
    for (const BlockMember& bm : v->members) {
      if (bm.name != name) continue;
      EXPECT_EQ(uint32_t(bm.offset), m.offset) << block << "." << name;
      if (bm.array_stride) EXPECT_EQ(uint32_t(bm.array_stride), m.array_stride) << name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 8);
}

TEST(ExactMatrixInterface, PackedUniformWordsRejectWrongSizes) {
  pack::Variable v;
  v.name = "M";
  v.type = "dmat2x3[2]";
  v.encoding = "binary64-words";
  v.lowered_names = {"M"};
  v.lowered_types = {"uvec4[6]"};
  std::vector<double> x(12);
  for (size_t k = 0; k < x.size(); ++k) x[k] = 0.5 + double(k);
  const auto w = pack::uniform_words(v, x);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].components, 4);
  EXPECT_EQ(w[0].count, 6);
  ASSERT_EQ(w[0].words.size(), 24u);
  EXPECT_EQ(std::memcmp(w[0].words.data(), x.data(), 96), 0) << "the host's bytes, unchanged";
  x.pop_back();
  EXPECT_TRUE(pack::uniform_words(v, x).empty()) << "11 doubles for a dmat2x3[2]";
  v.lowered_types = {"uvec4[5]"};
  x.push_back(1.0);
  EXPECT_TRUE(pack::uniform_words(v, x).empty()) << "a lowered array too small for the doubles";
}

TEST(ExactMatrixInterface, SameBytesAsNativeFp64) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const Case c = make_case();
  ASSERT_TRUE(c.lowered.ok) << diagnostics(c.lowered);
  ASSERT_EQ(c.buffers.size(), 4u);
  const auto native = run(Backend::Vulkan, kShader, c, true);
  ASSERT_EQ(native.size(), 4u);
  EXPECT_NE(differing_bytes(native, c.buffers), 0u) << "the shader wrote nothing";
  size_t bytes = 0;
  for (const auto& b : native) bytes += b.size();
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const auto got = run(backend, c.lowered.output, c, false);
    const size_t differing = differing_bytes(got, native);
    for (size_t b = 0; b < got.size() && b < native.size() && got[b].size() == native[b].size(); ++b)
      for (size_t at = 0, shown = 0; at + 8 <= got[b].size() && shown < 8; at += 8)
        if (std::memcmp(got[b].data() + at, native[b].data() + at, 8) != 0) {
          uint64_t g, n;
          std::memcpy(&g, got[b].data() + at, 8);
          std::memcpy(&n, native[b].data() + at, 8);
          std::cout << "  buffer " << b << " byte " << at << ": 0x" << std::hex << g << " native 0x" << n << std::dec
                    << "\n";
          ++shown;
        }
    std::cout << "[ exact ] double matrices across the interface on " << backend_name(backend) << ": " << differing
              << " of " << bytes << " output bytes differ from native fp64\n";
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
}

TEST(ExactMatrixInterface, SabotagedWordsOrColumnsDiffer) {
  REQUIRE_BACKEND(Backend::Vulkan);
  const Case c = make_case();
  ASSERT_TRUE(c.lowered.ok) << diagnostics(c.lowered);
  const auto native = run(Backend::Vulkan, kShader, c, true);
  // The uniform's load with low and high words swapped.
  std::smatch load;
  const std::string& text = c.lowered.output;
  ASSERT_TRUE(std::regex_search(text, load, std::regex(R"(  u_model_value = [^\n]*\n)")));
  std::string line = load.str(0);
  for (char& ch : line) ch = ch == 'x' ? 'y' : ch == 'y' ? 'x' : ch == 'z' ? 'w' : ch == 'w' ? 'z' : ch;
  line.replace(0, line.find(" = "), "  u_model_value");  // the name keeps its letters
  std::string swapped = text;
  swapped.replace(size_t(load.position(0)), load.length(0), line);
  const size_t swapped_differ = differing_bytes(run(Backend::Vulkan, swapped, c, false), native);
  // A block matrix's column read one column off (dmat3's column 1 from column 2's words).
  const std::string column = "df_dvec3 c1 = ex_load_dvec3(w.c[1]);";
  ASSERT_NE(text.find(column), std::string::npos);
  std::string shifted = text;
  shifted.replace(shifted.find(column), column.size(), "df_dvec3 c1 = ex_load_dvec3(w.c[2]);");
  const size_t shifted_differ = differing_bytes(run(Backend::Vulkan, shifted, c, false), native);
  std::cout << "[ exact ] matrices with swapped words: " << swapped_differ << " bytes differ; a column off: "
            << shifted_differ << "\n";
  EXPECT_GT(swapped_differ, 0u);
  EXPECT_GT(shifted_differ, 0u);
}

// Matrices inside structs in blocks: a std140 array of structs holding a dmat3, a struct holding a
// struct and a dmat2x3, and a std430 array of such structs written whole. Read and written in
// place (the struct's twin holds each matrix's column words as a block member's), same bytes as
// native fp64 on both drivers; a column read one off in the struct's load must differ.
const char* kStructShader = R"(#version 450
layout(local_size_x = 64) in;
struct Frame { dmat3 rot; dvec3 origin; double scale[2]; };
struct Node { Frame frame; dmat2x3 skew; };
layout(std140, binding = 0) readonly buffer Scene { vec4 pad; Frame frames[4]; Node node; };
layout(std430, binding = 1) readonly buffer In { dvec4 v[]; };
layout(std430, binding = 2) writeonly buffer Out { dvec4 o[]; };
layout(std430, binding = 3) writeonly buffer Written { Frame written[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 x = v[i];
  Frame f = frames[i & 3u];
  o[4u * i] = dvec4(f.rot * x.xyz + f.origin, f.scale[i & 1u]);
  o[4u * i + 1u] = dvec4(frames[(i + 1u) & 3u].rot[i % 3u], node.frame.scale[0]);
  o[4u * i + 2u] = dvec4(node.skew * x.zw, node.frame.rot[2][1]);
  o[4u * i + 3u] = dvec4(node.frame.rot * f.origin, double(pad.y));
  written[i] = Frame(f.rot * dmat3(x.w), x.xyz, double[2](x.x, f.scale[1]));
}
)";

// Doubles near 1 (exponents 2^-10 .. 2^11, random signs and significands): no NaN, no overflow.
std::vector<uint8_t> near_one_doubles(size_t count, std::mt19937_64& rng) {
  std::vector<uint8_t> bytes(count * 8);
  for (size_t k = 0; k < count; ++k) {
    const uint64_t x = (rng() & 0x800FFFFFFFFFFFFFull) | (uint64_t(1013 + rng() % 22) << 52);
    std::memcpy(bytes.data() + 8 * k, &x, 8);
  }
  return bytes;
}

std::vector<std::vector<uint8_t>> run_struct_shader(Backend backend, const std::string& glsl,
                                                    const std::vector<std::vector<uint8_t>>& buffers) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = buffers;
  job.groups_x = kInvocations / 64;
  ComputeResult result = run_compute(backend, job);
  EXPECT_TRUE(result.ok) << backend_name(backend) << ": " << result.error;
  return result.ok ? result.buffers : std::vector<std::vector<uint8_t>>{};
}

TEST(ExactMatrixInterface, MatricesInStructsInBlocksKeepNativesBytes) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.mode = Mode::Exact;
  const Result lowered = lower(kStructShader, o);
  ASSERT_TRUE(lowered.ok) << diagnostics(lowered);
  std::mt19937_64 rng(2028);
  std::vector<std::vector<uint8_t>> buffers = {near_one_doubles(256, rng), near_one_doubles(4 * kInvocations, rng),
                                               std::vector<uint8_t>(size_t(kInvocations) * 4 * 32, 0),
                                               std::vector<uint8_t>(size_t(kInvocations) * 160, 0)};
  const float pad[4] = {0.0f, 1.25f, 0.0f, 0.0f};  // pad.y: a float, not the low half of a double
  std::memcpy(buffers[0].data(), pad, sizeof pad);
  const auto native = run_struct_shader(Backend::Vulkan, kStructShader, buffers);
  ASSERT_EQ(native.size(), 4u);
  EXPECT_NE(differing_bytes(native, buffers), 0u) << "the shader wrote nothing";
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const size_t differing = differing_bytes(run_struct_shader(backend, lowered.output, buffers), native);
    std::cout << "[ exact ] matrices in structs in blocks on " << backend_name(backend) << ": " << differing
              << " output bytes differ from native fp64\n";
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
  const std::string column = "df_dvec3 c1 = ex_load_dvec3(w.c[1]);";
  ASSERT_NE(lowered.output.find(column), std::string::npos) << lowered.output;
  std::string shifted = lowered.output;
  shifted.replace(shifted.find(column), column.size(), "df_dvec3 c1 = ex_load_dvec3(w.c[2]);");
  const size_t shifted_differ = differing_bytes(run_struct_shader(Backend::Vulkan, shifted, buffers), native);
  std::cout << "[ exact ] a struct's matrix column read one off: " << shifted_differ << " bytes differ\n";
  EXPECT_GT(shifted_differ, 0u);
}

TEST(ExactMatrixInterface, InOutAndRowMajorMatricesAreDiagnosed) {
  Options o;
  o.mode = Mode::Exact;
  o.target = Target::Es300;
  o.stage = Stage::Vertex;
  const Result in = lower("#version 450\nlayout(location = 0) in dmat4 m;\nvoid main() { gl_Position = vec4(m[0]); }\n", o);
  ASSERT_FALSE(in.ok);
  EXPECT_NE(diagnostics(in).find("2:"), std::string::npos) << diagnostics(in);
  EXPECT_NE(diagnostics(in).find("pass its columns as dvecN inputs"), std::string::npos) << diagnostics(in);
  const Result row = lower("#version 450\nlayout(std140, row_major) uniform U { dmat3 m; };\n"
                           "void main() { gl_Position = vec4(m[0], 1.0); }\n", o);
  ASSERT_FALSE(row.ok);
  EXPECT_NE(diagnostics(row).find("row_major"), std::string::npos) << diagnostics(row);
  // A struct's matrix in a row_major block: the same refusal, at the block.
  const Result nested = lower("#version 450\nstruct S { dmat3 m; };\nlayout(std140, row_major) uniform U { S s; };\n"
                              "void main() { gl_Position = vec4(s.m[0], 1.0); }\n", o);
  ASSERT_FALSE(nested.ok);
  EXPECT_NE(diagnostics(nested).find("row_major"), std::string::npos) << diagnostics(nested);
  // ... and in a struct member declared row_major.
  const Result member = lower("#version 450\nstruct S { dmat3 m; };\nlayout(std140) uniform U { layout(row_major) S s; };\n"
                              "void main() { gl_Position = vec4(s.m[0], 1.0); }\n", o);
  ASSERT_FALSE(member.ok);
  EXPECT_NE(diagnostics(member).find("row_major"), std::string::npos) << diagnostics(member);
}

}  // namespace
}  // namespace doublet::runner::test
