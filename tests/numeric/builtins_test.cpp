// fp64 built-ins and matrix operations on real drivers: a compute shader written with doubles is
// lowered by doublet and run on Mesa GLES (llvmpipe) and lavapipe; each result is compared with a
// long-double reference on the host against the bound documented for its rule (docs/rules.md):
// exact functions must be exact, relative bounds are C u^2 |result|, absolute ones C u^2 S with
// the S of the rule's header. Inputs are exact float-float values, so the error measured is the
// rule's, not the 53 -> 48-bit input rounding. Sabotage: without the optimizer guard the
// arithmetic built-ins must break their bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "doublet/doublet.hpp"
#include "runner/runner.hpp"

namespace {

using doublet::runner::Backend;
using LD = long double;

constexpr int kSamples = 1024;
constexpr LD kU2 = 1.0L / 281474976710656.0L;  // u^2 = 2^-48

const char* kShader = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec2 words[]; };   // x, y, z, w as (hi, lo)
layout(std430, binding = 1) readonly buffer Bits { uvec2 bits[]; };     // a binary64 per sample
layout(std430, binding = 2) writeonly buffer Outputs { vec2 results[]; };

uint base;
void put(int slot, double r) {
  float hi = float(r);
  results[base + uint(slot)] = vec2(hi, float(r - double(hi)));
}
double load(uint k) { return double(words[k].x) + double(words[k].y); }

void main() {
  uint i = gl_GlobalInvocationID.x;
  base = i * 45u;
  double x = load(4u * i), y = load(4u * i + 1u), z = load(4u * i + 2u), w = load(4u * i + 3u);
  put(0, floor(x));
  put(1, ceil(x));
  put(2, trunc(x));
  put(3, round(x));
  put(4, roundEven(x));
  put(5, fract(x));
  put(6, mod(x, y));
  double ip;
  put(7, modf(x, ip));
  put(8, sign(x));
  put(9, clamp(x, min(y, z), max(y, z)));
  put(10, mix(x, y, z));
  put(11, step(y, x));
  put(12, smoothstep(-abs(z), abs(z), x));
  put(13, fma(x, y, z));
  put(14, ldexp(x, 7));
  int e;
  double m = frexp(x, e);
  put(15, m);
  put(16, ldexp(m, e));
  put(17, inversesqrt(abs(x)));
  dvec3 v = dvec3(x, y, z), u = dvec3(y, z, w);
  put(18, length(v));
  put(19, distance(v, u));
  put(20, dot(v, u));
  dvec3 c = cross(v, u);
  put(21, c.x); put(22, c.y); put(23, c.z);
  dvec3 n = normalize(v);
  put(24, n.x); put(25, n.y); put(26, n.z);
  dvec3 r = reflect(v, u);
  put(27, r.x); put(28, r.y); put(29, r.z);
  dmat3 M = dmat3(dvec3(x, y, z), dvec3(y, z, w), dvec3(z, w, -x));
  dvec3 mv = M * u;
  put(30, mv.x); put(31, mv.y); put(32, mv.z);
  put(33, determinant(M));
  dmat3 inv = inverse(M);
  put(34, inv[0][0]); put(35, inv[0][1]); put(36, inv[0][2]);
  uvec2 ub = unpackDouble2x32(x);
  results[base + 37u] = uintBitsToFloat(ub);
  put(38, packDouble2x32(bits[i]));
  put(39, outerProduct(v, u)[1][2]);
  dmat3 P = M * transpose(M);
  put(40, P[1][2]);
  put(41, matrixCompMult(M, transpose(M))[2][0]);
  put(42, (u * M).y);
  put(43, (M - 2.0lf)[1][1]);
  put(44, (M / y)[2][0]);
}
)";
constexpr int kSlots = 45;

struct Pair {
  float hi, lo;
  LD value() const { return static_cast<LD>(hi) + static_cast<LD>(lo); }
};
Pair split(double x) {
  float hi = static_cast<float>(x);
  return {hi, static_cast<float>(x - static_cast<double>(hi))};
}

struct Sample {
  Pair x, y, z, w;
  double bits_value;  // the binary64 given to packDouble2x32
};

