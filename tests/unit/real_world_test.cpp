// Constructs of real-world shaders (issue 12): every shader glslang accepts is lowered or
// refused with a diagnostic that names the construct, the target and what to do instead —
// never an internal error. Golden cases (tests/golden/cases) show the lowered text; these
// tests check the diagnostics.
#include <gtest/gtest.h>

#include <string>

#include "doublet/doublet.hpp"

namespace {

using doublet::Severity;
using doublet::Stage;
using doublet::Target;

doublet::Result lower(const std::string& source, Stage stage, Target target) {
  doublet::Options o;
  o.stage = stage;
  o.target = target;
  o.file_name = "real.glsl";
  return doublet::lower(source, o);
}

std::string messages(const doublet::Result& r) {
  std::string s;
  for (const auto& d : r.diagnostics) s += doublet::format_diagnostic(d) + "\n";
  return s;
}

// The diagnostic of `severity` whose message contains `fragment`, or null.
const doublet::Diagnostic* find(const doublet::Result& r, Severity severity, const std::string& fragment) {
  for (const auto& d : r.diagnostics)
    if (d.severity == severity && d.message.find(fragment) != std::string::npos) return &d;
  return nullptr;
}

void expect_no_internal_error(const doublet::Result& r) {
  EXPECT_EQ(messages(r).find("internal error"), std::string::npos) << messages(r);
}

const char* kPrecise = R"(#version 450
uniform double u;
out vec4 color;
void main() {
  precise double a = u * 3.0lf;
  color = vec4(float(a));
}
)";

TEST(RealWorld, UserPreciseIsDroppedWithAWarningWhereTheTargetLacksIt) {
  for (Target t : {Target::Es100, Target::Es300, Target::Es310, Target::Glsl330}) {
    auto r = lower(kPrecise, Stage::Fragment, t);
    EXPECT_TRUE(r.ok) << messages(r);
    const auto* w = find(r, Severity::Warning, "'precise' on 'a' is dropped: target " + std::string(to_string(t)));
    ASSERT_NE(w, nullptr) << messages(r);
    EXPECT_EQ(w->line, 5);
    EXPECT_EQ(r.output.find("precise df_double"), std::string::npos);
  }
  for (Target t : {Target::Es320, Target::Glsl450}) {
    auto r = lower(kPrecise, Stage::Fragment, t);
    EXPECT_TRUE(r.ok) << messages(r);
    EXPECT_EQ(find(r, Severity::Warning, "'precise'"), nullptr) << messages(r);
    EXPECT_NE(r.output.find("precise df_double a"), std::string::npos);
  }
}

// Mode exact's runtime is ex_*: a user function of that name would collide with it in the lowered
// text (ex_add(df_double, df_double) twice), so the prefix is reserved there, like df_ everywhere.
TEST(RealWorld, ExPrefixIsReservedInModeExactOnly) {
  const char* source = "#version 450\nlayout(local_size_x = 1) in;\nlayout(std430, binding = 0) buffer B { double x; };\n"
                       "double ex_add(double a, double b) { return a - b; }\nvoid main() { x = ex_add(x, 1.0lf); }\n";
  doublet::Options o;
  o.stage = Stage::Compute;
  o.target = Target::Es310;
  o.file_name = "user.comp";
  for (doublet::Mode mode : {doublet::Mode::Exact, doublet::Mode::RteExact}) {
    o.mode = mode;
    const doublet::Result r = doublet::lower(source, o);
    EXPECT_FALSE(r.ok);
    ASSERT_FALSE(r.diagnostics.empty());
    EXPECT_EQ(doublet::format_diagnostic(r.diagnostics[0]).rfind("user.comp:4:", 0), 0u) << messages(r);
    EXPECT_NE(messages(r).find("prefix 'ex_'"), std::string::npos) << messages(r);
  }
  o.mode = doublet::Mode::Df64;
  const doublet::Result df64 = doublet::lower(source, o);
  EXPECT_TRUE(df64.ok) << messages(df64);
}

// fp32 demotes `double exp(double)` to `float exp(float)`: a redefinition of ES 1.00's built-in,
// which glslang refuses there (it accepts overloads, so the rename was skipped): internal error.
TEST(RealWorld, DemotedOverloadOfABuiltinNameIsRenamedOnEs100) {
  const char* source = "#version 450\nuniform double s;\nout float shade;\n"
                       "double exp(double x) { return 1.0lf + x; }\n"
                       "void main() { shade = float(exp(s)); gl_Position = vec4(0.0); }\n";
  doublet::Options o;
  o.stage = Stage::Vertex;
  o.target = Target::Es100;
  o.mode = doublet::Mode::Fp32;
  const doublet::Result r = doublet::lower(source, o);
  expect_no_internal_error(r);
  EXPECT_TRUE(r.ok) << messages(r);
  EXPECT_NE(r.output.find("float exp_user(float x)"), std::string::npos) << r.output;
}

}  // namespace

