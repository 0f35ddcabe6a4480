// Mode exact's interface (docs/modes.md, "exact": interface): a host's raw doubles are the data.
//  - Storage blocks (std430 and std140, anonymous and named, writeonly, structs, arrays of dvec3/dvec4): the
//    same input bytes given to the original shader on native fp64 (lavapipe) and to the lowered
//    one (lavapipe, Mesa GLES) must leave the same output bytes; the manifest's member offsets must
//    be glslang's for the original. Sabotages: the words swapped in the load, a padding member
//    dropped — both must change the bytes.
//  - A vertex shader's double attributes (raw host vertex memory through pack::word_attributes),
//    loose uniforms (pack::uniform_words) and a std140 uniform block (the host's bytes) against the
//    host's IEEE arithmetic.
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

constexpr uint32_t kInvocations = 4096;

const char* kBlocks = R"(#version 450
layout(local_size_x = 64) in;
struct P { dvec3 pos; float w; double m; dvec4 q[2]; };
layout(std430, binding = 0) buffer In { float f; dvec3 v3; double d[]; } inb;
layout(std140, binding = 1) buffer Consts { float s; dvec4 v4; double k; dvec2 v2[2]; dvec3 v3s[2]; };
layout(std430, binding = 2) buffer Ps { int n; P p[]; };
layout(std430, binding = 3) writeonly buffer Outs { float of; dvec3 o3; double od[]; };
void bump(inout double x) { x += 1.0; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  od[i] = inb.d[i] - k;
  inb.d[i] = inb.d[i] * k + v4.y;
  bump(inb.d[i]);
  P q = p[i];
  q.pos += q.q[1].xyz + v3s[i & 1u];
  q.m = q.m - v2[1].x;
  p[i] = q;
  p[i].q[0].w = double(n) + q.m;
  if (i == 0u) {
    inb.v3.y += v2[0].y;
    v4.w = k * s;
    o3 = q.pos;
  }
}
)";