std::vector<Sample> make_inputs(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> exponent(-8.0, 8.0), unit(0.0, 1.0);
  auto random_double = [&] { return std::exp2(exponent(rng)) * (unit(rng) < 0.5 ? -1.0 : 1.0); };
  std::vector<Sample> s(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    double x = random_double();
    // Every 8th sample sits at an integer +- 2^-30, every 8th at a half-integer: the edges of
    // floor/ceil/round/fract.
    if (i % 8 == 1) x = std::round(x * 16) + (i % 16 == 1 ? 1 : -1) * std::exp2(-30);
    if (i % 8 == 2) x = std::floor(x * 16) + 0.5;
    s[i] = {split(x), split(random_double()), split(random_double()), split(random_double()),
            random_double() * std::exp2(exponent(rng) * 4)};
  }
  return s;
}

// How one slot is judged. bound(...) returns the allowed absolute error; exact slots allow 0.
struct Check {
  const char* name;
  std::function<LD(const Sample&)> reference;
  std::function<LD(const Sample&, LD ref)> allowed;  // absolute
  std::function<bool(const Sample&)> skip = nullptr;
};

LD rel(LD c, LD ref) { return c * kU2 * std::fabs(ref); }

struct Vec3 {
  LD a[3];
};
Vec3 v_of(const Sample& s) { return {{s.x.value(), s.y.value(), s.z.value()}}; }
Vec3 u_of(const Sample& s) { return {{s.y.value(), s.z.value(), s.w.value()}}; }
// M columns: (x, y, z), (y, z, w), (z, w, -x); m[col][row].
void matrix_of(const Sample& s, LD m[3][3]) {
  LD c[3][3] = {{s.x.value(), s.y.value(), s.z.value()},
                {s.y.value(), s.z.value(), s.w.value()},
                {s.z.value(), s.w.value(), -s.x.value()}};
  std::memcpy(m, c, sizeof c);
}
LD det3(LD m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[2][1] * m[1][2]) - m[1][0] * (m[0][1] * m[2][2] - m[2][1] * m[0][2]) +
         m[2][0] * (m[0][1] * m[1][2] - m[1][1] * m[0][2]);
}
LD per3(LD m[3][3]) {
  LD a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = std::fabs(m[i][j]);
  return a[0][0] * (a[1][1] * a[2][2] + a[2][1] * a[1][2]) + a[1][0] * (a[0][1] * a[2][2] + a[2][1] * a[0][2]) +
         a[2][0] * (a[0][1] * a[1][2] + a[1][1] * a[0][2]);
}
// cofactor (col c, row r) of the 2x2 minor without column c and row r, with its sign and per.
void cofactor(LD m[3][3], int c, int r, LD* value, LD* per) {
  LD k[2][2];
  for (int i = 0, ci = 0; i < 3; ++i) {
    if (i == c) continue;
    for (int j = 0, rj = 0; j < 3; ++j) {
      if (j == r) continue;
      k[ci][rj++] = m[i][j];
    }
    ++ci;
  }
  *value = ((c + r) % 2 ? -1 : 1) * (k[0][0] * k[1][1] - k[1][0] * k[0][1]);
  *per = std::fabs(k[0][0] * k[1][1]) + std::fabs(k[1][0] * k[0][1]);
}