namespace {

const char* kBlockVertex = R"(#version 450
in dvec3 position;
out VertexData { flat dvec3 world; vec2 uv; } vout;
void main() { vout.world = position; vout.uv = vec2(position.xy); gl_Position = vec4(position, 1.0); }
)";
const char* kBlockFragment = R"(#version 450
in VertexData { flat dvec3 world; vec2 uv; };
out vec4 color;
void main() { color = vec4(vec3(world), uv.x); }
)";

// lowered_names of the manifest's variables of `storage` that came from `block`.
std::vector<std::string> flattened_names(const doublet::Result& r, const std::string& storage, const std::string& block) {
  std::vector<std::string> names;
  for (const auto& v : r.manifest.variables)
    if (v.storage == storage && v.block == block) names.insert(names.end(), v.lowered_names.begin(), v.lowered_names.end());
  return names;
}

TEST(RealWorld, InOutBlocksFlattenToMatchingVaryingsWhereTheTargetLacksThem) {
  for (Target t : {Target::Es100, Target::Es300, Target::Es310}) {
    auto vert = lower(kBlockVertex, Stage::Vertex, t);
    auto frag = lower(kBlockFragment, Stage::Fragment, t);
    ASSERT_TRUE(vert.ok) << messages(vert);
    ASSERT_TRUE(frag.ok) << messages(frag);
    const std::vector<std::string> expected{"VertexData_world_hi", "VertexData_world_lo", "VertexData_uv"};
    const std::string out = t == Target::Es100 ? "varying" : "out";
    const std::string in = t == Target::Es100 ? "varying" : "in";
    EXPECT_EQ(flattened_names(vert, out, "VertexData"), expected) << vert.manifest.to_json();
    EXPECT_EQ(flattened_names(frag, in, "VertexData"), expected) << frag.manifest.to_json();
    EXPECT_NE(vert.manifest.to_json().find("\"block\": \"VertexData\""), std::string::npos);
  }
  for (Target t : {Target::Es320, Target::Glsl330, Target::Glsl450}) {  // these keep the block
    auto vert = lower(kBlockVertex, Stage::Vertex, t);
    ASSERT_TRUE(vert.ok) << messages(vert);
    EXPECT_NE(vert.output.find("out VertexData {\n  flat df_dvec3 world;"), std::string::npos) << vert.output;
  }
}

TEST(RealWorld, AnArrayOfInOutBlocksIsRefusedWhereItWouldBeFlattened) {
  const char* source = R"(#version 450
out Data { flat double d; } outs[2];
void main() { outs[0].d = 1.0lf; outs[1].d = 2.0lf; gl_Position = vec4(0.0); }
)";
  auto r = lower(source, Stage::Vertex, Target::Es300);
  EXPECT_FALSE(r.ok);
  expect_no_internal_error(r);
  const auto* e = find(r, Severity::Error, "output block 'Data' is an array, which cannot be flattened");
  ASSERT_NE(e, nullptr) << messages(r);
  EXPECT_EQ(e->line, 2);
  EXPECT_NE(e->message.find("es300"), std::string::npos);
  EXPECT_TRUE(lower(source, Stage::Vertex, Target::Glsl450).ok);
}

}  // namespace

namespace {

struct Refusal {
  const char* name;
  const char* source;
  Stage stage;
  Target target;
  const char* fragment;  // the construct and the target, in the message
  const char* advice;    // what to do instead, in the message
  int line;              // of the declaration or use it names
};

void PrintTo(const Refusal& r, std::ostream* os) { *os << r.name; }

class RealWorldRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(RealWorldRefusal, NamesTheConstructTheTargetAndWhatToDo) {
  const Refusal& c = GetParam();
  auto r = lower(c.source, c.stage, c.target);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(r.output.empty());
  expect_no_internal_error(r);
  const auto* e = find(r, Severity::Error, c.fragment);
  ASSERT_NE(e, nullptr) << messages(r);
  EXPECT_EQ(e->line, c.line) << messages(r);
  EXPECT_NE(e->message.find(c.advice), std::string::npos) << messages(r);
  // Under wgsl the passes lower for GLSL ES 3.10; the diagnostics name the target the user asked for.
  if (c.target == Target::Wgsl) {
    for (const auto& d : r.diagnostics) {
      std::string m = d.message;
      if (const size_t at = m.find("es310, the GLSL wgsl is lowered through"); at != std::string::npos) m.erase(at, 5);
      EXPECT_EQ(m.find("es310"), std::string::npos) << d.message;
    }
  }
}

const char* kSampler1D = R"(#version 450
uniform sampler1D ramp;
uniform double u;
out vec4 color;
void main() { color = texture(ramp, float(u)); }
)";
const char* kStorageBlock = R"(#version 450
layout(std430, binding = 0) buffer Samples { double values[]; };
uniform double u;
out vec4 color;
void main() { color = vec4(float(values[0] + u)); }
)";
const char* kAtomicCounter = R"(#version 450
layout(binding = 0) uniform atomic_uint counter;
uniform double u;
out vec4 color;
void main() { uint n = atomicCounterIncrement(counter); color = vec4(float(u) + float(n)); }
)";