bool is_nan(uint64_t x) { return (x & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

// Finite values and infinities (no NaN inputs: which NaN native passes on is its own choice).
double random_double(std::mt19937_64& rng) {
  for (;;) {
    uint64_t x = rng();
    if (rng() % 2) x = (x & 0x800FFFFFFFFFFFFFull) | (uint64_t(1000 + rng() % 48) << 52);  // near 1
    if (!is_nan(x)) return bits<double>(x);
  }
}

const InterfaceVariable* find_block(const Manifest& m, const std::string& name) {
  for (const auto& v : m.variables)
    if (v.name == name) return &v;
  return nullptr;
}

// Random doubles at every double the manifest lists for `block` (runtime arrays: `elements`),
// zeros elsewhere; the int member `n` gets 7.
std::vector<uint8_t> fill(const InterfaceVariable& block, uint32_t elements, std::mt19937_64& rng) {
  std::vector<uint8_t> bytes;
  auto put = [&](size_t at, const void* x, size_t size) {
    if (bytes.size() < at + size) bytes.resize(at + size, 0);
    std::memcpy(bytes.data() + at, x, size);
  };
  auto count_of = [&](const BlockMember& m) { return m.array_stride == 0 ? 1u : m.size ? uint32_t(m.size / m.array_stride) : elements; };
  for (const BlockMember& m : block.members) {
    if (m.name == "n") {
      const int32_t seven = 7;
      put(size_t(m.offset), &seven, 4);
    }
    const int components = m.type.rfind("double", 0) == 0 ? 1 : m.type.rfind("dvec", 0) == 0 ? m.type[4] - '0' : 0;
    if (components == 0) continue;
    // A member of element 0 of a struct array ("p[0].pos"): repeated over that array's elements.
    uint32_t outer = 1, outer_stride = 0;
    if (const size_t at = m.name.find("[0]."); at != std::string::npos)
      for (const BlockMember& parent : block.members)
        if (parent.name == m.name.substr(0, at)) outer = count_of(parent), outer_stride = uint32_t(parent.array_stride);
    for (uint32_t o = 0; o < outer; ++o)
      for (uint32_t e = 0; e < count_of(m); ++e)
        for (int c = 0; c < components; ++c) {
          const double x = random_double(rng);
          put(size_t(m.offset) + size_t(o) * outer_stride + size_t(e) * size_t(m.array_stride) + size_t(c) * 8, &x, 8);
        }
  }
  bytes.resize((bytes.size() + 15) / 16 * 16, 0);
  return bytes;
}

std::vector<std::vector<uint8_t>> run(Backend backend, const std::string& glsl, const std::vector<std::vector<uint8_t>>& in) {
  ComputeJob job;
  job.glsl = glsl;
  job.buffers = in;
  job.groups_x = kInvocations / 64;
  ComputeResult r = run_compute(backend, job);
  EXPECT_TRUE(r.ok) << backend_name(backend) << ": " << r.error;
  return r.ok ? r.buffers : std::vector<std::vector<uint8_t>>{};
}

struct Lowered {
  Result result;
  std::vector<std::vector<uint8_t>> inputs;
};

Lowered lower_blocks() {
  Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.mode = Mode::Exact;
  Lowered l;
  l.result = lower(kBlocks, o);
  if (!l.result.ok) return l;
  std::mt19937_64 rng(2026);
  for (const char* name : {"inb", "Consts", "Ps", "Outs"}) {
    const InterfaceVariable* block = find_block(l.result.manifest, name);
    if (!block) return l;
    l.inputs.push_back(fill(*block, kInvocations, rng));
  }
  return l;
}

TEST(ExactInterface, ManifestOffsetsAreTheOriginalBlocks) {
  Lowered l = lower_blocks();
  ASSERT_TRUE(l.result.ok);
  ShaderInterface native;
  std::string error;
  ASSERT_TRUE(reflect_compute(kBlocks, &native, &error)) << error;
  int checked = 0;
  for (const auto& m : native.members) {
    const std::string block = native.blocks[size_t(m.block)].name;
    const InterfaceVariable* v = find_block(l.result.manifest, block == "In" ? "inb" : block);
    ASSERT_NE(v, nullptr) << block;
    std::string name = m.name.rfind("In.", 0) == 0 ? m.name.substr(3) : m.name;
    if (const size_t dot = name.find('.'); dot != std::string::npos && name.find('[') == std::string::npos)
      name = name.substr(0, dot) + "[0]" + name.substr(dot);  // reflection says p.pos for p[0].pos
    for (const BlockMember& bm : v->members) {
      if (bm.name != name) continue;
      EXPECT_EQ(uint32_t(bm.offset), m.offset) << block << "." << name;
      if (m.array_size != 1 && bm.array_stride) EXPECT_EQ(uint32_t(bm.array_stride), m.array_stride) << name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 12);
  for (const auto& v : l.result.manifest.variables) EXPECT_EQ(v.encoding, "binary64-words") << v.name;
}

TEST(ExactInterface, BlocksReadAndWriteTheOriginalBytes) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  Lowered l = lower_blocks();
  std::string diagnostics;
  for (const Diagnostic& d : l.result.diagnostics) diagnostics += format_diagnostic(d) + "\n";
  ASSERT_TRUE(l.result.ok) << diagnostics;
  ASSERT_EQ(l.inputs.size(), 4u);
  const auto native = run(Backend::Vulkan, kBlocks, l.inputs);
  ASSERT_EQ(native.size(), 4u);
  EXPECT_NE(differing_bytes(native, l.inputs), 0u) << "the shader wrote nothing";
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const size_t differing = differing_bytes(run(backend, l.result.output, l.inputs), native);
    std::cout << "[ exact ] blocks on " << backend_name(backend) << ": " << differing
              << " bytes differ from native fp64\n";
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
}

TEST(ExactInterface, SabotagedWordsOrPaddingDiffer) {
  REQUIRE_BACKEND(Backend::Vulkan);
  Lowered l = lower_blocks();
  ASSERT_TRUE(l.result.ok);
  const auto native = run(Backend::Vulkan, kBlocks, l.inputs);
  const std::string load = "return df_double(w.y, w.x);";
  std::string swapped = l.result.output;
  ASSERT_NE(swapped.find(load), std::string::npos);
  swapped.replace(swapped.find(load), load.size(), "return df_double(w.x, w.y);");
  const size_t swapped_differ = differing_bytes(run(Backend::Vulkan, swapped, l.inputs), native);
  // The last padding member before inb's v3 (16 bytes): without it v3 and d[] move.
  std::smatch pad;
  ASSERT_TRUE(std::regex_search(l.result.output, pad, std::regex(R"(  uvec4 ex_pad\d+;\n  uvec4 v3_xy;)")));
  std::string unpadded = l.result.output;
  unpadded.replace(size_t(pad.position(0)), pad.str(0).find('\n') + 1, "");
  const size_t unpadded_differ = differing_bytes(run(Backend::Vulkan, unpadded, l.inputs), native);
  std::cout << "[ exact ] blocks with swapped words: " << swapped_differ << " bytes differ; without a pad: "
            << unpadded_differ << "\n";
  EXPECT_GT(swapped_differ, 0u);
  EXPECT_GT(unpadded_differ, 0u);
}

// ---- vertex stage: attributes, loose uniforms and a uniform block from the host's raw doubles ----

const char* kVertex = R"(#version 450
layout(location = 0) in double a;
layout(location = 1) in dvec2 b;
layout(location = 2) in dvec3 c;
layout(location = 4) in dvec4 d;
uniform double u;
uniform dvec3 e;
layout(std140, binding = 0) uniform Params { float s; dvec3 g; double h[2]; };
flat out dvec3 r;
flat out double t;
void main() {
  r = c + d.xyz * e + g;
  t = a - b.y * u + h[1];
  gl_Position = vec4(0.0);
}
)";

struct Vertex {  // the host's vertex: the shader's inputs in order, as doubles
  double a, b[2], c[3], d[4];
};

TEST(ExactInterface, VertexAttributesUniformsAndBlockFromRawDoubles) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es300;
  o.mode = Mode::Exact;
  const Result lowered = lower(kVertex, o);
  ASSERT_TRUE(lowered.ok);
  std::string error;
  const auto manifest = pack::parse_manifest(lowered.manifest.to_json(), &error);
  ASSERT_TRUE(manifest) << error;

  constexpr uint32_t kCount = 2048;
  std::mt19937_64 rng(7);
  std::vector<Vertex> vertices(kCount);
  for (Vertex& v : vertices) {
    v.a = random_double(rng);
    for (double& x : v.b) x = random_double(rng);
    for (double& x : v.c) x = random_double(rng);
    for (double& x : v.d) x = random_double(rng);
  }
  const double u = random_double(rng), e[3] = {random_double(rng), random_double(rng), random_double(rng)};
  const double g[3] = {random_double(rng), random_double(rng), random_double(rng)}, h1 = random_double(rng);

  GraphicsJob job;
  job.glsl = lowered.output;
  job.count = kCount;
  // Attributes: the host's vertex memory as uint words, where word_attributes says.
  const size_t offsets[] = {offsetof(Vertex, a), offsetof(Vertex, b), offsetof(Vertex, c), offsetof(Vertex, d)};
  const char* inputs[] = {"a", "b", "c", "d"};
  for (int k = 0; k < 4; ++k) {
    const auto attributes = pack::word_attributes(*manifest->find(inputs[k]), offsets[k]);
    ASSERT_FALSE(attributes.empty()) << inputs[k];
    for (const pack::WordAttribute& at : attributes) {
      std::vector<double>& words = job.inputs[at.name];
      for (const Vertex& v : vertices)
        for (int w = 0; w < at.components; ++w) {
          uint32_t word;
          std::memcpy(&word, reinterpret_cast<const uint8_t*>(&v) + at.offset_bytes + 4 * size_t(w), 4);
          words.push_back(word);
        }
    }
  }
  for (const auto& uw : pack::uniform_words(*manifest->find("u"), {u}))
    job.uniforms[uw.name].assign(uw.words.begin(), uw.words.end());
  for (const auto& uw : pack::uniform_words(*manifest->find("e"), {e[0], e[1], e[2]}))
    job.uniforms[uw.name].assign(uw.words.begin(), uw.words.end());
  ASSERT_EQ(job.uniforms.size(), 3u);  // u, e_xy, e_z
  // The block: std140 bytes of the doubles, at the original offsets (g at 32, h[] at 64, stride 16).
  std::vector<uint8_t> params(96, 0);
  std::memcpy(params.data() + 32, g, sizeof g);
  std::memcpy(params.data() + 64 + 16, &h1, 8);
  job.uniform_blocks["Params"] = params;

  std::vector<uint64_t> want_r(3 * size_t(kCount)), want_t(kCount);
  for (uint32_t i = 0; i < kCount; ++i) {
    const Vertex& v = vertices[i];
    for (int c = 0; c < 3; ++c) {
      volatile double product = v.d[c] * e[c], sum = v.c[c] + product, r = sum + g[c];
      want_r[3 * size_t(i) + size_t(c)] = bits<uint64_t>(double(r));
    }
    volatile double product = v.b[1] * u, difference = v.a - product, t = difference + h1;
    want_t[i] = bits<uint64_t>(double(t));
  }
  auto word_pairs = [](const std::vector<double>& words, size_t first, size_t stride, size_t count, size_t i) {
    std::vector<uint64_t> out;
    for (size_t k = 0; k < count; ++k)
      out.push_back(uint64_t(words[i * stride + first + 2 * k]) | uint64_t(words[i * stride + first + 2 * k + 1]) << 32);
    return out;
  };
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const GraphicsResult got = run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << backend_name(backend) << ": " << got.error;
    uint32_t differing = 0;
    for (uint32_t i = 0; i < kCount; ++i) {
      std::vector<uint64_t> r = word_pairs(got.outputs.at("r_xy"), 0, 4, 2, i);
      r.push_back(word_pairs(got.outputs.at("r_z"), 0, 2, 1, i)[0]);
      const uint64_t t = word_pairs(got.outputs.at("t"), 0, 2, 1, i)[0];
      for (int c = 0; c < 3; ++c) {
        const uint64_t want = want_r[3 * size_t(i) + size_t(c)];
        differing += r[size_t(c)] != want && !(is_nan(r[size_t(c)]) && is_nan(want));
      }
      differing += t != want_t[i] && !(is_nan(t) && is_nan(want_t[i]));
    }
    std::cout << "[ exact ] vertex attributes, uniforms, block on " << backend_name(backend) << ": " << differing
              << " of " << 4 * kCount << " results differ from the host's IEEE arithmetic\n";
    EXPECT_EQ(differing, 0u) << backend_name(backend);
  }
}

