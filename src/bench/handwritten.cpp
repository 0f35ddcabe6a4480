#include "bench/handwritten.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include <doublet/doublet.hpp>
#include <doublet/split.hpp>

#include "bench/kernels.hpp"
#include "bench/variants.hpp"
#include "demo/mandelbrot.hpp"
#include "demo/modes.hpp"
#include "runner/timed_compute.hpp"

namespace doublet::bench {

// Written for this benchmark from the algorithms a hand-written library uses (luma.gl's fp64
// module, after Thall's "Extended-precision floating-point numbers for GPU computation", 2006,
// and Dekker 1971 / Knuth TAOCP 4.2.2): per-operation functions on vec2(hi, lo); the guard is a
// uniform ONE (the host sets 1.0) multiplied into the steps a compiler would otherwise simplify
// away; the product splits both operands (Veltkamp, 4097); addition is the accurate two-TwoSum
// form; the product adds the two cross terms with a renormalisation after each; division is one
// Newton correction of hi/b.hi; sqrt is Karp's method (one correction of a.hi * 1/sqrt(a.hi)).
const char* const kHandwrittenLibrary = R"(uniform float ONE;

vec2 ff_split(float a) {
  float t = 4097.0 * a;
  float big = t - a;
  float hi = t * ONE - big;
  float lo = a * ONE - hi;
  return vec2(hi, lo);
}

vec2 ff_fast_sum(float a, float b) {
  float s = (a + b) * ONE;
  float back = (s - a) * ONE;
  return vec2(s, b - back);
}

vec2 ff_sum(float a, float b) {
  float s = a + b;
  float bv = (s * ONE - a) * ONE;
  float av = (s - bv) * ONE;
  float e = (a - av) * ONE * ONE * ONE + (b - bv);
  return vec2(s, e);
}

vec2 ff_diff(float a, float b) {
  float s = a - b;
  float bv = (s * ONE - a) * ONE;
  float av = (s - bv) * ONE;
  float e = (a - av) * ONE * ONE * ONE - (b + bv);
  return vec2(s, e);
}

vec2 ff_prod(float a, float b) {
  float p = a * b;
  vec2 as = ff_split(a);
  vec2 bs = ff_split(b);
  float e = ((as.x * bs.x - p) + as.x * bs.y + as.y * bs.x) + as.y * bs.y;
  return vec2(p, e);
}

vec2 ff_square(float a) {
  float p = a * a;
  vec2 as = ff_split(a);
  float e = ((as.x * as.x - p) * ONE + 2.0 * as.x * as.y * ONE * ONE) + as.y * as.y * ONE * ONE * ONE;
  return vec2(p, e);
}

vec2 ff_add(vec2 a, vec2 b) {
  vec2 s = ff_sum(a.x, b.x);
  vec2 t = ff_sum(a.y, b.y);
  s = ff_fast_sum(s.x, s.y + t.x);
  return ff_fast_sum(s.x, s.y + t.y);
}

vec2 ff_sub(vec2 a, vec2 b) {
  vec2 s = ff_diff(a.x, b.x);
  vec2 t = ff_diff(a.y, b.y);
  s = ff_fast_sum(s.x, s.y + t.x);
  return ff_fast_sum(s.x, s.y + t.y);
}

vec2 ff_mul(vec2 a, vec2 b) {
  vec2 p = ff_prod(a.x, b.x);
  p = ff_fast_sum(p.x, p.y + a.x * b.y);
  return ff_fast_sum(p.x, p.y + a.y * b.x);
}

vec2 ff_div(vec2 a, vec2 b) {
  float r = 1.0 / b.x;
  vec2 q = a * r;
  float rem = ff_sub(a, ff_mul(b, q)).x;
  return ff_add(q, ff_prod(r, rem));
}

vec2 ff_sqrt(vec2 a) {
  if (a.x <= 0.0) return vec2(sqrt(a.x), 0.0);
  float r = 1.0 / sqrt(a.x);
  float y = a.x * r;
  vec2 y2 = ff_square(y) * ONE;
  float rem = ff_sub(a, y2).x;
  return ff_add(vec2(y, 0.0), ff_prod(r * 0.5, rem));
}

bool ff_lt(vec2 a, vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
)";

const std::vector<std::string>& handwritten_ops() {
  static const std::vector<std::string> ops{"add", "sub", "mul", "div", "sqrt", "mulf", "addf", "sqr", "pow2", "mandelbrot"};
  return ops;
}

namespace {

constexpr int kAccuracySteps = kUnroll;

struct Step {
  const char* dbl;  // one step on doubles
  const char* hw;   // the same with the library
};

Step step_of(const std::string& op) {
  if (op == "add") return {"x = x + y;", "x = ff_add(x, y);"};
  if (op == "sub") return {"x = x - y;", "x = ff_sub(x, y);"};
  if (op == "mul") return {"x = x * y;", "x = ff_mul(x, y);"};
  if (op == "div") return {"x = x / y;", "x = ff_div(x, y);"};
  if (op == "sqrt") return {"x = sqrt(x);", "x = ff_sqrt(x);"};
  // The optimizer's cases: a float widened to double; a square (plus a constant, so the chain
  // stays bounded: x -> x^2 + w converges); a product by a power of two (x -> x/2 + y converges).
  if (op == "addf") return {"x = x + double(q);", "x = ff_add(x, vec2(q, 0.0));"};
  if (op == "sqr") return {"x = x * x + w;", "x = ff_add(ff_mul(x, x), w);"};
  if (op == "pow2") return {"x = x * 0.5lf + y;", "x = ff_add(ff_mul(x, vec2(0.5, 0.0)), y);"};
  return {"x = x * double(q);", "x = ff_mul(x, vec2(q, 0.0));"};  // mulf: a float widened to double
}

const char* kBuffers =
    "layout(std430, binding = 0) readonly buffer Inputs { vec4 inp[]; };\n"
    "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n";

std::string loop(const std::string& step, int steps) {
  std::string s = "  for (int k = 0; k < " + std::to_string(rounded_steps(steps) / kUnroll) + "; ++k) {\n";
  for (int u = 0; u < kUnroll; ++u) s += "    " + step + "\n";
  return s + "  }\n";
}

// The Mandelbrot of src/demo/mandelbrot.cpp written by hand with the library: each double
// operation of the original becomes the library call a user would write.
const char* kHandwrittenMandelbrot = R"(
layout(local_size_x = 8, local_size_y = 8) in;
uniform vec2 center_hi;
uniform vec2 center_lo;
uniform float scale_hi;
uniform float scale_lo;
uniform vec2 resolution;
uniform float max_iterations;
layout(std430, binding = 0) buffer Iterations { uint iterations[]; };
)";
const char* kHandwrittenMandelbrotMain = R"(
void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (float(p.x) >= resolution.x || float(p.y) >= resolution.y) return;
  vec2 scale = vec2(scale_hi, scale_lo);
  vec2 off = vec2(p) + 0.5 - 0.5 * resolution;
  vec2 cx = ff_add(vec2(center_hi.x, center_lo.x), ff_mul(vec2(off.x, 0.0), scale));
  vec2 cy = ff_add(vec2(center_hi.y, center_lo.y), ff_mul(vec2(off.y, 0.0), scale));
  vec2 zx = vec2(0.0);
  vec2 zy = vec2(0.0);
  uint n = 0u;
  uint limit = uint(max_iterations);
  while (n < limit && ff_lt(ff_add(ff_mul(zx, zx), ff_mul(zy, zy)), vec2(4.0, 0.0))) {
    vec2 nx = ff_add(ff_sub(ff_mul(zx, zx), ff_mul(zy, zy)), cx);
    vec2 ny = ff_add(ff_mul(ff_mul(vec2(2.0, 0.0), zx), zy), cy);
    zx = nx;
    zy = ny;
    ++n;
  }
  iterations[p.y * uint(resolution.x) + p.x] = n;
}
)";

