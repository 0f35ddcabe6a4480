#include "verify/sweep.hpp"

#include <mpfr.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>

#include "doublet/split.hpp"
#include "verify/heatmap.hpp"
#include "verify/metrics.hpp"

namespace doublet::verify {
namespace {

constexpr double kU2 = 0x1p-48;  // u² with u = 2^-24
constexpr double kFltMax = 3.4028234663852886e38, kFltMin = 0x1p-126;

struct OpInfo {
  const char* name;
  const char* expr;    // GLSL over double x, y
  const char* bound;
  double bound_u2;
  bool unary;
};

const OpInfo kOps[] = {
    {"add", "x + y", "3u^2 + 13u^3", 3 + 13 * 0x1p-24, false},
    {"sub", "x - y", "3u^2 + 13u^3", 3 + 13 * 0x1p-24, false},
    {"mul", "x * y", "7u^2", 7, false},
    {"div", "x / y", "15u^2 + 56u^3", 15 + 56 * 0x1p-24, false},
    {"sqrt", "sqrt(abs(x))", "25/8 u^2", 25.0 / 8, true},
};

const OpInfo* find_op(const std::string& name) {
  for (const OpInfo& op : kOps)
    if (name == op.name) return &op;
  return nullptr;
}

std::string shader_for(const OpInfo& op) {
  return std::string(R"(#version 310 es
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { vec4 xy[]; };
layout(std430, binding = 1) writeonly buffer Out { vec2 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 v = xy[i];
  double x = double(v.x) + double(v.y);
  double y = double(v.z) + double(v.w);
  double z = )") + op.expr + R"(;
  float hi = float(z);
  r[i] = vec2(hi, float(z - double(hi)));
}
)";
}

struct Sample {
  double x, y;
  int family;      // index into the family list
  int cell = -1;   // grid cell, -1 elsewhere
};

// A float-float-exact value with a random 48-bit significand in binade e, random sign.
double random_ff(std::mt19937_64& rng, int e) {
  const double m = 1.0 + static_cast<double>(rng() >> 16) * 0x1p-48;
  return join(split(std::ldexp(m, e) * ((rng() & 1) ? -1.0 : 1.0)));
}

const char* kFamilies[] = {"grid", "ratio", "cancel", "cts", "split-overflow", "near-max"};

std::vector<Sample> make_samples(int step, uint64_t seed, int* grid_width) {
  std::mt19937_64 rng(seed);
  std::vector<Sample> s;
  const int lo = -126, hi = 127;
  *grid_width = (hi - lo) / step + 1;
  for (int a = 0; a < *grid_width; ++a)
    for (int b = 0; b < *grid_width; ++b)
      s.push_back({random_ff(rng, lo + a * step), random_ff(rng, lo + b * step), 0, a * *grid_width + b});
  for (int k = 0; k <= 60; ++k)
    for (int i = 0; i < 64; ++i) {
      const double x = random_ff(rng, static_cast<int>(rng() % 41) - 20);
      s.push_back({x, join(split(std::ldexp(random_ff(rng, 0), std::ilogb(x) - k))), 1});
    }
  for (int k = 1; k <= 60; ++k)
    for (int i = 0; i < 64; ++i) {
      const double x = random_ff(rng, static_cast<int>(rng() % 41) - 20);
      s.push_back({x, join(split(-x * (1 + ((rng() & 1) ? 1 : -1) * std::ldexp(1.0, -k)))), 2});
    }
  const double inf = std::numeric_limits<double>::infinity();
  const double cts[] = {0.0, -0.0, kFltMin, -kFltMin, 0.5, -0.5, 1, -1, 2, -2, kFltMax, -kFltMax, inf, -inf,
                        std::nan("")};
  for (double x : cts)
    for (double y : cts) s.push_back({x, y, 3});
  for (int i = 0; i < 512; ++i) {  // |x| above FLT_MAX/4097, where an unscaled split overflows
    const double x = join(split(std::exp2(115.0 + 12.9 * std::uniform_real_distribution<double>(0, 1)(rng)) *
                                ((rng() & 1) ? -1 : 1)));
    s.push_back({x, i % 2 ? random_ff(rng, static_cast<int>(rng() % 41) - 20) : x * 0.75, 4});
  }
  for (int i = 0; i < 512; ++i)  // both operands in [FLT_MAX/4, FLT_MAX/2): sums near FLT_MAX
    s.push_back({std::fabs(random_ff(rng, 125)), std::fabs(random_ff(rng, 125)), 5});
  return s;
}

// Exact x op y in MPFR and the relative error of `got` against it (0 when both are the same
// special value; Inf for a class mismatch).
struct Reference {
  mpfr_t x, y, z, g, e;
  Reference() { mpfr_inits2(256, x, y, z, g, e, static_cast<mpfr_ptr>(nullptr)); }
  ~Reference() { mpfr_clears(x, y, z, g, e, static_cast<mpfr_ptr>(nullptr)); }
  double want(const OpInfo& op, double a, double b) {
    mpfr_set_d(x, a, MPFR_RNDN);
    mpfr_set_d(y, b, MPFR_RNDN);
    const std::string name = op.name;
    switch (name == "add" ? 0 : name == "sub" ? 1 : name == "mul" ? 2 : name == "div" ? 3 : 4) {
      case 0: mpfr_add(z, x, y, MPFR_RNDN); break;
      case 1: mpfr_sub(z, x, y, MPFR_RNDN); break;
      case 2: mpfr_mul(z, x, y, MPFR_RNDN); break;
      case 3: mpfr_div(z, x, y, MPFR_RNDN); break;
      default: mpfr_abs(z, x, MPFR_RNDN); mpfr_sqrt(z, z, MPFR_RNDN); break;
    }
    return mpfr_get_d(z, MPFR_RNDN);
  }
  double rel_err(double got) {  // after want()
    mpfr_set_d(g, got, MPFR_RNDN);
    mpfr_sub(e, g, z, MPFR_RNDN);
    if (!mpfr_zero_p(z)) mpfr_div(e, e, z, MPFR_RNDN);
    return std::fabs(mpfr_get_d(e, MPFR_RNDN));
  }
};

bool in_range(double v) { return v == 0 || (std::fabs(v) >= 0x1p-75 && std::fabs(v) <= 0x1p75); }

}  // namespace

const std::vector<std::string>& sweep_ops() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const OpInfo& op : kOps) n.push_back(op.name);
    return n;
  }();
  return names;
}

