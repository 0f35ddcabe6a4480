// Mode df64-int (docs/modes.md): float-float whose error terms come from integer residuals
// (rules/int.glsl). On real drivers (lavapipe and Mesa GLES/llvmpipe), with NO optimizer guard:
//   add, sub, mul, div, sqrt, a cancelling subtraction and a 3-stage expression >= 44 bits,
//   in compute (lavapipe: es310, glsl450; GLES: es310, es320) and in the vertex and fragment stages.
// Sabotages that must fail: df64 (float EFTs) without the guard (what the guard protects and
// df64-int does not need), the integer residuals replaced by 0 in the emitted text, and
// verify's drop-lo (the doubles demoted before lowering).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"
#include "verify/sabotage.hpp"

namespace {

using doublet::GuardKind;
using doublet::Mode;
using doublet::Target;
using doublet::runner::Backend;
using doublet::runner::GraphicsStage;
using doublet::verify::Sabotage;

constexpr int kOps = 7;
const char* kOpNames[kOps] = {"add", "sub", "mul", "div", "sqrt", "cancel", "3-stage"};

// The operations on x and y (double-word inputs), results in r[0..6]; the same code in every stage.
const char* kBody = R"(
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  double z = double(c.x) + double(c.y);
  double r0 = x + y;
  double r1 = x - y;
  double r2 = x * y;
  double r3 = x / y;
  double r4 = sqrt(abs(x));
  double r5 = x - z;
  double r6 = (x + y) * (x - y) / y;
)";

std::string compute_shader() {
  return std::string(R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 operands[]; };
layout(std430, binding = 1) readonly buffer Near { vec2 cs[]; };
layout(std430, binding = 2) writeonly buffer Outputs { vec2 results[]; };
void store(uint slot, double r) {
  float hi = float(r);
  results[slot] = vec2(hi, float(r - double(hi)));
}
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = operands[i];
  vec2 c = cs[i];
)") + kBody + R"(
  store(i * 7u + 0u, r0); store(i * 7u + 1u, r1); store(i * 7u + 2u, r2); store(i * 7u + 3u, r3);
  store(i * 7u + 4u, r4); store(i * 7u + 5u, r5); store(i * 7u + 6u, r6);
}
)";
}

// Fragment outputs cannot be double: the shader splits each result into hi and lo floats.
std::string graphics_shader(GraphicsStage stage) {
  const bool fragment = stage == GraphicsStage::Fragment;
  std::string s = "#version 450\n";
  s += fragment ? "flat in vec4 v;\nflat in vec2 c;\n" : "in vec4 v;\nin vec2 c;\n";
  for (int k = 0; k < kOps; ++k) {
    s += fragment ? "layout(location = " + std::to_string(k) + ") " : std::string("flat ");
    s += "out vec2 o" + std::to_string(k) + ";\n";
  }
  s += "void main() {\n" + std::string(kBody);
  for (int k = 0; k < kOps; ++k) {
    const std::string i = std::to_string(k);
    s += "  float h" + i + " = float(r" + i + ");\n  o" + i + " = vec2(h" + i + ", float(r" + i + " - double(h" + i + ")));\n";
  }
  if (!fragment) s += "  gl_Position = vec4(0.0);\n";
  return s + "}\n";
}

struct Sample {
  float xh, xl, yh, yl, zh, zl;  // z = x * (1 +- 2^-k) as a double-word: x - z cancels k bits
};

// x, y and z as double-words: hi the nearest float, lo the rest, rounded.
Sample as_words(double x, double y, double z) {
  auto dw = [](double v, float& h, float& l) {
    h = static_cast<float>(v);
    l = static_cast<float>(v - static_cast<double>(h));
  };
  Sample s{};
  dw(x, s.xh, s.xl);
  dw(y, s.yh, s.yl);
  dw(z, s.zh, s.zl);
  return s;
}