std::string es310_header() { return "#version 310 es\nprecision highp float;\nprecision highp int;\n"; }

double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Inputs {
  std::vector<float> words;  // per element: a, b_hi, b_lo, q
};

Inputs make_inputs(int elements) {
  Inputs in;
  in.words.resize(static_cast<size_t>(elements) * 4);
  uint64_t state = 0x9e3779b97f4a7c15ull;
  auto next = [&] {  // xorshift64*: reproducible
    state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
    return static_cast<double>((state * 2685821657736338717ull) >> 11) / 9007199254740992.0;  // [0, 1)
  };
  for (int i = 0; i < elements; ++i) {
    const double a = 0.5 + 0.5 * next();
    const double b = 1.0 + 0.001 * next();  // a double with a full lo word
    const FloatPair bp = split(b);
    in.words[4 * i + 0] = static_cast<float>(a);
    in.words[4 * i + 1] = bp.hi;
    in.words[4 * i + 2] = bp.lo;
    in.words[4 * i + 3] = static_cast<float>(1.0 + 0.001 * next());
  }
  return in;
}

// The chain on the host in long double (64-bit significand) from the same inputs.
long double reference(const std::string& op, const float* in, int steps) {
  long double x = in[0];
  const long double y = static_cast<long double>(in[1]) + static_cast<long double>(in[2]);
  const long double q = in[3];
  if (op == "sqrt") x = x + y;
  const long double w = y - static_cast<long double>(0.8f);
  if (op == "sqr") x = 0.25L;
  for (int s = 0; s < steps; ++s) {
    if (op == "add") x = x + y;
    else if (op == "sub") x = x - y;
    else if (op == "mul") x = x * y;
    else if (op == "div") x = x / y;
    else if (op == "sqrt") x = std::sqrt(x);
    else if (op == "addf") x = x + q;
    else if (op == "sqr") x = x * x + w;
    else if (op == "pow2") x = x * 0.5L + y;
    else x = x * q;
  }
  return x;
}

