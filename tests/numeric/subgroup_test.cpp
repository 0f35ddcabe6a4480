// Subgroup reductions and scans on doubles (docs/accuracy.md, "Subgroup reductions"), on lavapipe,
// against the host: every active lane's value combined in lane-id order with IEEE binary64
// operations. That order is what the lowering promises, so mode exact must give those bits exactly
// and the float-float modes must stay within the bound of the same order. The host is the oracle
// (not native fp64) because Mesa 22.3's lavapipe ignores the cluster size of clustered reductions.
// A third of the lanes return before the operations, so the active-lane bookkeeping is tested too.
// The sabotage (the lo words not moved between lanes) must fail every mode.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::Mode;
using doublet::Target;

constexpr uint32_t kInvocations = 256, kGroupSize = 64;
constexpr uint32_t kSkipped = 0xFFFFFFFFu;

// One output per operation; op names as in GLSL, cluster size 0 for the non-clustered ones.
struct Op {
  const char* glsl;
  char combine;  // + * < >
  enum Scope { Reduce, Inclusive, Exclusive, Clustered } scope;
  uint32_t cluster = 0;
};
const std::vector<Op>& ops() {
  static const std::vector<Op> list = {
      {"subgroupAdd(v)", '+', Op::Reduce},
      {"subgroupInclusiveAdd(v)", '+', Op::Inclusive},
      {"subgroupExclusiveAdd(v)", '+', Op::Exclusive},
      {"subgroupMul(w)", '*', Op::Reduce},
      {"subgroupExclusiveMul(w)", '*', Op::Exclusive},
      {"subgroupMin(v)", '<', Op::Reduce},
      {"subgroupInclusiveMax(v)", '>', Op::Inclusive},
      {"subgroupExclusiveMin(v)", '<', Op::Exclusive},
      {"subgroupClusteredAdd(v, 4u)", '+', Op::Clustered, 4},
      {"subgroupClusteredMax(v, 2u)", '>', Op::Clustered, 2},
      {"subgroupClusteredMul(w, 4u)", '*', Op::Clustered, 4},
  };
  return list;
}

std::string shader() {
  std::string s = R"(#version 450
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_clustered : require
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { uvec2 x[]; };
layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };
layout(std430, binding = 2) writeonly buffer Lanes { uint lane[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i % 3u == 1u) return;
  double v = packDouble2x32(x[2u * i]), w = packDouble2x32(x[2u * i + 1u]);
  lane[i] = gl_SubgroupID * 1024u + gl_SubgroupInvocationID;
)";
  for (size_t k = 0; k < ops().size(); ++k)
    s += "  r[" + std::to_string(ops().size()) + "u * i + " + std::to_string(k) + "u] = unpackDouble2x32(" +
         ops()[k].glsl + ");\n";
  return s + "}\n";
}

double from_words(const uint32_t* w) {
  uint64_t b = uint64_t(w[1]) << 32 | w[0];
  double d;
  std::memcpy(&d, &b, 8);
  return d;
}

struct Outcome {
  std::string error;
  int differing_bits = 0;     // outputs whose bits differ from the host's (mode exact's check)
  int over_bound = 0;         // outputs outside the float-float bound
  int checked = 0;
  std::string worst;
};