std::vector<Check> checks() {
  auto exact = [](const Sample&, LD) { return LD(0); };
  std::vector<Check> c(kSlots);
  c[0] = {"floor", [](const Sample& s) { return std::floor(s.x.value()); }, exact};
  c[1] = {"ceil", [](const Sample& s) { return std::ceil(s.x.value()); }, exact};
  c[2] = {"trunc", [](const Sample& s) { return std::trunc(s.x.value()); }, exact};
  c[3] = {"round", [](const Sample& s) { return std::round(s.x.value()); }, exact};
  c[4] = {"roundEven", [](const Sample& s) { return std::nearbyint(s.x.value()); }, exact};
  c[5] = {"fract", [](const Sample& s) { return s.x.value() - std::floor(s.x.value()); },
          [](const Sample&, LD r) { return rel(2, r); }};
  c[6] = {"mod", [](const Sample& s) { return s.x.value() - s.y.value() * std::floor(s.x.value() / s.y.value()); },
          [](const Sample& s, LD) { return 10 * kU2 * (std::fabs(s.x.value()) + std::fabs(s.y.value())); },
          [](const Sample& s) {  // x / y within df_div's error of an integer: floor may differ
            LD q = s.x.value() / s.y.value();
            return std::fabs(q - std::round(q)) < 1e-9L * std::max<LD>(1, std::fabs(q));
          }};
  c[7] = {"modf", [](const Sample& s) { return s.x.value() - std::trunc(s.x.value()); },
          [](const Sample&, LD r) { return rel(3, r); }};
  c[8] = {"sign", [](const Sample& s) { return s.x.value() > 0 ? 1.0L : s.x.value() < 0 ? -1.0L : 0.0L; }, exact};
  c[9] = {"clamp",
          [](const Sample& s) {
            return std::min(std::max(s.x.value(), std::min(s.y.value(), s.z.value())), std::max(s.y.value(), s.z.value()));
          },
          exact};
  c[10] = {"mix", [](const Sample& s) { return s.x.value() + s.z.value() * (s.y.value() - s.x.value()); },
           [](const Sample& s, LD r) {
             return kU2 * (3 * std::fabs(r) + 10 * std::fabs(s.z.value() * (s.y.value() - s.x.value())));
           }};
  c[11] = {"step", [](const Sample& s) { return s.x.value() < s.y.value() ? 0.0L : 1.0L; }, exact};
  c[12] = {"smoothstep",
           [](const Sample& s) {
             LD e = std::fabs(s.z.value());
             LD t = std::clamp((s.x.value() + e) / (2 * e), 0.0L, 1.0L);
             return t * t * (3 - 2 * t);
           },
           [](const Sample&, LD) { return 55 * kU2; }};
  c[13] = {"fma", [](const Sample& s) { return s.x.value() * s.y.value() + s.z.value(); },
           [](const Sample& s, LD r) { return kU2 * (3 * std::fabs(r) + 7 * std::fabs(s.x.value() * s.y.value())); }};
  c[14] = {"ldexp", [](const Sample& s) { return std::ldexp(s.x.value(), 7); }, exact};
  c[15] = {"frexp", [](const Sample& s) {
             int e;
             return std::frexp(s.x.value(), &e);
           },
           exact};
  c[16] = {"ldexp(frexp)", [](const Sample& s) { return s.x.value(); }, exact};
  c[17] = {"inversesqrt", [](const Sample& s) { return 1 / std::sqrt(std::fabs(s.x.value())); },
           [](const Sample&, LD r) { return rel(18.125L, r); }};
  c[18] = {"length", [](const Sample& s) {
             Vec3 v = v_of(s);
             return std::sqrt(v.a[0] * v.a[0] + v.a[1] * v.a[1] + v.a[2] * v.a[2]);
           },
           [](const Sample&, LD r) { return rel(9.625L, r); }};
  c[19] = {"distance", [](const Sample& s) {
             Vec3 v = v_of(s), u = u_of(s);
             LD d0 = v.a[0] - u.a[0], d1 = v.a[1] - u.a[1], d2 = v.a[2] - u.a[2];
             return std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
           },
           [](const Sample&, LD r) { return rel(12.625L, r); }};
  auto dot_sum = [](const Sample& s) {
    Vec3 v = v_of(s), u = u_of(s);
    return std::fabs(v.a[0] * u.a[0]) + std::fabs(v.a[1] * u.a[1]) + std::fabs(v.a[2] * u.a[2]);
  };
  c[20] = {"dot", [](const Sample& s) {
             Vec3 v = v_of(s), u = u_of(s);
             return v.a[0] * u.a[0] + v.a[1] * u.a[1] + v.a[2] * u.a[2];
           },
           [dot_sum](const Sample& s, LD) { return 13 * kU2 * dot_sum(s); }};
  for (int k = 0; k < 3; ++k) {
    int j = (k + 1) % 3, l = (k + 2) % 3;
    c[21 + k] = {"cross", [j, l](const Sample& s) {
                   Vec3 v = v_of(s), u = u_of(s);
                   return v.a[j] * u.a[l] - v.a[l] * u.a[j];
                 },
                 [j, l](const Sample& s, LD) {
                   Vec3 v = v_of(s), u = u_of(s);
                   return 10 * kU2 * (std::fabs(v.a[j] * u.a[l]) + std::fabs(v.a[l] * u.a[j]));
                 }};
    c[24 + k] = {"normalize", [k](const Sample& s) {
                   Vec3 v = v_of(s);
                   return v.a[k] / std::sqrt(v.a[0] * v.a[0] + v.a[1] * v.a[1] + v.a[2] * v.a[2]);
                 },
                 [](const Sample&, LD r) { return rel(24.625L, r); }};
    c[27 + k] = {"reflect", [k](const Sample& s) {
                   Vec3 v = v_of(s), u = u_of(s);
                   LD d = u.a[0] * v.a[0] + u.a[1] * v.a[1] + u.a[2] * v.a[2];
                   return v.a[k] - 2 * d * u.a[k];
                 },
                 [k, dot_sum](const Sample& s, LD r) {
                   return kU2 * (3 * std::fabs(r) + 20 * 2 * dot_sum(s) * std::fabs(u_of(s).a[k]));
                 }};
    c[30 + k] = {"dmat3*dvec3", [k](const Sample& s) {
                   LD m[3][3];
                   matrix_of(s, m);
                   Vec3 u = u_of(s);
                   return m[0][k] * u.a[0] + m[1][k] * u.a[1] + m[2][k] * u.a[2];
                 },
                 [k](const Sample& s, LD) {
                   LD m[3][3];
                   matrix_of(s, m);
                   Vec3 u = u_of(s);
                   return 13 * kU2 * (std::fabs(m[0][k] * u.a[0]) + std::fabs(m[1][k] * u.a[1]) + std::fabs(m[2][k] * u.a[2]));
                 }};
    c[34 + k] = {"inverse", [k](const Sample& s) {
                   LD m[3][3], cof, per;
                   matrix_of(s, m);
                   cofactor(m, k, 0, &cof, &per);  // inverse[0][k] = cofactor(row 0, column k) / det
                   return cof / det3(m);
                 },
                 [k](const Sample& s, LD r) {
                   LD m[3][3], cof, per;
                   matrix_of(s, m);
                   cofactor(m, k, 0, &cof, &per);
                   return std::fabs(r) * kU2 * (10 * per / std::fabs(cof) + 23 * per3(m) / std::fabs(det3(m)) + 15);
                 }};
  }
  c[33] = {"determinant", [](const Sample& s) {
             LD m[3][3];
             matrix_of(s, m);
             return det3(m);
           },
           [](const Sample& s, LD) {
             LD m[3][3];
             matrix_of(s, m);
             return 23 * kU2 * per3(m);
           }};
  c[37] = {"unpackDouble2x32", nullptr, nullptr};  // compared bit for bit below
  c[38] = {"packDouble2x32", [](const Sample& s) { return static_cast<LD>(s.bits_value); },
           [](const Sample&, LD r) { return rel(2, r); }};
  c[39] = {"outerProduct", [](const Sample& s) { return v_of(s).a[2] * u_of(s).a[1]; },
           [](const Sample&, LD r) { return rel(7, r); }};
  auto mat = [](const Sample& s, int col, int row) {
    LD m[3][3];
    matrix_of(s, m);
    return m[col][row];
  };
  // (M M^T)[1][2] = sum_k M[k][2] M[k][1]: a dot of width 3 over the matrix's rows.
  c[40] = {"dmat3*dmat3", [mat](const Sample& s) {
             LD r = 0;
             for (int k = 0; k < 3; ++k) r += mat(s, k, 2) * mat(s, k, 1);
             return r;
           },
           [mat](const Sample& s, LD) {
             LD sum = 0;
             for (int k = 0; k < 3; ++k) sum += std::fabs(mat(s, k, 2) * mat(s, k, 1));
             return 13 * kU2 * sum;
           }};
  c[41] = {"matrixCompMult", [mat](const Sample& s) { return mat(s, 2, 0) * mat(s, 0, 2); },
           [](const Sample&, LD r) { return rel(7, r); }};
  c[42] = {"dvec3*dmat3", [mat](const Sample& s) {
             Vec3 u = u_of(s);
             return u.a[0] * mat(s, 1, 0) + u.a[1] * mat(s, 1, 1) + u.a[2] * mat(s, 1, 2);
           },
           [mat](const Sample& s, LD) {
             Vec3 u = u_of(s);
             return 13 * kU2 *
                    (std::fabs(u.a[0] * mat(s, 1, 0)) + std::fabs(u.a[1] * mat(s, 1, 1)) + std::fabs(u.a[2] * mat(s, 1, 2)));
           }};
  c[43] = {"dmat3-double", [mat](const Sample& s) { return mat(s, 1, 1) - 2; },
           [](const Sample&, LD r) { return rel(3, r); }};
  c[44] = {"dmat3/double", [mat](const Sample& s) { return mat(s, 2, 0) / s.y.value(); },
           [](const Sample&, LD r) { return rel(15, r); }};
  return c;
}