struct Contender {
  std::string name;
  bool handwritten = false;
  Target target = Target::Es310;
  bool optimize = true;
};

std::vector<Contender> contenders() {
  return {{"handwritten (ONE guard)", true},
          {"doublet es310 -O0", false, Target::Es310, false},
          {"doublet es310", false, Target::Es310, true},
          {"doublet es320 -O0", false, Target::Es320, false},
          {"doublet es320", false, Target::Es320, true}};
}

bool lower_for(const Contender& v, const std::string& source, std::string* out, std::string* error) {
  Options o;
  o.stage = Stage::Compute;
  o.target = v.target;
  o.optimize = v.optimize;
  o.file_name = "bench.comp";
  Result r = lower(source, o);
  if (!r.ok) {
    *error = "doublet::lower failed:";
    for (const Diagnostic& d : r.diagnostics) *error += " " + format_diagnostic(d) + ";";
    return false;
  }
  *out = std::move(r.output);
  return true;
}

void set_mandelbrot_uniforms(runner::ComputeJob& job, const HandwrittenOptions& o, bool split_doubles) {
  const double cx = -1.7497591451303665, cy = 0.0;  // the demo's view (src/demo/mandelbrot.hpp)
  if (split_doubles) {
    const FloatPair x = split(cx), y = split(cy), s = split(o.mandelbrot_zoom);
    job.uniforms["center_hi"] = {x.hi, y.hi};
    job.uniforms["center_lo"] = {x.lo, y.lo};
    job.uniforms["scale_hi"] = {s.hi};
    job.uniforms["scale_lo"] = {s.lo};
  } else {
    job.uniforms["center"] = {cx, cy};
    job.uniforms["scale"] = {o.mandelbrot_zoom};
  }
  job.uniforms["resolution"] = {static_cast<double>(o.mandelbrot_size), static_cast<double>(o.mandelbrot_size)};
  job.float_uniforms["max_iterations"] = static_cast<float>(o.mandelbrot_iterations);
  job.float_uniforms["ONE"] = 1.0f;
  job.groups_x = job.groups_y = static_cast<uint32_t>((o.mandelbrot_size + 7) / 8);
  job.buffers.assign(1, std::vector<uint8_t>(static_cast<size_t>(o.mandelbrot_size) * o.mandelbrot_size * 4));
}

}  // namespace

std::string handwritten_kernel(const std::string& op, int steps) {
  if (op == "mandelbrot") return es310_header() + kHandwrittenMandelbrot + "\n" + kHandwrittenLibrary + kHandwrittenMandelbrotMain;
  std::string s = es310_header() + "layout(local_size_x = " + std::to_string(kLocalSize) + ") in;\n" + kBuffers + "\n" +
                  kHandwrittenLibrary +
                  "\nvoid main() {\n"
                  "  uint i = gl_GlobalInvocationID.x;\n"
                  "  vec4 p = inp[i];\n"
                  "  vec2 x = vec2(p.x, 0.0);\n"
                  "  vec2 y = vec2(p.y, p.z);\n"
                  "  float q = p.w;\n";
  if (op == "sqrt") s += "  x = ff_add(x, y);\n";
  if (op == "sqr") s += "  vec2 w = ff_sub(y, vec2(0.8, 0.0));\n  x = vec2(0.25, 0.0);\n";
  s += loop(step_of(op).hw, steps);
  return s + "  outp[i] = vec4(x, 0.0, 0.0);\n}\n";
}

