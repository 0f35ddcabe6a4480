// `doublet bench --peer-mesa-fp64`: the adaptation of Mesa's float64.glsl keeps its arithmetic
// (the adapted uvec2 text gives the same bits as the unmodified file compiled with native 64-bit
// integers on lavapipe), the bit-identity check counts what it should (0 for exact, and a
// sabotaged rounding is caught), and the whole bench runs end to end with tiny sizes.
// Mesa's file is fetched at run time (scripts/fetch-mesa-fp64), never committed: without it the
// tests that need it are skipped with that message. No timing thresholds.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "bench/mesa_fp64.hpp"
#include "bench/peer_bench.hpp"
#include "bench/variants.hpp"
#include "verify/sabotage.hpp"

namespace {
using namespace doublet::bench;
using doublet::runner::Backend;

const std::string kPeerPath = DOUBLET_PEER_MESA_FP64;

std::string read_peer() {
  std::ifstream in(kPeerPath);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

#define REQUIRE_PEER()                                                                          \
  if (!std::filesystem::exists(kPeerPath))                                                      \
  GTEST_SKIP() << kPeerPath << " is missing: run scripts/fetch-mesa-fp64 (downloads Mesa's source " \
                                "package from the Debian archive)"

std::string adapted() {
  std::string library, error;
  EXPECT_TRUE(adapt_mesa_fp64(read_peer(), &library, &error)) << error;
  return library;
}

// The unmodified file, as Mesa compiles it (uint64_t from GL_ARB_gpu_shader_int64), with a main
// that applies one op: only the #version line changes (compute shaders need 4.30+).
std::string original_int64_check_shader(const std::string& op) {
  std::string text = read_peer();
  const size_t v = text.find("#version 400");
  EXPECT_NE(v, std::string::npos);
  text.replace(v, 12, "#version 450");
  return text + "\nlayout(local_size_x = 64) in;\n"
                "layout(std430, binding = 0) readonly buffer In { uvec4 ab[]; };\n"
                "layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };\n"
                "void main() {\n  uint i = gl_GlobalInvocationID.x;\n"
                "  uint64_t a = packUint2x32(ab[i].xy), b = packUint2x32(ab[i].zw);\n"
                "  r[i] = unpackUint2x32(" + mesa_op_expression(op, "a", "b") + ");\n}\n";
}

size_t count_differing(const std::vector<uint64_t>& x, const std::vector<uint64_t>& y) {
  size_t n = 0;
  for (size_t i = 0; i < x.size() && i < y.size(); ++i) n += x[i] != y[i];
  return n + (x.size() > y.size() ? x.size() - y.size() : y.size() - x.size());
}

TEST(PeerMesaFp64, AdaptationRefusesWhatItCannotSlice) {
  std::string library, error;
  EXPECT_FALSE(adapt_mesa_fp64("uint f() { return 1u; }\n", &library, &error));
  EXPECT_NE(error.find("__fadd64"), std::string::npos) << error;
  EXPECT_FALSE(adapt_mesa_fp64("#ifdef X\nuint __fadd64() { return 1u; }\n#endif\n", &library, &error));
  EXPECT_NE(error.find("#ifdef"), std::string::npos) << error;
  EXPECT_FALSE(adapt_mesa_fp64("uint __fadd64() { return 1u; }}\n", &library, &error));
  EXPECT_NE(error.find("unbalanced"), std::string::npos) << error;
}

// Every op Mesa's file has, on the same inputs: the adapted text and the original with 64-bit
// integers give the same 64 bits. Sabotage: a wrong spelling of one 64-bit literal (the default
// NaN the file returns for invalid operations) must show up as differences.
TEST(PeerMesaFp64, AdaptedTextGivesTheOriginalsBits) {
  REQUIRE_PEER();
  const std::string library = adapted();
  const std::vector<uint64_t> ab = peer_check_inputs(1 << 14);
  for (const char* op : {"add", "sub", "mul", "sqrt"}) {
    SCOPED_TRACE(op);
    std::vector<uint64_t> original, adapted_bits, sabotaged;
    std::string error;
    ASSERT_TRUE(run_check_shader(Backend::Vulkan, original_int64_check_shader(op), ab, &original, &error)) << error;
    ASSERT_TRUE(run_check_shader(Backend::Vulkan, mesa_check_shader(op, library), ab, &adapted_bits, &error)) << error;
    EXPECT_EQ(count_differing(original, adapted_bits), 0u);
    std::string broken = library;
    const std::string nan = "uvec2(0xFFFFFFFFu, 0xFFFFFFFFu)";
    ASSERT_NE(broken.find(nan), std::string::npos);
    for (size_t p = broken.find(nan); p != std::string::npos; p = broken.find(nan, p + 1))
      broken.replace(p, nan.size(), "uvec2(0xFFFFFFFFu, 0x7FFFFFFFu)");
    ASSERT_TRUE(run_check_shader(Backend::Vulkan, mesa_check_shader(op, broken), ab, &sabotaged, &error)) << error;
    const size_t caught = count_differing(original, sabotaged);
    std::cout << "[ peer ] " << op << ": adapted text with the default NaN misspelt: " << caught << " differ\n";
    EXPECT_GT(caught, 0u);
  }
}

// The bit-identity check of mode exact: 0 differing on both backends; with ties rounded away from
// zero in the lowered shader, nonzero.
TEST(PeerMesaFp64, ExactBitCheckIsZeroAndCatchesSabotagedRounding) {
  const std::vector<uint64_t> ab = peer_check_inputs(1 << 14);
  for (const char* op : {"add", "mul", "div"}) {
    SCOPED_TRACE(op);
    std::vector<uint64_t> native;
    std::string error;
    ASSERT_TRUE(run_check_shader(Backend::Vulkan, double_check_shader(op), ab, &native, &error)) << error;
    for (Backend backend : {Backend::Vulkan, Backend::Gles}) {
      const Variant exact = make_variant(Mode::Exact, backend, double_check_shader(op), doublet::Target::Es310, "check.comp");
      ASSERT_FALSE(exact.glsl.empty()) << exact.note;
      const PeerBits good = compare_with_native(op, "exact", backend, exact.glsl, ab, native);
      ASSERT_TRUE(good.ok) << good.note;
      EXPECT_EQ(good.differing, 0u) << good.example;
      std::string sabotaged = exact.glsl;
      ASSERT_TRUE(doublet::verify::apply_output_sabotage(doublet::verify::Sabotage::TiesAway, &sabotaged));
      const PeerBits bad = compare_with_native(op, "exact", backend, sabotaged, ab, native);
      ASSERT_TRUE(bad.ok) << bad.note;
      std::cout << "[ peer ] exact " << op << " with ties away from zero: " << bad.differing << " of " << bad.inputs
                << " differ\n";
      EXPECT_GT(bad.differing, bad.nan_only);
    }
  }
}

TEST(PeerMesaFp64, TinyBenchRunsEndToEnd) {
  REQUIRE_PEER();
  PeerOptions o;
  o.peer_path = kPeerPath;
  o.elements = 128;
  o.steps = 8;
  o.warmup = 1;
  o.repetitions = 2;
  o.check_inputs = 512;
  PeerReport report;
  std::string error;
  ASSERT_TRUE(run_peer_bench(o, &report, &error)) << error;
  EXPECT_EQ(report.timings.size(), 5u * 2u * 4u);  // ops x backends x (fp32 exact mesa native)
  for (const PeerTiming& t : report.timings) {
    SCOPED_TRACE(t.op + " " + t.variant + ": " + t.note);
    if (t.backend == Backend::Gles && t.variant == "native") {
      EXPECT_TRUE(t.not_applicable);
      continue;
    }
    ASSERT_TRUE(t.ok);
    EXPECT_EQ(t.seconds.size(), 2u);
    EXPECT_TRUE(std::isfinite(t.median_seconds) && t.median_seconds > 0);
    EXPECT_GT(t.spirv_instructions, 0u);
  }
  ASSERT_EQ(report.bits.size(), 5u * 2u * 2u);
  for (const PeerBits& b : report.bits) {
    SCOPED_TRACE(b.op + " " + b.variant + ": " + b.note);
    ASSERT_TRUE(b.ok);
    EXPECT_EQ(b.inputs, 512u);
    if (b.variant == "exact") EXPECT_EQ(b.differing, 0u) << b.example;
  }
  const std::string md = format_peer_markdown(report);
  for (const char* key : {"exact / mesa", "exact / native", "exact / fp32", "mesa: differing", "### gles"})
    EXPECT_NE(md.find(key), std::string::npos) << key;
}

}  // namespace
