// fp64 in the vertex and fragment stages on real drivers: one shader body (matrix uniform, double
// inputs and outputs, matrix and geometric built-ins) runs natively in fp64 on lavapipe and,
// lowered by doublet, on lavapipe and on Mesa GLES, in the real stage (the runner wraps the stage
// and feeds it from buffers). Inputs and the matrix are O(1) and well conditioned, so every output
// must match native fp64 to 2^-40 at unit scale; without the optimizer guard it must not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;
using doublet::runner::GraphicsStage;

constexpr uint32_t kCount = 256;

// Fragment outputs cannot be double in GLSL, so the fragment variant splits its results into float
// outputs itself (hi = float(r), lo = float(r - hi)), natively and lowered alike.
std::string shader(GraphicsStage stage) {
  const bool fragment = stage == GraphicsStage::Fragment;
  std::string s = "#version 450\nuniform dmat4 M;\n";
  s += fragment ? "flat in dvec4 a;\n"
                  "layout(location = 0) out vec4 r_hi;\nlayout(location = 1) out vec4 r_lo;\n"
                  "layout(location = 2) out vec4 s_hi;\nlayout(location = 3) out vec4 s_lo;\n"
                : "in dvec4 a;\nlayout(location = 0) out dvec4 r;\nlayout(location = 2) out dvec4 s;\n";
  s += "void main() {\n"
       "  dmat4 N = M * transpose(M) + 0.25lf;\n"
       "  dvec4 rr = N * a + dvec4(determinant(M), length(a.xyz), floor(a.w * 3.0lf), sqrt(abs(a.x)));\n"
       "  dvec4 ss = inverse(M)[1] + dvec4(cross(a.xyz, a.zxy), dot(a, a)) * fract(a.x) + a * M;\n";
  s += fragment ? "  r_hi = vec4(rr);\n  r_lo = vec4(rr - dvec4(r_hi));\n  s_hi = vec4(ss);\n  s_lo = vec4(ss - dvec4(s_hi));\n"
                : "  r = rr;\n  s = ss;\n  gl_Position = vec4(0.0);\n";
  return s + "}\n";
}

struct Inputs {
  std::vector<double> a;       // kCount x 4, float-float exact
  std::vector<double> matrix;  // 16, column by column
};

Inputs make_inputs() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(1.0, 2.0), small(-0.25, 0.25);
  auto dw = [](double x) {
    float hi = static_cast<float>(x);
    return static_cast<double>(hi) + static_cast<double>(static_cast<float>(x - hi));
  };
  Inputs in;
  for (uint32_t i = 0; i < kCount * 4; ++i) in.a.push_back(dw(unit(rng)));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) in.matrix.push_back(dw((c == r ? 3.0 : 0.0) + small(rng)));
  return in;
}

// Runs `glsl` (native or lowered) and returns r and s, 8 values per sample.
std::vector<double> run(Backend backend, GraphicsStage stage, const std::string& glsl, bool lowered, std::string* error) {
  const Inputs in = make_inputs();
  doublet::runner::GraphicsJob job;
  job.stage = stage;
  job.glsl = glsl;
  job.count = kCount;
  if (lowered) {
    std::vector<double> hi, lo;
    for (double v : in.a) {
      hi.push_back(static_cast<float>(v));
      lo.push_back(v - static_cast<float>(v));
    }
    job.inputs["a_hi"] = hi;
    job.inputs["a_lo"] = lo;
    std::vector<double> mhi, mlo;
    for (double v : in.matrix) {
      mhi.push_back(static_cast<float>(v));
      mlo.push_back(v - static_cast<float>(v));
    }
    job.uniforms["M_hi"] = mhi;
    job.uniforms["M_lo"] = mlo;
  } else {
    job.inputs["a"] = in.a;
    job.uniforms["M"] = in.matrix;
  }
  auto result = doublet::runner::run_graphics(backend, job);
  if (!result.ok) {
    *error = result.error + "\n--- shader ---\n" + glsl;
    return {};
  }
  std::vector<double> out(kCount * 8);
  for (uint32_t i = 0; i < kCount; ++i)
    for (int k = 0; k < 4; ++k) {
      if (lowered || stage == GraphicsStage::Fragment) {
        out[i * 8 + k] = result.outputs["r_hi"][i * 4 + k] + result.outputs["r_lo"][i * 4 + k];
        out[i * 8 + 4 + k] = result.outputs["s_hi"][i * 4 + k] + result.outputs["s_lo"][i * 4 + k];
      } else {
        out[i * 8 + k] = result.outputs["r"][i * 4 + k];
        out[i * 8 + 4 + k] = result.outputs["s"][i * 4 + k];
      }
    }
  return out;
}