std::string double_kernel(const std::string& op, int steps) {
  if (op == "mandelbrot") return demo::kMandelbrotComputeShader;
  std::string s = "#version 450\nlayout(local_size_x = " + std::to_string(kLocalSize) + ") in;\n" + kBuffers +
                  "void main() {\n"
                  "  uint i = gl_GlobalInvocationID.x;\n"
                  "  vec4 p = inp[i];\n"
                  "  double x = double(p.x);\n"
                  "  double y = double(p.y) + double(p.z);\n"
                  "  float q = p.w;\n";
  if (op == "sqrt") s += "  x = x + y;\n";
  if (op == "sqr") s += "  double w = y - 0.800000011920928955078125lf;\n  x = 0.25lf;\n";
  s += loop(step_of(op).dbl, steps);
  // hi and lo of the result: x - double(float(x)) is exact.
  return s + "  outp[i] = vec4(float(x), float(x - double(float(x))), 0.0, 0.0);\n}\n";
}

double kernel_bits(const std::string& op, const std::string& glsl, int elements, std::string* error) {
  const Inputs inputs = make_inputs(elements);
  runner::ComputeJob job;
  job.glsl = glsl;
  job.buffers = {bytes_of(inputs.words), std::vector<uint8_t>(inputs.words.size() * 4)};
  job.float_uniforms["ONE"] = 1.0f;
  job.groups_x = static_cast<uint32_t>((elements + kLocalSize - 1) / kLocalSize);
  const runner::ComputeResult r = runner::run_compute(runner::Backend::Gles, job);
  if (!r.ok) {
    *error = r.error;
    return -1;
  }
  WorstRelativeError error_of;
  for (int i = 0; i < elements; ++i) {
    const long double got = stored_hi_lo(r.buffers[1], static_cast<size_t>(i));
    const long double ref = reference(op, &inputs.words[4 * static_cast<size_t>(i)], kAccuracySteps);
    error_of.add(std::fabs(got - ref) / std::fabs(ref));
  }
  return error_of.bits(64.0);
}

bool run_handwritten(const HandwrittenOptions& o, HandwrittenReport* report, std::string* error) {
  report->options = o;
  std::vector<std::string> ops = o.ops.empty() ? handwritten_ops() : o.ops;
  for (const std::string& op : ops)
    if (std::find(handwritten_ops().begin(), handwritten_ops().end(), op) == handwritten_ops().end()) {
      *error = "unknown op '" + op + "' for --handwritten";
      return false;
    }
  if (o.elements < kLocalSize || o.repetitions < 1 || o.mandelbrot_size < 8 || o.mandelbrot_iterations < 1) {
    *error = "--handwritten needs at least 64 elements, 1 repetition, 8x8 pixels and 1 iteration";
    return false;
  }
  const Inputs inputs = make_inputs(o.elements);
  for (const std::string& op : ops) {
    const bool mandel = op == "mandelbrot";
    std::vector<uint32_t> native_counts;
    if (mandel) {  // the reference picture: native fp64 on lavapipe
      std::string glsl, e;
      if (demo::shader_for_mode(demo::Mode::Native, demo::kMandelbrotComputeShader, Stage::Compute, Target::Es310,
                                &glsl, &e)) {
        runner::ComputeJob job;
        job.glsl = glsl;
        set_mandelbrot_uniforms(job, o, false);
        const runner::ComputeResult r = runner::run_compute(runner::Backend::Vulkan, job);
        if (r.ok) {
          native_counts.resize(r.buffers[0].size() / 4);
          std::memcpy(native_counts.data(), r.buffers[0].data(), r.buffers[0].size());
        }
      }
    }
    // Prepare every contender, then time them interleaved: repetition r of each contender runs
    // before repetition r + 1 of any, so a burst of load from elsewhere lands on all of them.
    struct Prepared {
      HandwrittenRow row;
      runner::ComputeJob job;
      std::string accuracy_glsl;
      std::vector<uint8_t> last_output;
    };
    std::vector<Prepared> prepared;
    for (const Contender& v : contenders()) {
      Prepared p;
      p.row.op = op;
      p.row.variant = v.name;
      std::string glsl;
      if (v.handwritten) {
        glsl = handwritten_kernel(op, o.steps);
        p.accuracy_glsl = handwritten_kernel(op, kAccuracySteps);
      } else if (!lower_for(v, double_kernel(op, o.steps), &glsl, &p.row.note) ||
                 (!mandel && !lower_for(v, double_kernel(op, kAccuracySteps), &p.accuracy_glsl, &p.row.note))) {
        prepared.push_back(std::move(p));
        continue;
      }
      p.row.spirv_instructions = shader_size(glsl).spirv_instructions;
      p.job.glsl = glsl;
      if (mandel) {
        set_mandelbrot_uniforms(p.job, o, true);
      } else {
        p.job.buffers = {bytes_of(inputs.words), std::vector<uint8_t>(inputs.words.size() * 4)};
        p.job.float_uniforms["ONE"] = 1.0f;
        p.job.groups_x = static_cast<uint32_t>((o.elements + kLocalSize - 1) / kLocalSize);
      }
      p.row.ok = true;  // until a run fails
      prepared.push_back(std::move(p));
    }
    for (int rep = 0; rep < o.repetitions; ++rep)
      for (Prepared& p : prepared) {
        if (!p.row.ok) continue;
        const runner::TimedResult t =
            runner::run_compute_timed(runner::Backend::Gles, p.job, rep == 0 ? o.warmup : 1, 1);
        if (!t.ok) {
          p.row.ok = false;
          p.row.note = t.error;
          continue;
        }
        report->device = t.device + " (" + t.clock + ")";
        p.row.seconds.push_back(t.seconds.at(0));
        p.last_output = t.buffers.at(0);
      }
    double hw_median = 0, hw_min = 0;
    for (Prepared& p : prepared) {
      HandwrittenRow& row = p.row;
      if (row.ok) {
        row.median_seconds = median_of(row.seconds);
        row.min_seconds = *std::min_element(row.seconds.begin(), row.seconds.end());
        if (mandel) {
          if (!native_counts.empty() && p.last_output.size() == native_counts.size() * 4) {
            size_t equal = 0;
            for (size_t k = 0; k < native_counts.size(); ++k) {
              uint32_t n;
              std::memcpy(&n, p.last_output.data() + 4 * k, 4);
              equal += n == native_counts[k];
            }
            row.agree = static_cast<double>(equal) / static_cast<double>(native_counts.size());
          }
        } else {
          std::string e;
          row.bits = kernel_bits(op, p.accuracy_glsl, o.elements, &e);
          if (row.bits < 0) row.note = "accuracy run: " + e;
        }
        if (&p == &prepared.front()) hw_median = row.median_seconds, hw_min = row.min_seconds;
        if (hw_median > 0) {
          row.speedup_median = hw_median / row.median_seconds;
          row.speedup_min = hw_min / row.min_seconds;
        }
      }
      report->rows.push_back(row);
    }
  }
  return true;
}

