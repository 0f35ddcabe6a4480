#include "bench/compile_time.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "runner/timed_compute.hpp"

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
         "uniform float steps;  // a bound no compiler can unroll\n"
         "void main() {\n"
         "  uint i = gl_GlobalInvocationID.x;\n"
         "  double a = ab[i].x, b = ab[i].y, s = a;\n"
         "  for (int k = 0; k < int(steps); ++k) {\n" + body +
         "  }\n"
         "  o[i] = vec2(float(s), float(s - double(float(s))));\n"
         "}\n";
}

std::vector<CompileTimeRow> run_compile_time_bench(const CompileTimeOptions& o, std::string* devices) {
  struct Variant {
    CompileTimeRow row;
    runner::ComputeJob job;
  };
  std::vector<Variant> variants;
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
            variants.push_back(v);
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
            variants.push_back(v);
            continue;
          }
          v.job.glsl = lowered.output;
        }
        // Zero-filled buffers large enough for every representation of a dvec2 (exact: 4 words).
        v.job.buffers = {std::vector<uint8_t>(kInvocations * 32), std::vector<uint8_t>(kInvocations * 8)};
        v.job.float_uniforms["steps"] = 2.0f;
        variants.push_back(v);
      }
  // Mesa keeps compiled shaders in a disk cache: a shader compiled by an earlier round (or an earlier
  // run) would be timed as a cache hit. Set before the runner creates its devices.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  setenv("MESA_GLSL_CACHE_DISABLE", "true", 1);
  // The first compile of a process also pays for the device and compiler start-up: one untimed
  // compile per backend first.
  for (runner::Backend backend : o.backends)
    for (const Variant& v : variants)
      if (v.row.backend == backend && !v.job.glsl.empty()) {
        runner::run_compute_timed(backend, v.job, 0, 1);
        break;
      }
  // Interleaved rounds: every variant once per round, the fastest round kept.
  std::map<runner::Backend, std::string> names;
  for (int round = 0; round < o.rounds; ++round)
    for (Variant& v : variants) {
      if (v.job.glsl.empty()) continue;  // not applicable, or it does not lower (row.error says why)
      const runner::TimedResult r = runner::run_compute_timed(v.row.backend, v.job, 0, 1);
      if (!r.ok) {
        v.row.ok = false;
        v.row.error = r.error.substr(0, r.error.find('\n'));
        continue;
      }
      names[v.row.backend] = r.device;
      const double compile = std::max(0.0, r.first_result_seconds - r.seconds.at(0));
      if (!v.row.ok || compile < v.row.compile_seconds) v.row.compile_seconds = compile;
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
      << "Milliseconds from the shader text to its first result, less one dispatch (the fastest of " << o.rounds
      << " interleaved rounds); in parentheses the ratio to fp32 (the float twin) and to native fp64, same run.\n";
  for (runner::Backend backend : o.backends) {
    out << "\n### " << runner::backend_name(backend) << "\n\n| double ops per iteration |";
    for (const std::string& m : o.modes) out << " " << m << " |";
    out << "\n|---|";
    for (size_t i = 0; i < o.modes.size(); ++i) out << "---|";
    out << "\n";
    for (int ops : o.ops) {
      auto find = [&](const std::string& mode) -> const CompileTimeRow* {
        for (const CompileTimeRow& r : rows)
          if (r.ops == ops && r.backend == backend && r.mode == mode) return &r;
        return nullptr;
      };
      const CompileTimeRow* fp32 = find("fp32");
      const CompileTimeRow* native = find("native");
      out << "| " << ops << " |";
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
    }
  }
  for (const CompileTimeRow& r : rows)
    if (!r.ok && !r.not_applicable)
      out << "\n- " << runner::backend_name(r.backend) << " " << r.mode << ", " << r.ops << " ops: " << r.error;
  out << "\n";
  return out.str();
}

}  // namespace doublet::bench
