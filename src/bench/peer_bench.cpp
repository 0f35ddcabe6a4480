#include "bench/peer_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

#include "bench/kernels.hpp"
#include "bench/mesa_fp64.hpp"
#include "bench/variants.hpp"
#include "runner/timed_compute.hpp"

namespace doublet::bench {

const std::vector<std::string>& peer_ops() {
  static const std::vector<std::string> ops{"add", "sub", "mul", "div", "sqrt"};
  return ops;
}

const std::vector<std::string>& peer_variants() {
  static const std::vector<std::string> v{"fp32", "exact", "mesa", "native"};
  return v;
}

namespace {

const char* kEsHeader = "#version 310 es\nprecision highp float;\nprecision highp int;\n";
const char* kCheckBuffers =
    "layout(local_size_x = 64) in;\n"
    "layout(std430, binding = 0) readonly buffer In { uvec4 ab[]; };\n"
    "layout(std430, binding = 1) writeonly buffer Out { uvec2 r[]; };\n";

std::string words(double v) {
  uint64_t u;
  std::memcpy(&u, &v, 8);
  char buf[64];
  std::snprintf(buf, sizeof buf, "uvec2(0x%08Xu, 0x%08Xu)", static_cast<unsigned>(u & 0xFFFFFFFFu),
                static_cast<unsigned>(u >> 32));
  return buf;
}

std::string hex64(uint64_t v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "0x%016llX", static_cast<unsigned long long>(v));
  return buf;
}

bool is_nan(uint64_t v) { return (v & 0x7FFFFFFFFFFFFFFFull) > 0x7FF0000000000000ull; }

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

bool run_check_shader(runner::Backend backend, const std::string& glsl, const std::vector<uint64_t>& ab,
               std::vector<uint64_t>* out, std::string* error) {
  runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers = {bytes_of(ab), std::vector<uint8_t>(ab.size() / 2 * 8)};
  job.groups_x = static_cast<uint32_t>((ab.size() / 2 + 63) / 64);
  const runner::ComputeResult r = runner::run_compute(backend, job);
  if (!r.ok) {
    *error = r.error;
    return false;
  }
  out->resize(ab.size() / 2);
  std::memcpy(out->data(), r.buffers[1].data(), out->size() * 8);
  return true;
}

PeerBits compare_with_native(const std::string& op, const std::string& variant, runner::Backend backend,
                             const std::string& glsl, const std::vector<uint64_t>& ab, const std::vector<uint64_t>& native) {
  PeerBits b;
  b.op = op, b.variant = variant, b.backend = backend, b.inputs = native.size();
  std::vector<uint64_t> got;
  if (glsl.empty()) {
    b.note = "no shader";
    return b;
  }
  if (!run_check_shader(backend, glsl, ab, &got, &b.note)) return b;
  b.ok = true;
  for (size_t i = 0; i < native.size(); ++i) {
    if (got[i] == native[i]) continue;
    ++b.differing;
    const uint64_t sign = 0x8000000000000000ull, magnitude = ~sign;
    const bool subnormal = (native[i] & magnitude) != 0 && (native[i] & 0x7FF0000000000000ull) == 0;
    if (is_nan(got[i]) && is_nan(native[i])) ++b.nan_only;
    else if ((got[i] & magnitude) == 0 && subnormal) ++b.flushed;
    else if ((got[i] & sign) == (native[i] & sign) && !is_nan(got[i]) && !is_nan(native[i]) &&
             ((got[i] & magnitude) - (native[i] & magnitude) == 1 || (native[i] & magnitude) - (got[i] & magnitude) == 1))
      ++b.one_ulp;
    if (!(is_nan(got[i]) && is_nan(native[i])) && b.example.empty())
      b.example = hex64(ab[2 * i]) + (op == "sqrt" ? "" : ", " + hex64(ab[2 * i + 1])) + ": got " + hex64(got[i]) +
                  ", native " + hex64(native[i]);
  }
  return b;
}

namespace {

struct Contender {
  PeerTiming row;
  runner::ComputeJob job;
};

}  // namespace

std::string mesa_chain_kernel(const std::string& op, int steps, const std::string& library) {
  // The same chains as kernel_source (bench/kernels.cpp), spelled with Mesa's functions.
  const std::string cvt = "__fp32_to_fp64";
  std::string setup, step;
  if (op == "add" || op == "sub") {
    setup = "uvec2 x = " + cvt + "(p.x); uvec2 y = " + cvt + "(p.y);";
  } else if (op == "mul" || op == "div") {
    setup = "uvec2 x = " + cvt + "(p.x); uvec2 y = __fadd64(" + words(1.0) + ", __fmul64(" + cvt + "(p.y), " +
            words(0.001) + "));";
  } else {
    setup = "uvec2 x = __fadd64(" + cvt + "(p.x), " + cvt + "(p.y));";
  }
  const std::string expr = mesa_op_expression(op, "x", "y");
  std::string unrolled;
  for (int u = 0; u < kUnroll; ++u) unrolled += "    x = " + expr + ";\n";
  return std::string(kEsHeader) +
         "layout(local_size_x = " + std::to_string(kLocalSize) + ") in;\n"
         "layout(std430, binding = 0) readonly buffer Inputs { vec4 inp[]; };\n"
         "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n" +
         library +
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  vec4 p = inp[i];\n"
         "  " + setup + "\n"
         "  for (int k = 0; k < " + std::to_string(rounded_steps(steps) / kUnroll) + "; ++k) {\n" +
         unrolled +
         "  }\n"
         "  outp[i] = vec4(__fp64_to_fp32(x));\n"
         "}\n";
}

std::string mesa_check_shader(const std::string& op, const std::string& library) {
  return std::string(kEsHeader) + kCheckBuffers + library +
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n  uvec2 a = ab[i].xy, b = ab[i].zw;\n  r[i] = " +
         mesa_op_expression(op, "a", "b") + ";\n}\n";
}

std::string double_check_shader(const std::string& op) {
  const std::string expr = op == "add" ? "a + b" : op == "sub" ? "a - b" : op == "mul" ? "a * b" : op == "div" ? "a / b" : "sqrt(a)";
  return std::string("#version 450\n") + kCheckBuffers +
         "void main() {\n  uint i = gl_GlobalInvocationID.x;\n"
         "  double a = packDouble2x32(ab[i].xy);\n  double b = packDouble2x32(ab[i].zw);\n"
         "  r[i] = unpackDouble2x32(" + expr + ");\n}\n";
}

// The input classes of tests/exact (random patterns, an exponent grid at the subnormal/1/overflow
// boundaries, short significands whose results tie, nearby magnitudes, halfway subnormal results,
// special values), in equal shares.
std::vector<uint64_t> peer_check_inputs(size_t count) {
  std::mt19937_64 rng(20261124);
  static const uint64_t kSpecial[] = {0, 1, 0x000FFFFFFFFFFFFFull, 0x0010000000000000ull, 0x7FEFFFFFFFFFFFFFull,
                                      0x7FF0000000000000ull, 0x7FF8000000000000ull, 0x7FF0000000000001ull,
                                      0x3FF0000000000000ull, 0x3CA0000000000000ull};
  auto sign = [&](uint64_t m) { return (rng() & 1) ? m | 0x8000000000000000ull : m; };
  auto special = [&] { return sign(kSpecial[rng() % std::size(kSpecial)]); };
  auto grid = [&]() -> uint64_t {
    switch (rng() % 3) {
      case 0: return rng() % 4;
      case 1: return 1020 + rng() % 7;
      default: return 2043 + rng() % 5;
    }
  };
  std::vector<uint64_t> ab(2 * count);
  for (size_t i = 0; i < count; ++i) {
    uint64_t a = rng(), b = rng();
    switch (i % 6) {
      case 1: a = sign((grid() << 52) | (rng() >> 12)), b = sign((grid() << 52) | (rng() >> 12)); break;
      case 2: {
        const uint64_t ea = rng() % 2047, eb = (ea + 2047 - 60 + rng() % 120) % 2047;
        a = sign((ea << 52) | ((rng() >> 34) << 22)), b = sign((eb << 52) | ((rng() >> 38) << 26));
        break;
      }
      case 3: {
        const uint64_t e = rng() % 60;
        a = sign((e << 52) | (rng() >> 12)), b = sign(((e + rng() % 3) << 52) | (rng() >> 12));
        break;
      }
      case 4: {
        const uint64_t j = 1 + rng() % 60;
        a = sign((j << 52) | (rng() >> 12) | 1), b = sign((rng() & 1) ? (j + 1023) << 52 : (1023 - j) << 52);
        break;
      }
      case 5: a = special(), b = (rng() & 1) ? special() : rng(); break;
      default: break;
    }
    ab[2 * i] = a, ab[2 * i + 1] = b;
  }
  return ab;
}

bool run_peer_bench(const PeerOptions& o, PeerReport* report, std::string* error) {
  report->options = o;
  std::ifstream in(o.peer_path);
  if (!in) {
    *error = o.peer_path + ": cannot read (fetch it with scripts/fetch-mesa-fp64)";
    return false;
  }
  std::stringstream text;
  text << in.rdbuf();
  std::string library;
  if (!adapt_mesa_fp64(text.str(), &library, error)) {
    *error = o.peer_path + ": " + *error;
    return false;
  }
  if (std::ifstream source(o.peer_path + ".source"); source) {
    std::stringstream s;
    s << source.rdbuf();
    report->peer_source = s.str();
  }
  const std::vector<uint64_t> ab = peer_check_inputs(static_cast<size_t>(o.check_inputs));
  for (const std::string& op : o.ops) {
    // Bit identity: one application per input, against native fp64 on lavapipe.
    std::vector<uint64_t> native;
    if (!run_check_shader(runner::Backend::Vulkan, double_check_shader(op), ab, &native, error)) {
      *error = op + ": native fp64 reference on lavapipe: " + *error;
      return false;
    }
    for (runner::Backend backend : o.backends) {
      const Variant exact = make_variant(Mode::Exact, backend, double_check_shader(op), o.target, op + ".comp");
      PeerBits e = compare_with_native(op, "exact", backend, exact.glsl, ab, native);
      if (!exact.note.empty()) e.note = exact.note;
      report->bits.push_back(e);
      report->bits.push_back(compare_with_native(op, "mesa", backend, mesa_check_shader(op, library), ab, native));
    }
    // Timing: every contender prepared, then dispatches interleaved across them.
    const Kernel* kernel = find_kernel(op);
    const std::string source = kernel_source(*kernel, o.steps);
    for (runner::Backend backend : o.backends) {
      std::vector<Contender> contenders;
      for (const std::string& variant : peer_variants()) {
        Contender c;
        c.row.op = op, c.row.variant = variant, c.row.backend = backend;
        std::string glsl;
        if (variant == "mesa") {
          glsl = mesa_chain_kernel(op, o.steps, library);
        } else {
          const Mode mode = variant == "fp32" ? Mode::Fp32 : variant == "exact" ? Mode::Exact : Mode::Native;
          const Variant v = make_variant(mode, backend, source, o.target, op + ".comp");
          glsl = v.glsl;
          c.row.note = v.note;
          c.row.not_applicable = v.not_applicable;
        }
        if (!glsl.empty()) {
          c.row.ok = true;  // until a dispatch fails
          c.row.spirv_instructions = shader_size(glsl).spirv_instructions;
          c.job.glsl = glsl;
          c.job.buffers = kernel_buffers(*kernel, o.elements);
          c.job.groups_x = static_cast<uint32_t>((o.elements + kLocalSize - 1) / kLocalSize);
        }
        contenders.push_back(std::move(c));
      }
      // Up to 3 rounds, each running every contender in turn: interleaved against load from
      // elsewhere, while each (large) shader is compiled only once per round.
      const int rounds = std::min(o.repetitions, 3);
      for (int round = 0; round < rounds; ++round)
        for (Contender& c : contenders) {
          if (!c.row.ok) continue;
          const int reps = o.repetitions / rounds + (round < o.repetitions % rounds ? 1 : 0);
          const runner::TimedResult t = runner::run_compute_timed(backend, c.job, round == 0 ? o.warmup : 1, reps);
          if (!t.ok) {
            c.row.ok = false;
            c.row.note = t.error;
            continue;
          }
          report->devices[backend == runner::Backend::Vulkan ? "vulkan" : "gles"] = t.device + " (" + t.clock + ")";
          c.row.seconds.insert(c.row.seconds.end(), t.seconds.begin(), t.seconds.end());
        }
      for (Contender& c : contenders) {
        if (c.row.ok) {
          c.row.median_seconds = median_of(c.row.seconds);
          c.row.min_seconds = *std::min_element(c.row.seconds.begin(), c.row.seconds.end());
        }
        report->timings.push_back(std::move(c.row));
      }
    }
  }
  return true;
}

namespace {

const PeerTiming* find_timing(const PeerReport& r, const std::string& op, runner::Backend b, const std::string& variant) {
  for (const PeerTiming& t : r.timings)
    if (t.ok && t.op == op && t.backend == b && t.variant == variant && t.median_seconds > 0) return &t;
  return nullptr;
}

std::string ms(const PeerTiming* t) {
  if (!t) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", 1e3 * t->median_seconds);
  return buf;
}

std::string ratio(const PeerTiming* a, const PeerTiming* b) {
  if (!a || !b) return "—";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f×", a->median_seconds / b->median_seconds);
  return buf;
}

}  // namespace

std::string format_peer_markdown(const PeerReport& r) {
  const PeerOptions& o = r.options;
  std::ostringstream out;
  out << "# doublet exact vs Mesa's soft-fp64 (float64.glsl) vs native fp64 vs fp32\n\n"
      << "command: " << r.command << "\n"
      << "peer: " << o.peer_path << "\n";
  std::istringstream source(r.peer_source);
  for (std::string line; std::getline(source, line);) out << "  " << line << "\n";
  out << "kernels: " << o.elements << " invocations x " << rounded_steps(o.steps)
      << " dependent steps; median of " << o.repetitions
      << " dispatches in up to 3 rounds over the variants; exact and fp32 lowered for " << to_string(o.target)
      << "; Mesa's file as GLSL ES 3.10 (uint64_t spelled uvec2); native = the fp64 shader on lavapipe\n"
      << "mesa: add = __fadd64, sub = __fadd64(a, __fneg64(b)), mul = __fmul64, sqrt = __fsqrt64, "
         "div = __fmul64(a, rcp(b)) with rcp as Mesa's NIR lowers it (float estimate, two Newton steps on "
         "__ffma64: the file has no division)\n\n";
  for (runner::Backend b : o.backends) {
    const std::string key = b == runner::Backend::Vulkan ? "vulkan" : "gles";
    const auto dev = r.devices.find(key);
    out << "### " << key << (dev != r.devices.end() ? " — " + dev->second : "") << "\n\n"
        << "| op | fp32 ms | exact ms | mesa ms | native ms | exact / mesa | exact / native | exact / fp32 | mesa / native | SPIR-V instr exact, mesa |\n"
        << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const std::string& op : o.ops) {
      const PeerTiming* fp32 = find_timing(r, op, b, "fp32");
      const PeerTiming* exact = find_timing(r, op, b, "exact");
      const PeerTiming* mesa = find_timing(r, op, b, "mesa");
      const PeerTiming* native = find_timing(r, op, runner::Backend::Vulkan, "native");
      size_t ex_instr = 0, mesa_instr = 0;
      for (const PeerTiming& t : r.timings)
        if (t.op == op && t.backend == b) {
          if (t.variant == "exact") ex_instr = t.spirv_instructions;
          if (t.variant == "mesa") mesa_instr = t.spirv_instructions;
        }
      out << "| " << op << " | " << ms(fp32) << " | " << ms(exact) << " | " << ms(mesa) << " | " << ms(native) << " | "
          << ratio(exact, mesa) << " | " << ratio(exact, native) << " | " << ratio(exact, fp32) << " | "
          << ratio(mesa, native) << " | " << ex_instr << ", " << mesa_instr << " |\n";
    }
    out << "\n";
  }
  out << "### bit identity with native fp64 (lavapipe), " << o.check_inputs
      << " inputs per op: specials, exponent grid, ties, cancellation, halfway subnormals, random\n\n"
      << "| op | backend | exact: differing | mesa: differing | mesa: NaN vs NaN | mesa: 1 ulp off | mesa: 0 for a subnormal | mesa: first non-NaN difference (a, b: got, native) |\n"
      << "|---|---|---|---|---|---|---|---|\n";
  for (const std::string& op : o.ops)
    for (runner::Backend b : o.backends) {
      const PeerBits* e = nullptr;
      const PeerBits* m = nullptr;
      for (const PeerBits& x : r.bits)
        if (x.op == op && x.backend == b) (x.variant == "exact" ? e : m) = &x;
      auto count = [](const PeerBits* x) { return !x ? std::string("—") : x->ok ? std::to_string(x->differing) : "failed"; };
      out << "| " << op << " | " << (b == runner::Backend::Vulkan ? "vulkan" : "gles") << " | " << count(e) << " | "
          << count(m) << " | " << (m && m->ok ? std::to_string(m->nan_only) : "—") << " | "
          << (m && m->ok ? std::to_string(m->one_ulp) : "—") << " | " << (m && m->ok ? std::to_string(m->flushed) : "—") << " | "
          << (m && !m->example.empty() ? m->example : "—") << " |\n";
    }
  std::vector<std::string> notes;
  for (const PeerTiming& t : r.timings)
    if (!t.ok && !t.not_applicable && !t.note.empty())
      notes.push_back(t.op + " " + t.variant + " on " + (t.backend == runner::Backend::Vulkan ? "vulkan" : "gles") + ": " + t.note);
  for (const PeerBits& x : r.bits)
    if (!x.ok) notes.push_back(x.op + " " + x.variant + " bit check on " + (x.backend == runner::Backend::Vulkan ? "vulkan" : "gles") + ": " + x.note);
  if (!notes.empty()) {
    out << "\nFailed:\n";
    for (const std::string& n : notes) out << "- " << n << "\n";
  }
  return out.str();
}

}  // namespace doublet::bench