std::string format_handwritten_markdown(const HandwrittenReport& r) {
  std::ostringstream out;
  char buf[512];
  out << "# doublet vs a hand-written float-float library (Mesa GLES)\n\n";
  out << "command: " << r.command << "\n";
  out << "device: " << r.device << "\n";
  out << "per-op kernels: " << r.options.elements << " invocations x " << rounded_steps(r.options.steps)
      << " dependent steps; bits after " << kUnroll << " steps vs a long double host reference (worst of "
      << r.options.elements << " inputs)\n";
  out << "mandelbrot: " << r.options.mandelbrot_size << "x" << r.options.mandelbrot_size << " pixels, "
      << r.options.mandelbrot_iterations << " iterations max, " << r.options.mandelbrot_zoom
      << " units per pixel; accuracy = pixels with native fp64's iteration count (lavapipe)\n";
  out << "speed-up = handwritten time / this time (> 1: faster than hand-written), same run\n\n";
  out << "| op | variant | median ms | min ms | speed-up (median; min) | accuracy | SPIR-V instr |\n";
  out << "|---|---|---|---|---|---|---|\n";
  for (const HandwrittenRow& row : r.rows) {
    if (!row.ok) {
      std::snprintf(buf, sizeof buf, "| %s | %s | failed: %s | | | | |\n", row.op.c_str(), row.variant.c_str(),
                    row.note.substr(0, 200).c_str());
      out << buf;
      continue;
    }
    std::string acc;
    if (row.agree >= 0) {
      std::snprintf(buf, sizeof buf, "%.2f%% pixels = native", 100 * row.agree);
      acc = buf;
    } else if (row.op == "mandelbrot") {
      acc = "no native reference";
    } else {
      std::snprintf(buf, sizeof buf, "%.2f bits", row.bits);
      acc = buf;
    }
    std::snprintf(buf, sizeof buf, "| %s | %s | %.3f | %.3f | %.2fx; %.2fx | %s | %zu |\n", row.op.c_str(),
                  row.variant.c_str(), 1e3 * row.median_seconds, 1e3 * row.min_seconds, row.speedup_median,
                  row.speedup_min, acc.c_str(), row.spirv_instructions);
    out << buf;
  }
  return out.str();
}

}  // namespace doublet::bench