const char* kDescriptorSet = R"(#version 450
layout(set = 1, binding = 0) uniform Camera { dmat4 view; } camera;
out vec4 color;
void main() { color = vec4(float(camera.view[0][0])); }
)";
const char* kPushConstant = R"(#version 450
layout(push_constant) uniform Push { double scale; } push;
out vec4 color;
void main() { color = vec4(float(push.scale)); }
)";
const char* kSubpassInput = R"(#version 450
layout(input_attachment_index = 0, binding = 0) uniform subpassInput gbuffer;
uniform double u;
out vec4 color;
void main() { color = subpassLoad(gbuffer) * float(u); }
)";
// The user's `precise` (dropped with a warning on es300) must not hide the construct the target
// really refuses, a fragment output array indexed by a variable.
const char* kPreciseAndOutputIndex = R"(#version 450
uniform int k;
out vec4 o[2];
void main() { precise double x = double(k) * 1.5lf; o[k] = vec4(float(x)); o[1 - k] = vec4(0.0); }
)";
const char* kVertexIndex = R"(#version 450
uniform double u;
void main() { gl_Position = vec4(float(gl_VertexIndex) * float(u)); }
)";

INSTANTIATE_TEST_SUITE_P(
    RealWorld, RealWorldRefusal,
    ::testing::Values(
        Refusal{"Sampler1DOnEs300", kSampler1D, Stage::Fragment, Target::Es300,
                "'ramp' has the type sampler1D, which es300 does not have", "target glsl330, glsl450", 2},
        Refusal{"Sampler1DOnEs320", kSampler1D, Stage::Fragment, Target::Es320, "sampler1D, which es320",
                "2D one of height 1", 2},
        Refusal{"StorageBlockOnEs300", kStorageBlock, Stage::Fragment, Target::Es300,
                "storage block 'Samples' (buffer) is not available on es300: storage blocks need GLSL ES 3.10",
                "target es310, es320 or glsl450", 2},
        Refusal{"StorageBlockOnGlsl330", kStorageBlock, Stage::Fragment, Target::Glsl330,
                "storage block 'Samples' (buffer) is not available on glsl330", "use a uniform block", 2},
        Refusal{"AtomicCounterOnEs300", kAtomicCounter, Stage::Fragment, Target::Es300,
                "'counter' has the type atomic_uint, which es300 does not have", "target es310, es320, glsl450", 2},
        Refusal{"AtomicCounterOnGlsl330", kAtomicCounter, Stage::Fragment, Target::Glsl330,
                "atomic_uint, which glsl330 does not have", "storage buffer", 2},
        Refusal{"VulkanDescriptorSet", kDescriptorSet, Stage::Fragment, Target::Glsl450,
                "descriptor sets (layout(set = N)) are Vulkan GLSL", "target glsl450 is OpenGL GLSL", 2},
        Refusal{"VulkanPushConstant", kPushConstant, Stage::Fragment, Target::Es310,
                "'layout(push_constant)' is Vulkan GLSL", "target es310 is OpenGL ES GLSL", 2},
        Refusal{"VulkanSubpassInput", kSubpassInput, Stage::Fragment, Target::Es320, "subpass inputs",
                "texelFetch(tex, ivec2(gl_FragCoord.xy), 0)", 2},
        Refusal{"VulkanVertexIndex", kVertexIndex, Stage::Vertex, Target::Es300, "'gl_VertexIndex' is Vulkan GLSL",
                "gl_VertexID", 3},
        Refusal{"Sampler1DOnWgsl", kSampler1D, Stage::Fragment, Target::Wgsl,
                "'ramp' has the type sampler1D, which wgsl does not have", "target glsl330, glsl450", 2},
        Refusal{"PreciseDoesNotHideAnIndexedOutputOnEs300", kPreciseAndOutputIndex, Stage::Fragment, Target::Es300,
                "variable indexing fragment shader output array", "target es300 does not allow this", 4},
        Refusal{"PreciseDoesNotHideAnIndexedOutputOnWgsl", kPreciseAndOutputIndex, Stage::Fragment, Target::Wgsl,
                "variable indexing fragment shader output array",
                "target wgsl does not allow this (glslang, compiling the shader itself as es310, the GLSL wgsl is "
                "lowered through", 4}),
    [](const ::testing::TestParamInfo<Refusal>& info) { return std::string(info.param.name); });

TEST(RealWorld, AtomicCountersPassThroughWhereTheTargetHasThem) {
  for (Target t : {Target::Es310, Target::Es320, Target::Glsl450}) {
    auto r = lower(kAtomicCounter, Stage::Fragment, t);
    ASSERT_TRUE(r.ok) << messages(r);
    EXPECT_NE(r.output.find("uniform atomic_uint counter;"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("atomicCounterIncrement(counter)"), std::string::npos) << r.output;
  }
}

}  // namespace