// `sabotage`: the lo words are not moved between lanes (each lane combines the others' hi words
// with its own lo word).
Outcome run(Mode mode, bool sabotage) {
  Outcome out;
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = Target::Glsl450;
  options.mode = mode;
  options.file_name = "subgroup.comp";
  doublet::Result lowered = doublet::lower(shader(), options);
  for (const auto& d : lowered.diagnostics) out.error += doublet::format_diagnostic(d) + "\n";
  if (!lowered.ok) return out;
  out.error.clear();
  std::string glsl = lowered.output;
  if (sabotage) {
    const std::string move = "subgroupShuffle(v.lo, j)";
    if (glsl.find(move) == std::string::npos) out.error = "sabotage: no '" + move + "' in the lowered text";
    for (size_t at = glsl.find(move); at != std::string::npos; at = glsl.find(move)) glsl.replace(at, move.size(), "v.lo");
  }

  // Full 53-bit significands; v of both signs over a few binades (sums cancel), w near 1 (products
  // stay finite over a whole subgroup).
  std::mt19937_64 rng(11);
  std::vector<double> in(2 * kInvocations);
  for (uint32_t i = 0; i < kInvocations; ++i) {
    const double m = 1.0 + double(rng() >> 12) * 0x1p-52;
    in[2 * i] = std::ldexp(m, int(rng() % 9) - 4) * (rng() & 1 ? -1.0 : 1.0);
    in[2 * i + 1] = 0.75 + double(rng() >> 11) * 0x1p-53 * 0.5;
  }
  const size_t n_ops = ops().size();
  doublet::runner::ComputeJob job;
  job.glsl = glsl;
  std::vector<uint8_t> input(in.size() * 8);
  std::memcpy(input.data(), in.data(), input.size());
  job.buffers = {input, std::vector<uint8_t>(kInvocations * n_ops * 8, 0xFF),
                 std::vector<uint8_t>(kInvocations * 4, 0xFF)};
  job.groups_x = kInvocations / kGroupSize;
  auto result = doublet::runner::run_compute(doublet::runner::Backend::Vulkan, job);
  if (!result.ok) {
    out.error = result.error;
    return out;
  }
  std::vector<uint32_t> lanes(kInvocations), words(kInvocations * n_ops * 2);
  std::memcpy(lanes.data(), result.buffers[2].data(), lanes.size() * 4);
  std::memcpy(words.data(), result.buffers[1].data(), words.size() * 4);

  // subgroup (workgroup, gl_SubgroupID) → its active invocations in lane order.
  std::map<std::pair<uint32_t, uint32_t>, std::map<uint32_t, uint32_t>> subgroups;
  for (uint32_t i = 0; i < kInvocations; ++i) {
    if (i % 3 == 1) {
      if (lanes[i] != kSkipped) out.error = "a lane that returned wrote its lane id";
      continue;
    }
    subgroups[{i / kGroupSize, lanes[i] / 1024}][lanes[i] % 1024] = i;
  }
  constexpr double u2 = 0x1p-48;  // u^2, u = 2^-24
  for (const auto& [key, members] : subgroups) {
    for (const auto& [self, i] : members) {
      for (size_t k = 0; k < n_ops; ++k) {
        const Op& op = ops()[k];
        const bool product = std::strstr(op.glsl, "(w") != nullptr;  // the operand is w, not v
        double acc = 0, magnitude = 0;  // magnitude: the sum of |partial results|, for the bound
        bool started = false;
        int terms = 0;
        for (const auto& [lane, j] : members) {
          const bool taken = op.scope == Op::Reduce      ? true
                             : op.scope == Op::Clustered ? lane / op.cluster == self / op.cluster
                             : op.scope == Op::Inclusive ? lane <= self
                                                         : lane < self;
          if (!taken) continue;
          const double x = product ? in[2 * j + 1] : in[2 * j];
          if (!started) acc = x;
          else if (op.combine == '+') acc = acc + x;
          else if (op.combine == '*') acc = acc * x;
          else if (op.combine == '<') acc = x < acc ? x : acc;
          else acc = acc < x ? x : acc;
          started = true;
          ++terms;
          magnitude += std::fabs(acc) + std::fabs(x);
        }
        if (!started)  // an exclusive scan's first lane: the operation's identity
          acc = op.combine == '+' ? 0.0 : op.combine == '*' ? 1.0
              : op.combine == '<' ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
        const double got = from_words(&words[(i * n_ops + k) * 2]);
        ++out.checked;
        uint64_t gb, wb;
        std::memcpy(&gb, &got, 8);
        std::memcpy(&wb, &acc, 8);
        if (gb != wb) ++out.differing_bits;
        // Float-float: each input carried to within u^2 of itself, each combination within 8u^2
        // (df_add 3u^2 + 13u^3, df_mul 7u^2) of its partial result; a product's partials are all
        // within a factor 2^terms of the result.
        const double bound = op.combine == '*' ? (terms + 1) * 8 * u2 * std::fabs(acc)
                           : op.combine == '+' ? 8 * u2 * magnitude
                                               : u2 * std::fabs(acc);
        const bool within = std::isinf(acc) ? got == acc : std::fabs(got - acc) <= bound;
        if (!within) {
          if (out.over_bound++ == 0)
            out.worst = std::string(op.glsl) + " at invocation " + std::to_string(i) + ": got " + std::to_string(got) +
                        ", want " + std::to_string(acc) + " (error " + std::to_string(std::fabs(got - acc)) +
                        ", bound " + std::to_string(bound) + ")";
        }
      }
    }
  }
  return out;
}

TEST(SubgroupReductions, ModeExactGivesTheLaneOrderBinary64Results) {
  Outcome o = run(Mode::Exact, false);
  ASSERT_EQ(o.error, "");
  EXPECT_GT(o.checked, 1000);
  EXPECT_EQ(o.differing_bits, 0) << o.worst;
  std::cout << "[ subgroup ] exact: " << o.checked << " results, " << o.differing_bits << " differ\n";
}

TEST(SubgroupReductions, FloatFloatModesStayWithinTheBoundOfTheLaneOrder) {
  for (Mode mode : {Mode::Df64, Mode::Df64Int}) {
    Outcome o = run(mode, false);
    ASSERT_EQ(o.error, "") << doublet::to_string(mode);
    EXPECT_GT(o.checked, 1000);
    EXPECT_EQ(o.over_bound, 0) << doublet::to_string(mode) << ": " << o.worst;
    std::cout << "[ subgroup ] " << doublet::to_string(mode) << ": " << o.checked << " results, " << o.over_bound
              << " over the bound, " << o.differing_bits << " differ from binary64\n";
  }
}

TEST(SubgroupReductions, LoWordsLeftBehindAreFound) {
  Outcome exact = run(Mode::Exact, true);
  ASSERT_EQ(exact.error, "");
  EXPECT_GT(exact.differing_bits, 100);
  Outcome df64 = run(Mode::Df64, true);
  ASSERT_EQ(df64.error, "");
  EXPECT_GT(df64.over_bound, 100);
}

}  // namespace