TEST(ExactInterface, UniformWordsKeepTheHostBytes) {
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es300;
  o.mode = Mode::Exact;
  const Result lowered =
      lower("#version 450\nuniform double u[2];\nuniform dvec2 v;\nuniform dvec4 w;\n"
            "void main() { gl_Position = vec4(float(u[1] + v.y + w.w)); }\n",
            o);
  ASSERT_TRUE(lowered.ok);
  const auto manifest = pack::parse_manifest(lowered.manifest.to_json());
  ASSERT_TRUE(manifest);
  const double u[2] = {1.5, -0x1p-1074}, v[2] = {3.0, 1e300}, w[4] = {0.25, -0.0, 7.0, 1.0 / 3};
  const auto uw = pack::uniform_words(*manifest->find("u"), u);
  ASSERT_EQ(uw.size(), 1u);
  EXPECT_EQ(uw[0].name, "u");
  EXPECT_EQ(uw[0].components, 2);
  EXPECT_EQ(uw[0].count, 2);
  ASSERT_EQ(uw[0].words.size(), 4u);
  EXPECT_EQ(std::memcmp(uw[0].words.data(), u, sizeof u), 0) << "uvec2 u[2] takes the host's bytes";
  const auto vw = pack::uniform_words(*manifest->find("v"), v);
  ASSERT_EQ(vw.size(), 1u);
  EXPECT_EQ(vw[0].components, 4);
  EXPECT_EQ(std::memcmp(vw[0].words.data(), v, sizeof v), 0);
  const auto ww = pack::uniform_words(*manifest->find("w"), w);
  ASSERT_EQ(ww.size(), 2u);
  EXPECT_EQ(ww[0].name, "w_xy");
  EXPECT_EQ(ww[1].name, "w_zw");
  EXPECT_EQ(std::memcmp(ww[0].words.data(), w, 16), 0);
  EXPECT_EQ(std::memcmp(ww[1].words.data(), w + 2, 16), 0);
  EXPECT_TRUE(pack::uniform_words(*manifest->find("u"), {1.0}).empty()) << "size mismatch";
}