struct Case {
  Backend backend;
  GraphicsStage stage;
  doublet::Target target;
};

std::string name(const Case& c) {
  return std::string(doublet::runner::backend_name(c.backend)) + "_" +
         (c.stage == GraphicsStage::Vertex ? "vert" : "frag") + "_" + std::string(doublet::to_string(c.target));
}

// Worst error against native fp64, in bits at unit scale: -log2(|got - want| / max(1, |want|)).
double worst_bits(const Case& c, doublet::GuardKind guard, std::string* error) {
  std::string native_error;
  auto native = run(Backend::Vulkan, c.stage, shader(c.stage), false, &native_error);
  if (native.empty()) {
    *error = "native fp64 run failed: " + native_error;
    return 0;
  }
  doublet::Options o;
  o.stage = c.stage == GraphicsStage::Vertex ? doublet::Stage::Vertex : doublet::Stage::Fragment;
  o.target = c.target;
  o.guard = guard;
  o.file_name = "stage.glsl";
  auto lowered = doublet::lower(shader(c.stage), o);
  if (!lowered.ok) {
    for (const auto& d : lowered.diagnostics) *error += doublet::format_diagnostic(d) + "\n";
    return 0;
  }
  auto got = run(c.backend, c.stage, lowered.output, true, error);
  if (got.empty()) return 0;
  double worst = 99;
  for (size_t i = 0; i < got.size(); ++i) {
    double err = std::fabs(got[i] - native[i]) / std::max(1.0, std::fabs(native[i]));
    worst = std::min(worst, err == 0 ? 99.0 : -std::log2(err));
    if (std::isnan(got[i])) worst = -1;
  }
  return worst;
}

class Stages : public ::testing::TestWithParam<Case> {};

TEST_P(Stages, LoweredMatchesNativeFp64To40Bits) {
  std::string error;
  double bits = worst_bits(GetParam(), doublet::GuardKind::Auto, &error);
  ASSERT_TRUE(error.empty()) << error;
  std::printf("%s: worst %.2f bits against native fp64 (unit scale)\n", name(GetParam()).c_str(), bits);
  EXPECT_GE(bits, 40.0);
}

TEST_P(Stages, WithoutTheGuardItDoesNot) {
  std::string error;
  double bits = worst_bits(GetParam(), doublet::GuardKind::None, &error);
  ASSERT_TRUE(error.empty()) << error;
  std::printf("%s, guard removed: worst %.2f bits\n", name(GetParam()).c_str(), bits);
  EXPECT_LT(bits, 40.0);
}

INSTANTIATE_TEST_SUITE_P(Drivers, Stages,
                         ::testing::Values(Case{Backend::Vulkan, GraphicsStage::Vertex, doublet::Target::Es310},
                                           Case{Backend::Vulkan, GraphicsStage::Fragment, doublet::Target::Glsl450},
                                           Case{Backend::Gles, GraphicsStage::Vertex, doublet::Target::Es310},
                                           Case{Backend::Gles, GraphicsStage::Fragment, doublet::Target::Es320}),
                         [](const auto& info) { return name(info.param); });

}  // namespace