std::vector<OpSweep> sweep(const SweepOptions& options, std::string* error) {
  std::vector<OpSweep> out;
  int width = 0;
  const std::vector<Sample> samples = make_samples(options.grid_step, options.seed, &width);
  const size_t n = (samples.size() + 63) / 64 * 64;
  std::vector<float> packed(n * 4, 1.0f);  // padding invocations compute 1 op 1
  for (size_t i = 0; i < samples.size(); ++i) {
    const FloatPair x = split(samples[i].x), y = split(samples[i].y);
    packed[4 * i] = x.hi;
    packed[4 * i + 1] = x.lo;
    packed[4 * i + 2] = y.hi;
    packed[4 * i + 3] = y.lo;
  }
  for (const std::string& name : options.ops) {
    const OpInfo* op = find_op(name);
    if (!op) {
      *error = "unknown sweep op '" + name + "'";
      return {};
    }
    const auto start = std::chrono::steady_clock::now();
    Options lo;
    lo.stage = Stage::Compute;
    lo.target = options.target;
    lo.file_name = std::string("sweep_") + op->name + ".comp";
    std::string source = shader_for(*op);
    apply_sabotage(options.sabotage, &source, &lo);
    const Result lowered = lower(source, lo);
    if (!lowered.ok) {
      *error = "lowering the " + name + " sweep shader failed";
      for (const Diagnostic& d : lowered.diagnostics) *error += "\n" + format_diagnostic(d);
      return {};
    }
    runner::ComputeJob job;
    job.glsl = lowered.output;
    job.buffers = {std::vector<uint8_t>(packed.size() * 4), std::vector<uint8_t>(n * 8)};
    std::memcpy(job.buffers[0].data(), packed.data(), job.buffers[0].size());
    job.groups_x = static_cast<uint32_t>(n / 64);
    const runner::ComputeResult r = runner::run_compute(options.backend, job);
    if (!r.ok) {
      *error = "the " + name + " sweep failed on " + runner::backend_name(options.backend) + ": " + r.error;
      return {};
    }
    std::vector<float> res(n * 2);
    std::memcpy(res.data(), r.buffers[1].data(), r.buffers[1].size());

    OpSweep s;
    s.op = op->name;
    s.bound = op->bound;
    s.bound_u2 = op->bound_u2;
    s.driver = r.device;
    for (const char* f : kFamilies) s.families.push_back({f});
    std::vector<double> cells(static_cast<size_t>(width * width), std::nan(""));
    Reference ref;
    for (size_t i = 0; i < samples.size(); ++i) {
      const Sample& smp = samples[i];
      const float hi = res[2 * i], lo = res[2 * i + 1];
      const double got = std::isfinite(hi) ? join(hi, lo) : hi;
      const double want = ref.want(*op, smp.x, smp.y);
      double rel = 0;
      double bits = correct_bits(got, want, 0, &rel);
      if (std::isfinite(got) && std::isfinite(want) && got != want) {
        rel = ref.rel_err(got);
        bits = std::clamp(-std::log2(rel), 0.0, kMaxBits);
      }
      SweepFamily& fam = s.families[static_cast<size_t>(smp.family)];
      ++fam.samples;
      if (classify(got) != classify(want) && !(got == 0 && want == 0)) ++fam.class_mismatches;
      const bool judged = std::isfinite(got) && std::isfinite(want) && in_range(smp.x) &&
                          (op->unary || in_range(smp.y)) && in_range(want);
      if (bits < fam.min_bits) {
        fam.min_bits = bits;
        fam.worst = "x=" + hex(smp.x) + (op->unary ? "" : " y=" + hex(smp.y)) + " got=" + hex(got) + " want=" + hex(want);
      }
      if (judged) {
        fam.max_err_u2 = std::max(fam.max_err_u2, rel / kU2);
        s.in_range_min_bits = std::min(s.in_range_min_bits, bits);
        s.in_range_max_err_u2 = std::max(s.in_range_max_err_u2, rel / kU2);
      }
      if (smp.cell >= 0) {
        double& c = cells[static_cast<size_t>(smp.cell)];
        c = std::isnan(c) ? bits : std::min(c, bits);
      }
    }
    s.within_bound = s.in_range_max_err_u2 <= s.bound_u2;
    if (!options.heatmap_dir.empty()) {
      std::filesystem::create_directories(options.heatmap_dir);
      s.heatmap = (std::filesystem::path(options.heatmap_dir) /
                   (std::string("sweep_") + op->name + "_" + std::string(to_string(options.target)) + "_" +
                    (options.backend == runner::Backend::Vulkan ? "vulkan" : "gles") + ".png"))
                      .string();
      // Rows: exponent of x from 127 (top) down to -126; columns: exponent of y from -126.
      std::vector<double> flipped(cells.size());
      for (int a = 0; a < width; ++a)
        for (int b = 0; b < width; ++b)
          flipped[static_cast<size_t>((width - 1 - a) * width + b)] = cells[static_cast<size_t>(a * width + b)];
      if (std::string e = write_heatmap_png(s.heatmap, flipped, width, width, std::max(1, 512 / width)); !e.empty()) {
        *error = e;
        return {};
      }
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.push_back(std::move(s));
  }
  return out;
}

std::string format_sweep(const std::vector<OpSweep>& sweeps) {
  std::string s;
  char line[512];
  for (const OpSweep& o : sweeps) {
    std::snprintf(line, sizeof line, "%s on %s: bound %s = %.3g u^2; in range [2^-75, 2^75]: min %.2f bits, max %.3g u^2 -> %s (%.1f s)\n",
                  o.op.c_str(), o.driver.c_str(), o.bound.c_str(), o.bound_u2, o.in_range_min_bits,
                  o.in_range_max_err_u2, o.within_bound ? "WITHIN BOUND" : "OUTSIDE BOUND", o.seconds);
    s += line;
    for (const SweepFamily& f : o.families) {
      std::snprintf(line, sizeof line, "  %-15s %7llu samples  min %6.2f bits  max %8.3g u^2 (in range)  class mismatches %llu\n",
                    f.name.c_str(), static_cast<unsigned long long>(f.samples), f.min_bits, f.max_err_u2,
                    static_cast<unsigned long long>(f.class_mismatches));
      s += line;
      if (f.min_bits < kMaxBits) s += "      worst: " + f.worst + "\n";
    }
    if (!o.heatmap.empty()) s += "  heatmap: " + o.heatmap + "\n";
  }
  return s;
}

}  // namespace doublet::verify