// A loose uniform of a struct type: its twin Light_words, each double member a word leaf the host
// sets from the manifest ("light.pos_xy", "light.pos_z", "light.k").
TEST(ExactInterface, StructUniformLeavesAreWords) {
  REQUIRE_BACKEND(Backend::Vulkan);
  REQUIRE_BACKEND(Backend::Gles);
  const char* source = "#version 450\nstruct Light { dvec3 pos; float w; double k; };\nuniform Light light;\n"
                       "flat out dvec3 r;\nvoid main() { r = light.pos * light.k; gl_Position = vec4(light.w); }\n";
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es300;
  o.mode = Mode::Exact;
  const Result lowered = lower(source, o);
  ASSERT_TRUE(lowered.ok);
  const InterfaceVariable* light = find_block(lowered.manifest, "light");
  ASSERT_NE(light, nullptr);
  EXPECT_EQ(light->encoding, "binary64-words");
  EXPECT_EQ(light->lowered_names, (std::vector<std::string>{"light.pos_xy", "light.pos_z", "light.w", "light.k"}));
  const double pos[3] = {0x1.8p1000, -0x1p-1070, 3.25}, k = -0x1.123456789abcdp-40;
  GraphicsJob job;
  job.glsl = lowered.output;
  job.count = 1;
  std::vector<double>& xy = job.uniforms["light.pos_xy"];
  std::vector<double>& z = job.uniforms["light.pos_z"];
  std::vector<double>& kw = job.uniforms["light.k"];
  for (int c = 0; c < 3; ++c) {
    const ExactWords w = exact_words(pos[c]);
    (c < 2 ? xy : z).insert((c < 2 ? xy : z).end(), {double(w.lo), double(w.hi)});
  }
  kw = {double(exact_words(k).lo), double(exact_words(k).hi)};
  for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
    const GraphicsResult got = run_graphics(backend, job);
    ASSERT_TRUE(got.ok) << backend_name(backend) << ": " << got.error;
    const std::vector<double>& r_xy = got.outputs.at("r_xy");
    const std::vector<double>& r_z = got.outputs.at("r_z");
    for (int c = 0; c < 3; ++c) {
      const double* w = c < 2 ? &r_xy[2 * size_t(c)] : &r_z[0];
      volatile double want = pos[c] * k;
      EXPECT_EQ(exact_join({uint32_t(w[0]), uint32_t(w[1])}), double(want)) << backend_name(backend) << " r." << c;
    }
  }
}

// What the exact interface refuses, with a position and no internal error.
TEST(ExactInterface, NameCollisionsAreDiagnosed) {
  Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es300;
  o.mode = Mode::Exact;
  const Result taken = lower("#version 450\nin double a;\nfloat a_value;\n"
                             "void main() { a_value = 1.0; gl_Position = vec4(float(a)); }\n", o);
  ASSERT_FALSE(taken.ok);
  std::string errors;
  for (const Diagnostic& d : taken.diagnostics) errors += format_diagnostic(d) + "\n";
  EXPECT_NE(errors.find("<stdin>:2:"), std::string::npos) << errors;
  EXPECT_NE(errors.find("'a_value'"), std::string::npos) << errors;
  EXPECT_EQ(errors.find("internal error"), std::string::npos) << errors;
}

}  // namespace
}  // namespace doublet::runner::test
