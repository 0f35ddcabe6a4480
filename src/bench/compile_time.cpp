#include "bench/compile_time.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "bench/kernels.hpp"
#include "runner/timed_compute.hpp"
#include "verify/spec.hpp"
#include "verify/verify.hpp"

namespace doublet::bench {
namespace {

constexpr int kInvocations = 64;  // one workgroup: the dispatch is short next to the compile

std::optional<doublet::Mode> compiler_mode(const std::string& m) {
  if (m == "native") return std::nullopt;
  return doublet::parse_mode(m);
}

}  // namespace

std::string compile_time_kernel(int ops) {
  std::string body;
  for (int k = 0; k < ops; ++k) body += k % 2 == 0 ? "    s = s * b;\n" : "    s = s + a;\n";
  return "#version 450\n"
         "// doublet bench --compile-time: " + std::to_string(ops) + " double operation(s) per iteration\n"
         "layout(local_size_x = 64) in;\n"
         "layout(std430, binding = 0) buffer In { dvec2 ab[]; };\n"
         "layout(std430, binding = 1) buffer Out { vec2 o[]; };\n"
         "// The bound from memory, not a uniform: lavapipe inlines uniforms that bound loops (and unrolls)\n"
         "layout(std430, binding = 2) readonly buffer Bound { float steps; };\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  double a = ab[i].x, b = ab[i].y, s = a;\n"
         "  for (int k = 0; k < int(steps); ++k) {\n" + body +
         "  }\n"
         "  o[i] = vec2(float(s), float(s - double(float(s))));\n"
         "}\n";
}

namespace {

// One shader in one mode on one backend, with what it takes to compile and run it once.
struct Variant {
  CompileTimeRow row;
  bool graphics = false;
  runner::ComputeJob job;
  runner::GraphicsJob graphics_job;
  bool runnable() const { return graphics ? !graphics_job.glsl.empty() : !job.glsl.empty(); }
};

void add_series(const CompileTimeOptions& o, std::vector<Variant>* variants) {
  for (int ops : o.ops)
    for (runner::Backend backend : o.backends)
      for (const std::string& mode : o.modes) {
        Variant v;
        v.row.ops = ops;
        v.row.mode = mode;
        v.row.backend = backend;
        const std::string source = compile_time_kernel(ops);
        if (mode == "native") {
          if (backend != runner::Backend::Vulkan) {
            v.row.not_applicable = true;  // Mesa's GLES has no fp64
            variants->push_back(v);
            continue;
          }
          v.job.glsl = source;
        } else {
          Options options;
          options.stage = Stage::Compute;
          options.target = o.target;
          options.file_name = "compile_time_" + std::to_string(ops) + ".comp";
          if (const std::optional<doublet::Mode> m = compiler_mode(mode)) options.mode = *m;
          const Result lowered = lower(source, options);
          if (!lowered.ok) {
            v.row.error = lowered.diagnostics.empty() ? "does not lower" : format_diagnostic(lowered.diagnostics[0]);
            variants->push_back(v);
            continue;
          }
          v.job.glsl = lowered.output;
        }
        // Zero-filled buffers large enough for every representation of a dvec2 (exact: 4 words).
        v.job.buffers = {std::vector<uint8_t>(kInvocations * 32), std::vector<uint8_t>(kInvocations * 8),
                         bytes_of(std::vector<float>{2.0f})};  // the loop's bound: two trips
        variants->push_back(v);
      }
}

// A report's first two lines (a compile log's heading and its first message).
std::string first_two_lines(const std::string& text) {
  const size_t first = text.find('\n');
  return first == std::string::npos ? text : text.substr(0, text.find('\n', first + 1));
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every shader of the corpus directories, fed as `doublet verify` feeds it (verify::first_jobs: its
// spec, one sample), so each compiles and runs as in the corpus tests. Native fp64 runs on lavapipe
// only; geometry and tessellation shaders on lavapipe only (the runner's GLES path has neither).
void add_corpus(const CompileTimeOptions& o, std::vector<Variant>* variants) {
  namespace fs = std::filesystem;
  for (const std::string& dir : o.corpus_dirs) {
    std::vector<fs::path> shaders;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && stage_from_path(e.path().string()) && e.path().extension() != ".json")
        shaders.push_back(e.path());
    std::sort(shaders.begin(), shaders.end());
    for (const fs::path& path : shaders) {
      const std::string source = read_text(path);
      verify::VerifyOptions options;
      options.lower.stage = stage_from_path(path.string());
      options.lower.target = o.target;
      options.lower.file_name = path.string();
      if (fs::is_directory(fs::path(dir) / "include")) options.lower.include_dirs = {(fs::path(dir) / "include").string()};
      const fs::path spec_path = path.string() + ".json";
      std::string spec_error;
      if (fs::exists(spec_path)) spec_error = verify::parse_spec(read_text(spec_path), &options.spec);
      const bool graphics = *options.lower.stage != Stage::Compute;
      const bool vulkan_only = *options.lower.stage != Stage::Compute && *options.lower.stage != Stage::Vertex &&
                               *options.lower.stage != Stage::Fragment;
      // Each mode lowered once; the native job comes from the first mode whose jobs were planned.
      std::map<std::string, verify::FirstJobs> jobs;
      const verify::FirstJobs* native = nullptr;
      if (spec_error.empty())
        for (const std::string& mode : o.modes) {
          if (mode == "native") continue;
          if (const std::optional<doublet::Mode> m = compiler_mode(mode)) options.lower.mode = *m;
          jobs[mode] = verify::first_jobs(source, options);
        }
      for (const std::string& mode : o.modes)
        if (!native && jobs.count(mode) && jobs.at(mode).error.empty()) native = &jobs.at(mode);
      for (runner::Backend backend : o.backends)
        for (const std::string& mode : o.modes) {
          Variant v;
          v.row.shader = path.filename().string();
          v.row.mode = mode;
          v.row.backend = backend;
          v.graphics = graphics;
          if ((mode == "native" || vulkan_only) && backend != runner::Backend::Vulkan) {
            v.row.not_applicable = true;
          } else if (!spec_error.empty()) {
            v.row.error = spec_path.string() + ": " + spec_error;
          } else if (mode == "native" ? !native : !jobs.at(mode).error.empty()) {
            // Not a compile failure: verify cannot plan its inputs and outputs (listed, not timed).
            const std::string why = mode != "native" ? jobs.at(mode).error
                                    : jobs.empty() ? "--modes names no lowering mode (native's interface is planned with one)"
                                                   : jobs.begin()->second.error;
            v.row.not_applicable = true;
            v.row.error = "not timed, verify cannot feed it: " + first_two_lines(why);
          } else {
            const verify::FirstJobs& j = mode == "native" ? *native : jobs.at(mode);
            if (graphics) v.graphics_job = mode == "native" ? j.native_graphics : j.lowered_graphics;
            else v.job = mode == "native" ? j.native_compute : j.lowered_compute;
          }
          variants->push_back(v);
        }
    }
  }
}

// Seconds from the text to the first result, the first dispatch or draw included: lavapipe compiles
// a compute shader's machine code (LLVM) when it is first dispatched, not when its pipeline is
// created, so the first dispatch holds most of the compile (docs/performance.md, "The first dispatch
// holds the compile"). One dispatch of 64 invocations, or a draw of one point or patch, runs in far
// less than a millisecond.
std::optional<double> time_once(const Variant& v, std::string* error, std::string* device) {
  if (v.graphics) {
    const auto start = std::chrono::steady_clock::now();
    const runner::GraphicsResult r = runner::run_graphics(v.row.backend, v.graphics_job);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    if (!r.ok) return (*error = r.error), std::nullopt;
    *device = r.device;
    return took.count();
  }
  const runner::TimedResult r = runner::run_compute_timed(v.row.backend, v.job, 0, 1);
  if (!r.ok) return (*error = r.error), std::nullopt;
  *device = r.device;
  return r.first_result_seconds;
}

}  // namespace

std::vector<CompileTimeRow> run_compile_time_bench(const CompileTimeOptions& o, std::string* devices) {
  std::vector<Variant> variants;
  add_series(o, &variants);
  add_corpus(o, &variants);
  // Mesa keeps compiled shaders in a disk cache: a shader compiled by an earlier round (or an earlier
  // run) would be timed as a cache hit. Set before the runner creates its devices.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
  // The first compile of a process also pays for the device and compiler start-up: one untimed
  // compile per backend first.
  for (runner::Backend backend : o.backends)
    for (const Variant& v : variants)
      if (v.row.backend == backend && v.runnable()) {
        std::string ignored_error, ignored_device;
        time_once(v, &ignored_error, &ignored_device);
        break;
      }
  // Interleaved rounds: every variant once per round, the fastest round kept.
  std::map<runner::Backend, std::string> names;
  for (int round = 0; round < o.rounds; ++round)
    for (Variant& v : variants) {
      if (!v.runnable()) continue;  // not applicable, or it does not lower (row.error says why)
      std::string error, device;
      const std::optional<double> compile = time_once(v, &error, &device);
      if (!compile) {
        v.row.ok = false;
        v.row.error = first_two_lines(error);  // a driver's log starts on the second line
        continue;
      }
      names[v.row.backend] = device;
      if (!v.row.ok || *compile < v.row.compile_seconds) v.row.compile_seconds = *compile;
      v.row.ok = v.row.error.empty();
    }
  if (devices)
    for (const auto& [backend, name] : names) *devices += std::string(runner::backend_name(backend)) + ": " + name + "; ";
  std::vector<CompileTimeRow> rows;
  for (const Variant& v : variants) rows.push_back(v.row);
  return rows;
}

std::string format_compile_time_markdown(const CompileTimeOptions& o, const std::vector<CompileTimeRow>& rows,
                                         const std::string& command, const std::string& devices) {
  std::ostringstream out;
  out << "# doublet bench --compile-time\n\n`" << command << "`\n\n" << devices << "\n\n"
      << "Milliseconds from the shader text to its first result, its first dispatch (compute: 64 invocations) or draw "
         "(one sample) included, where lavapipe compiles its machine code (the fastest of " << o.rounds
      << " interleaved rounds); in parentheses the ratio to fp32 (the float twin) and to native fp64, same run.\n";
  // One table row: a series' operation count or a corpus shader, a cell per mode.
  auto print_row = [&](runner::Backend backend, const std::string& label, int ops, const std::string& shader) {
    auto find = [&](const std::string& mode) -> const CompileTimeRow* {
      for (const CompileTimeRow& r : rows)
        if (r.ops == ops && r.shader == shader && r.backend == backend && r.mode == mode) return &r;
      return nullptr;
    };
    const CompileTimeRow* fp32 = find("fp32");
    const CompileTimeRow* native = find("native");
    out << "| " << label << " |";
    for (const std::string& m : o.modes) {
      const CompileTimeRow* r = find(m);
      char cell[96];
      if (!r || r->not_applicable) {
        std::snprintf(cell, sizeof cell, " n/a |");
      } else if (!r->ok) {
        std::snprintf(cell, sizeof cell, " failed |");
      } else {
        std::string ratios;
        char part[32];
        if (fp32 && fp32->ok && m != "fp32" && fp32->compile_seconds > 0) {
          std::snprintf(part, sizeof part, "%.1f× fp32", r->compile_seconds / fp32->compile_seconds);
          ratios += part;
        }
        if (native && native->ok && !native->not_applicable && m != "native" && native->compile_seconds > 0) {
          std::snprintf(part, sizeof part, "%s%.1f× native", ratios.empty() ? "" : ", ",
                        r->compile_seconds / native->compile_seconds);
          ratios += part;
        }
        std::snprintf(cell, sizeof cell, " %.0f%s |", r->compile_seconds * 1e3,
                      ratios.empty() ? "" : (" (" + ratios + ")").c_str());
      }
      out << cell;
    }
    out << "\n";
  };
  auto print_header = [&](const std::string& first_column) {
    out << "| " << first_column << " |";
    for (const std::string& m : o.modes) out << " " << m << " |";
    out << "\n|---|";
    for (size_t i = 0; i < o.modes.size(); ++i) out << "---|";
    out << "\n";
  };
  std::vector<std::string> shaders;
  for (const CompileTimeRow& r : rows)
    if (!r.shader.empty() && std::find(shaders.begin(), shaders.end(), r.shader) == shaders.end())
      shaders.push_back(r.shader);
  for (runner::Backend backend : o.backends) {
    out << "\n### " << runner::backend_name(backend) << "\n";
    if (!o.ops.empty()) {
      out << "\n";
      print_header("double ops per iteration");
      for (int ops : o.ops) print_row(backend, std::to_string(ops), ops, "");
    }
    if (!shaders.empty()) {
      out << "\n";
      print_header("corpus shader");
      for (const std::string& shader : shaders) print_row(backend, shader, 0, shader);
    }
  }
  for (const CompileTimeRow& r : rows)
    if (!r.ok && !r.error.empty())
      out << "\n- " << runner::backend_name(r.backend) << " " << r.mode << ", "
          << (r.shader.empty() ? std::to_string(r.ops) + " ops" : r.shader) << ": " << r.error;
  out << "\n";
  return out.str();
}

}  // namespace doublet::bench