// Log-uniform magnitudes in [2^-20, 2^20], random signs; a quarter of the y close to x.
std::vector<Sample> samples(int count) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> exponent(-20.0, 20.0), unit(0.0, 1.0);
  auto sign = [&] { return unit(rng) < 0.5 ? -1.0 : 1.0; };
  std::vector<Sample> out;
  for (int i = 0; i < count; ++i) {
    const double x = std::exp2(exponent(rng)) * sign();
    const double y = i % 4 == 3 ? x * (1.0 + sign() * std::exp2(-(1 + i % 40))) : std::exp2(exponent(rng)) * sign();
    out.push_back(as_words(x, y, x * (1.0 + sign() * std::exp2(-(8 + i % 30)))));
  }
  return out;
}

// Inputs that reach each case of the integer residuals (rules/int.glsl), magnitudes 2^-10..2^20 so
// that no error term underflows (where df64-int rounds and df64's float EFTs may not: docs/modes.md):
// exponents 20..30 apart (df_int_sum_error's shifts clamp past 25), near and exact cancellation, a
// power of two minus a small value (the sum drops a binade), halfway cases (ties to even), zeros.
std::vector<Sample> edge_samples(int count) {
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> exponent(-10.0, 20.0), unit(0.0, 1.0);
  auto sign = [&] { return unit(rng) < 0.5 ? -1.0 : 1.0; };
  std::vector<Sample> out;
  for (int i = 0; i < count; ++i) {
    double x = std::exp2(exponent(rng)) * sign(), y = 0.0;
    switch (i % 8) {
      case 0: y = x * sign() * std::exp2(-(20 + i % 11)) * (1.0 + unit(rng)); break;
      case 1: y = -x * (1.0 + sign() * std::exp2(-(1 + i % 50))); break;
      case 2:
        x = sign() * std::exp2(std::floor(exponent(rng)));
        y = -x * std::exp2(-(23 + i % 4)) * (1.0 + std::ldexp(unit(rng), -10));
        break;
      case 3: y = -x; break;
      case 4: {  // x a float, y half its ulp: x + y is a tie
        x = static_cast<float>(x);
        int e = 0;
        std::frexp(x, &e);
        y = sign() * std::ldexp(1.0, e - 25);
        break;
      }
      case 5: y = 0.0; break;
      default: y = std::exp2(exponent(rng)) * sign();
    }
    out.push_back(as_words(x, y, x * (1.0 + sign() * std::exp2(-(8 + i % 30)))));
  }
  return out;
}

// The host's double reference, in the shader's order.
void reference(const Sample& s, double want[kOps]) {
  const double x = static_cast<double>(s.xh) + s.xl, y = static_cast<double>(s.yh) + s.yl;
  const double z = static_cast<double>(s.zh) + s.zl;  // x - z is exact in double (Sterbenz)
  want[0] = x + y;
  want[1] = x - y;
  want[2] = x * y;
  want[3] = x / y;
  want[4] = std::sqrt(std::fabs(x));
  want[5] = x - z;
  want[6] = (x + y) * (x - y) / y;
}

double bits(double got, double want) {
  if (got == want) return 60.0;
  if (std::isnan(got)) return -1.0;
  return std::min(60.0, -std::log2(std::fabs(got - want) / std::max(std::fabs(want), 1e-300)));
}

struct Accuracy {
  std::string error;
  double min_bits[kOps];
  double worst() const { return *std::min_element(std::begin(min_bits), std::end(min_bits)); }
  std::string report() const {
    std::string s;
    for (int k = 0; k < kOps; ++k) s += std::string(" ") + kOpNames[k] + "=" + std::to_string(min_bits[k]).substr(0, 5);
    return s;
  }
};

struct Lowering {
  Mode mode = Mode::Df64Int;
  GuardKind guard = GuardKind::Auto;
  Sabotage sabotage = Sabotage::None;
  bool zero_int_residuals = false;  // sabotage of the emitted text: the integer error terms replaced by 0
};