struct SlotResult {
  double worst_ratio = 0;  // max error / allowed (exact slots: error > 0 counts as infinity)
  double worst_bits = 99;  // min -log2(relative error)
  int failures = 0;
  std::string worst;
};

struct Measurement {
  std::string error;
  std::vector<SlotResult> slots;
};

std::string hexfloat(LD v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", static_cast<double>(v));
  return buf;
}

Measurement measure(Backend backend, doublet::Target target, doublet::GuardKind guard) {
  Measurement run;
  doublet::Options options;
  options.stage = doublet::Stage::Compute;
  options.target = target;
  options.guard = guard;
  options.file_name = "builtins.comp";
  doublet::Result lowered = doublet::lower(kShader, options);
  if (!lowered.ok) {
    for (const auto& d : lowered.diagnostics) run.error += doublet::format_diagnostic(d) + "\n";
    return run;
  }
  auto inputs = make_inputs(20261123);
  std::vector<float> words;
  std::vector<uint32_t> bits;
  for (const auto& s : inputs) {
    for (const Pair& p : {s.x, s.y, s.z, s.w}) words.insert(words.end(), {p.hi, p.lo});
    uint64_t b;
    std::memcpy(&b, &s.bits_value, 8);
    bits.insert(bits.end(), {static_cast<uint32_t>(b), static_cast<uint32_t>(b >> 32)});
  }
  doublet::runner::ComputeJob job;
  job.glsl = lowered.output;
  job.buffers.resize(3);
  job.buffers[0].resize(words.size() * 4);
  std::memcpy(job.buffers[0].data(), words.data(), job.buffers[0].size());
  job.buffers[1].resize(bits.size() * 4);
  std::memcpy(job.buffers[1].data(), bits.data(), job.buffers[1].size());
  job.buffers[2].assign(static_cast<size_t>(kSamples) * kSlots * 8, 0);
  job.groups_x = kSamples / 64;
  auto result = doublet::runner::run_compute(backend, job);
  if (!result.ok) {
    run.error = result.error + "\n--- lowered shader ---\n" + lowered.output;
    return run;
  }
  std::vector<float> out(static_cast<size_t>(kSamples) * kSlots * 2);
  std::memcpy(out.data(), result.buffers[2].data(), out.size() * 4);
  auto table = checks();
  run.slots.resize(kSlots);
  std::fesetround(FE_TONEAREST);
  for (int i = 0; i < kSamples; ++i) {
    const Sample& s = inputs[i];
    for (int k = 0; k < kSlots; ++k) {
      SlotResult& slot = run.slots[k];
      const float* word = &out[(static_cast<size_t>(i) * kSlots + k) * 2];
      if (k == 37) {  // the binary64 nearest to x: x = hi + lo is exact in binary64
        double want = static_cast<double>(s.x.value());
        uint64_t want_bits, got_bits;
        std::memcpy(&want_bits, &want, 8);
        uint32_t lo, hi;
        std::memcpy(&lo, &word[0], 4);
        std::memcpy(&hi, &word[1], 4);
        got_bits = (static_cast<uint64_t>(hi) << 32) | lo;
        if (got_bits != want_bits) {
          ++slot.failures;
          slot.worst_ratio = INFINITY;
          slot.worst = "x=" + hexfloat(want) + " bits " + std::to_string(got_bits) + " want " + std::to_string(want_bits);
        }
        continue;
      }
      if (table[k].skip && table[k].skip(s)) continue;
      LD want = table[k].reference(s);
      LD got = static_cast<LD>(word[0]) + static_cast<LD>(word[1]);
      LD err = std::fabs(got - want);
      LD allowed = table[k].allowed(s, want);
      double ratio = err == 0 ? 0.0 : allowed == 0 ? INFINITY : static_cast<double>(err / allowed);
      double bits_ok = want == 0 ? (err == 0 ? 99.0 : -std::log2(static_cast<double>(err)))
                                 : (err == 0 ? 99.0 : -std::log2(static_cast<double>(err / std::fabs(want))));
      slot.worst_bits = std::min(slot.worst_bits, bits_ok);
      if (ratio > 1) ++slot.failures;
      if (ratio > slot.worst_ratio || (std::isnan(static_cast<double>(got)) && slot.worst.empty())) {
        slot.worst_ratio = std::isnan(static_cast<double>(got)) ? INFINITY : ratio;
        slot.worst = "x=" + hexfloat(s.x.value()) + " y=" + hexfloat(s.y.value()) + " z=" + hexfloat(s.z.value()) +
                     " w=" + hexfloat(s.w.value()) + " got=" + hexfloat(got) + " want=" + hexfloat(want);
      }
      if (std::isnan(static_cast<double>(got))) ++slot.failures;
    }
  }
  return run;
}