std::string lower(const std::string& shader, doublet::Stage stage, Target target, const Lowering& how, std::string* error) {
  std::string source = shader;
  doublet::Options options;
  options.stage = stage;
  options.target = target;
  options.file_name = "int_mode.glsl";
  options.mode = how.mode;
  options.guard = how.guard;
  doublet::verify::apply_sabotage(how.sabotage, &source, &options);
  doublet::Result r = doublet::lower(source, options);
  for (const auto& d : r.diagnostics) *error += doublet::format_diagnostic(d) + "\n";
  if (!r.ok) return "";
  error->clear();
  std::string text = r.output;
  if (how.zero_int_residuals) {
    for (const std::string call : {"(df_int_sum_error(a, b, s))", "(df_int_prod_error(a, b, p))"}) {
      size_t at = text.find(call);
      if (at == std::string::npos) *error += "sabotage: no '" + call + "' in the lowered text\n";
      for (; at != std::string::npos; at = text.find(call)) text.replace(at, call.size(), "(0.0)");
    }
  }
  return text;
}

// The compute shader lowered as `how` says, run on `in`: the result words, (hi, lo) per op and sample
// (empty, with *error set, when lowering or the run fails).
std::vector<float> compute_words(Backend backend, Target target, const Lowering& how, const std::vector<Sample>& in,
                                 std::string* error) {
  const int count = static_cast<int>(in.size());
  std::string glsl = lower(compute_shader(), doublet::Stage::Compute, target, how, error);
  if (glsl.empty() || !error->empty()) return {};
  std::vector<float> operands, tiny;
  for (const auto& s : in) {
    operands.insert(operands.end(), {s.xh, s.xl, s.yh, s.yl});
    tiny.insert(tiny.end(), {s.zh, s.zl});
  }
  doublet::runner::ComputeJob job;
  job.glsl = glsl;
  auto bytes = [](const std::vector<float>& v) {
    const auto* p = reinterpret_cast<const uint8_t*>(v.data());
    return std::vector<uint8_t>(p, p + v.size() * sizeof(float));
  };
  job.buffers = {bytes(operands), bytes(tiny), std::vector<uint8_t>(static_cast<size_t>(count) * kOps * 8, 0)};
  job.groups_x = static_cast<uint32_t>(count / 64);
  auto run = doublet::runner::run_compute(backend, job);
  if (!run.ok) {
    *error = run.error;
    return {};
  }
  std::vector<float> out(static_cast<size_t>(count) * kOps * 2);
  std::memcpy(out.data(), run.buffers[2].data(), out.size() * sizeof(float));
  return out;
}

Accuracy compute_accuracy(Backend backend, Target target, const Lowering& how) {
  constexpr int kCount = 1024;
  Accuracy m;
  std::fill(std::begin(m.min_bits), std::end(m.min_bits), 60.0);
  const auto in = samples(kCount);
  const std::vector<float> out = compute_words(backend, target, how, in, &m.error);
  if (out.empty()) return m;
  for (int i = 0; i < kCount; ++i) {
    double want[kOps];
    reference(in[i], want);
    for (int k = 0; k < kOps; ++k) {
      const size_t at = (static_cast<size_t>(i) * kOps + k) * 2;
      m.min_bits[k] = std::min(m.min_bits[k], bits(static_cast<double>(out[at]) + out[at + 1], want[k]));
    }
  }
  return m;
}

Accuracy graphics_accuracy(Backend backend, GraphicsStage stage, Target target, const Lowering& how) {
  constexpr uint32_t kCount = 256;
  Accuracy m;
  std::fill(std::begin(m.min_bits), std::end(m.min_bits), 60.0);
  const auto doublet_stage = stage == GraphicsStage::Vertex ? doublet::Stage::Vertex : doublet::Stage::Fragment;
  std::string glsl = lower(graphics_shader(stage), doublet_stage, target, how, &m.error);
  if (glsl.empty() || !m.error.empty()) return m;
  const auto in = samples(kCount);
  doublet::runner::GraphicsJob job;
  job.stage = stage;
  job.glsl = glsl;
  job.count = kCount;
  for (const auto& s : in) {
    job.inputs["v"].insert(job.inputs["v"].end(), {s.xh, s.xl, s.yh, s.yl});
    job.inputs["c"].insert(job.inputs["c"].end(), {s.zh, s.zl});
  }
  auto run = doublet::runner::run_graphics(backend, job);
  if (!run.ok) {
    m.error = run.error + "\n--- shader ---\n" + glsl;
    return m;
  }
  for (uint32_t i = 0; i < kCount; ++i) {
    double want[kOps];
    reference(in[i], want);
    for (int k = 0; k < kOps; ++k) {
      const auto& o = run.outputs["o" + std::to_string(k)];
      m.min_bits[k] = std::min(m.min_bits[k], bits(o[i * 2] + o[i * 2 + 1], want[k]));
    }
  }
  return m;
}

struct ComputeCase {
  Backend backend;
  Target target;
};

std::string case_name(Backend b, Target t) {
  return std::string(doublet::runner::backend_name(b)) + "_" + std::string(doublet::to_string(t));
}

class Df64IntCompute : public ::testing::TestWithParam<ComputeCase> {};

TEST_P(Df64IntCompute, Holds44BitsWithoutAnyGuard) {
  const auto [backend, target] = GetParam();
  Accuracy a = compute_accuracy(backend, target, {Mode::Df64Int, GuardKind::None});
  ASSERT_TRUE(a.error.empty()) << a.error;
  std::printf("df64-int, guard none, %s:%s\n", case_name(backend, target).c_str(), a.report().c_str());
  for (int k = 0; k < kOps; ++k) EXPECT_GE(a.min_bits[k], 44.0) << kOpNames[k];
}

// The default lowering of df64-int (guard Auto) is the same unguarded text.
TEST_P(Df64IntCompute, DefaultGuardIsNoneAndHolds) {
  const auto [backend, target] = GetParam();
  Accuracy a = compute_accuracy(backend, target, {Mode::Df64Int, GuardKind::Auto});
  ASSERT_TRUE(a.error.empty()) << a.error;
  EXPECT_GE(a.worst(), 44.0) << a.report();
}

// What the guard protects: the float EFTs of df64, unguarded, lose the error terms.
TEST_P(Df64IntCompute, Df64WithoutTheGuardDoesNot) {
  const auto [backend, target] = GetParam();
  Accuracy a = compute_accuracy(backend, target, {Mode::Df64, GuardKind::None});
  ASSERT_TRUE(a.error.empty()) << a.error;
  std::printf("df64, guard none, %s:%s\n", case_name(backend, target).c_str(), a.report().c_str());
  EXPECT_LT(a.worst(), 44.0) << a.report();
}

TEST_P(Df64IntCompute, FailsWhenTheIntegerResidualsAreZeroed) {
  const auto [backend, target] = GetParam();
  Lowering how{Mode::Df64Int, GuardKind::None};
  how.zero_int_residuals = true;
  Accuracy a = compute_accuracy(backend, target, how);
  ASSERT_TRUE(a.error.empty()) << a.error;
  EXPECT_LT(a.worst(), 30.0) << a.report();
}

TEST_P(Df64IntCompute, FailsUnderDropLo) {
  const auto [backend, target] = GetParam();
  Accuracy a = compute_accuracy(backend, target, {Mode::Df64Int, GuardKind::None, Sabotage::DropLo});
  ASSERT_TRUE(a.error.empty()) << a.error;
  EXPECT_LT(a.worst(), 30.0) << a.report();
}

// The oracle df64-int == df64 (docs/modes.md: both error terms are exact, so the pairs are the same):
// every result word equals df64's, bit for bit, on edge_samples; NaNs count as equal. Both are lowered
// with the same guard (ES 3.10: the uniform, the others: precise), so that their other float operations
// compile alike: GLSL's '/' is not correctly rounded, and with df64-int's default guard none (no
// precise) the driver compiles the quotient and the non-EFT products differently, which moved the
// last bits of 12 (es310) and 825 (glsl450, es320) of these 28,672 results. Shown to fail: with the
// integer residuals replaced by 0 most words differ.
int words_differing(const std::vector<float>& a, const std::vector<float>& b, std::string* first) {
  int differ = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    uint32_t wa = 0, wb = 0;
    std::memcpy(&wa, &a[i], 4);
    std::memcpy(&wb, &b[i], 4);
    if (wa == wb || (std::isnan(a[i]) && std::isnan(b[i]))) continue;
    if (++differ <= 5)
      *first += std::string(kOpNames[(i / 2) % kOps]) + " sample " + std::to_string(i / 2 / kOps) + (i % 2 ? " lo: " : " hi: ") +
                std::to_string(a[i]) + " against df64's " + std::to_string(b[i]) + "\n";
  }
  return differ;
}