std::string report(const Measurement& r) {
  std::string s;
  auto table = checks();
  for (int k = 0; k < kSlots; ++k) {
    char line[512];
    std::snprintf(line, sizeof line, "  %2d %-18s min bits %6.2f  worst error/bound %8.3g  failures %d%s%s\n", k,
                  table[k].name, r.slots[k].worst_bits, r.slots[k].worst_ratio, r.slots[k].failures,
                  r.slots[k].worst.empty() ? "" : "  worst: ", r.slots[k].worst.c_str());
    s += line;
  }
  return s;
}

struct Case {
  Backend backend;
  doublet::Target target;
};

class Builtins : public ::testing::TestWithParam<Case> {};

TEST_P(Builtins, EveryResultWithinItsDocumentedBound) {
  auto [backend, target] = GetParam();
  ASSERT_EQ(doublet::runner::backend_unavailable_reason(backend), "");
  Measurement r = measure(backend, target, doublet::GuardKind::Auto);
  ASSERT_TRUE(r.error.empty()) << r.error;
  std::printf("%s %s (%d samples):\n%s", doublet::runner::backend_name(backend),
              std::string(doublet::to_string(target)).c_str(), kSamples, report(r).c_str());
  for (int k = 0; k < kSlots; ++k) EXPECT_EQ(r.slots[k].failures, 0) << checks()[k].name << "\n" << report(r);
}

TEST_P(Builtins, WithoutTheGuardTheBoundsBreak) {
  auto [backend, target] = GetParam();
  Measurement r = measure(backend, target, doublet::GuardKind::None);
  ASSERT_TRUE(r.error.empty()) << r.error;
  int broken = 0;
  for (const auto& slot : r.slots) broken += slot.failures > 0;
  std::printf("%s %s, guard removed:\n%s", doublet::runner::backend_name(backend),
              std::string(doublet::to_string(target)).c_str(), report(r).c_str());
  EXPECT_GE(broken, 5) << "sabotage (no guard) did not break the bounds:\n" << report(r);
}

INSTANTIATE_TEST_SUITE_P(Drivers, Builtins,
                         ::testing::Values(Case{Backend::Gles, doublet::Target::Es310},
                                           Case{Backend::Gles, doublet::Target::Es320},
                                           Case{Backend::Vulkan, doublet::Target::Es310},
                                           Case{Backend::Vulkan, doublet::Target::Glsl450}),
                         [](const auto& info) {
                           return std::string(doublet::runner::backend_name(info.param.backend)) + "_" +
                                  std::string(doublet::to_string(info.param.target));
                         });

}  // namespace