TEST_P(Df64IntCompute, GivesDf64sPairsBitForBit) {
  const auto [backend, target] = GetParam();
  const auto in = edge_samples(4096);
  std::string error, first;
  const GuardKind guard = target == Target::Es310 ? GuardKind::Uniform : GuardKind::Precise;
  const auto df64 = compute_words(backend, target, {Mode::Df64, guard}, in, &error);
  ASSERT_TRUE(error.empty()) << error;
  const auto int_mode = compute_words(backend, target, {Mode::Df64Int, guard}, in, &error);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_EQ(int_mode.size(), df64.size());
  EXPECT_EQ(words_differing(int_mode, df64, &first), 0) << first;
  Lowering zeroed{Mode::Df64Int, guard};
  zeroed.zero_int_residuals = true;
  const auto sabotaged = compute_words(backend, target, zeroed, in, &error);
  ASSERT_TRUE(error.empty()) << error;
  first.clear();
  EXPECT_GT(words_differing(sabotaged, df64, &first), static_cast<int>(in.size()));
}

INSTANTIATE_TEST_SUITE_P(Drivers, Df64IntCompute,
                         ::testing::Values(ComputeCase{Backend::Vulkan, Target::Es310},
                                           ComputeCase{Backend::Vulkan, Target::Glsl450},
                                           ComputeCase{Backend::Gles, Target::Es310},
                                           ComputeCase{Backend::Gles, Target::Es320}),
                         [](const auto& info) { return case_name(info.param.backend, info.param.target); });

struct GraphicsCase {
  Backend backend;
  GraphicsStage stage;
  Target target;
};

std::string graphics_name(const GraphicsCase& c) {
  return case_name(c.backend, c.target) + (c.stage == GraphicsStage::Vertex ? "_vert" : "_frag");
}

class Df64IntStages : public ::testing::TestWithParam<GraphicsCase> {};

TEST_P(Df64IntStages, Holds44BitsWithoutAnyGuard) {
  const GraphicsCase c = GetParam();
  Accuracy a = graphics_accuracy(c.backend, c.stage, c.target, {Mode::Df64Int, GuardKind::None});
  ASSERT_TRUE(a.error.empty()) << a.error;
  std::printf("df64-int, guard none, %s:%s\n", graphics_name(c).c_str(), a.report().c_str());
  for (int k = 0; k < kOps; ++k) EXPECT_GE(a.min_bits[k], 44.0) << kOpNames[k];
}

TEST_P(Df64IntStages, FailsWhenTheIntegerResidualsAreZeroed) {
  const GraphicsCase c = GetParam();
  Lowering how{Mode::Df64Int, GuardKind::None};
  how.zero_int_residuals = true;
  Accuracy a = graphics_accuracy(c.backend, c.stage, c.target, how);
  ASSERT_TRUE(a.error.empty()) << a.error;
  EXPECT_LT(a.worst(), 30.0) << a.report();
}

INSTANTIATE_TEST_SUITE_P(Drivers, Df64IntStages,
                         ::testing::Values(GraphicsCase{Backend::Vulkan, GraphicsStage::Vertex, Target::Es310},
                                           GraphicsCase{Backend::Vulkan, GraphicsStage::Fragment, Target::Glsl450},
                                           GraphicsCase{Backend::Gles, GraphicsStage::Vertex, Target::Es300},
                                           GraphicsCase{Backend::Gles, GraphicsStage::Fragment, Target::Es310}),
                         [](const auto& info) { return graphics_name(info.param); });

// ---- the mode's contract at the API: no guard emitted, ES 3.00+, whole shader only ----

doublet::Result lower_text(const std::string& source, Target target, Mode mode,
                           std::vector<std::pair<std::string, Mode>> mode_for = {}) {
  doublet::Options o;
  o.stage = doublet::Stage::Fragment;
  o.target = target;
  o.file_name = "m.frag";
  o.mode = mode;
  o.mode_for = std::move(mode_for);
  return doublet::lower(source, o);
}

const char* kFragment = R"(#version 450
uniform double a;
uniform double b;
out vec4 color;
void main() { color = vec4(float(a * b + a)); }
)";

TEST(Df64IntContract, EmitsIntegerEftsAndNoGuard) {
  auto r = lower_text(kFragment, Target::Es300, Mode::Df64Int);
  ASSERT_TRUE(r.ok);
  EXPECT_EQ(r.manifest.mode, "df64-int");
  EXPECT_EQ(r.manifest.guard.kind, "none");
  // No rule reads the guard: it is declared only to read the uniforms' words through it, once each
  // at the top of main (docs/modes.md).
  size_t reads = 0;
  for (size_t at = r.output.find("df_guard[int("); at != std::string::npos; at = r.output.find("df_guard[int(", at + 1)) ++reads;
  EXPECT_EQ(reads, 4u) << r.output;
  EXPECT_NE(r.output.find("a = df_double(a_hi - df_guard[int(df_guard[1])], a_lo - df_guard[int(df_guard[1])]);"),
            std::string::npos) << r.output;
  EXPECT_NE(r.output.find("b = df_double(b_hi - df_guard[int(df_guard[1])], b_lo - df_guard[int(df_guard[1])]);"),
            std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("precise"), std::string::npos);
  EXPECT_NE(r.output.find("df_int_prod_error"), std::string::npos);
  EXPECT_NE(r.output.find("df_int_sum_error"), std::string::npos);
  EXPECT_EQ(r.output.find("4097.0"), std::string::npos) << "the float Veltkamp split is still emitted";
  auto df64 = lower_text(kFragment, Target::Es300, Mode::Df64);
  ASSERT_TRUE(df64.ok);
  EXPECT_EQ(df64.output.find("df_int_"), std::string::npos);
}

TEST(Df64IntContract, Es100IsAClearError) {
  auto r = lower_text(kFragment, Target::Es100, Mode::Df64Int);
  EXPECT_FALSE(r.ok);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics[0].message.find("df64-int needs uint and floatBitsToUint (GLSL ES 3.00 or later)"),
            std::string::npos)
      << r.diagnostics[0].message;
}

TEST(Df64IntContract, PerDeclarationIsAPositionedError) {
  const std::string source = std::string("#version 450\n#pragma doublet mode(df64-int)\n") +
                             "double f(double x) { return x * x; }\nuniform double a;\nout vec4 color;\n"
                             "void main() { color = vec4(float(f(a))); }\n";
  auto r = lower_text(source, Target::Es300, Mode::Df64);
  EXPECT_FALSE(r.ok);
  bool found = false;
  for (const auto& d : r.diagnostics)
    if (d.severity == doublet::Severity::Error && d.line == 2 && d.column > 0 &&
        d.message.find("mode df64-int applies to the whole shader only (--mode df64-int)") != std::string::npos)
      found = true;
  EXPECT_TRUE(found) << (r.diagnostics.empty() ? "" : doublet::format_diagnostic(r.diagnostics[0]));
  auto by_name = lower_text(kFragment, Target::Es300, Mode::Df64, {{"a", Mode::Df64Int}});
  EXPECT_FALSE(by_name.ok);
  ASSERT_FALSE(by_name.diagnostics.empty());
  EXPECT_NE(by_name.diagnostics[0].message.find("--mode-for a=df64-int: mode df64-int applies to the whole shader"),
            std::string::npos)
      << by_name.diagnostics[0].message;
}

}  // namespace
