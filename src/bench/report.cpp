// Markdown and JSON renderings of a BenchReport.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "bench/bench.hpp"
#include "bench/kernels.hpp"

namespace doublet::bench {
namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// Bits measured against native fp64 in the same run (Measurement::bits).
std::string measured_bits(const Measurement& r) {
  if (r.bits < 0) return "—";
  if (r.mode == Mode::Native && r.backend == runner::Backend::Vulkan) return "53 (reference)";
  return fixed(r.bits, 2);
}

std::string flops(const Kernel* k, Mode m) {
  if (!k || m == Mode::Rte || m == Mode::Df64Fast || m == Mode::Df64Int || m == Mode::Exact) return "—";  // no single documented count
  return std::to_string(m == Mode::Df64 ? k->rule_flops : k->fp32_flops);
}

// Emitted float operations per step, and their excess over the documented count.
std::string emitted(const Kernel* k, const Measurement& r) {
  if (!k || r.emitted_flops_per_step < 0) return "—";
  const double doc = r.mode == Mode::Df64 ? k->rule_flops : k->fp32_flops;
  char buf[64];
  if (r.mode == Mode::Rte || r.mode == Mode::Df64Fast || r.mode == Mode::Df64Int || r.mode == Mode::Exact) {
    std::snprintf(buf, sizeof buf, "%.4g", r.emitted_flops_per_step);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "%.4g (%+.0f%%)", r.emitted_flops_per_step, 100.0 * (r.emitted_flops_per_step / doc - 1.0));
  return buf;
}

std::string ratio(const std::optional<double>& r) { return r ? fixed(*r, 2) + "×" : "—"; }

}  // namespace

std::string format_markdown(const BenchReport& report) {
  const bool shader = !report.options.shader_path.empty();
  std::string s;
  for (runner::Backend b : report.options.backends) {
    const std::string key = backend_key(b);
    const auto dev = report.devices.find(key);
    const auto clock = report.clocks.find(key);
    s += "### " + key + (dev != report.devices.end() ? " — " + dev->second : "") + "\n\nclock: " +
         (clock != report.clocks.end() ? clock->second : "none (nothing ran)") + "\n\n";
    s += shader ? "| shader | mode | median ms | min ms | invocations/s | time / fp32 | time / native fp64 | SPIR-V instr | GLSL lines |\n"
                  "|---|---|---|---|---|---|---|---|---|\n"
                : "| op | mode | flops/step (docs) | emitted flops/step (SPIR-V) | bits (measured) | median ms | min ms | ops/s | time / fp32 | time / native fp64 | SPIR-V instr | GLSL lines |\n"
                  "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const Measurement& r : report.rows) {
      if (r.backend != b) continue;
      const Kernel* k = shader ? nullptr : find_kernel(r.op);
      s += "| " + r.op + " | " + mode_name(r.mode) + " | ";
      if (!shader) s += flops(k, r.mode) + " | " + emitted(k, r) + " | " + measured_bits(r) + " | ";
      if (!r.ok) {
        s += "not run | | | | | | |\n";
        continue;
      }
      char ops[32];
      std::snprintf(ops, sizeof ops, "%.3g", r.ops_per_second);
      s += fixed(r.median_seconds * 1e3, 3) + " | " + fixed(r.min_seconds * 1e3, 3) + " | " + ops + " | " + ratio(r.time_vs_fp32) + " | " +
           ratio(r.time_vs_native) + " | " + std::to_string(r.size.spirv_instructions) + " | " +
           std::to_string(r.size.glsl_lines) + " |" + (r.finite_output ? "" : " (non-finite output!)") + "\n";
    }
    s += "\n";
  }
  if (!report.notes.empty()) {
    s += "Not run:\n";
    for (const std::string& n : report.notes) s += "- " + n.substr(0, n.find('\n')) + "\n";
  }
  return s;
}

std::string format_json(const BenchReport& report) {
  const BenchOptions& o = report.options;
  nlohmann::json j;
  j["command"] = report.command;
  j["shader"] = o.shader_path.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.shader_path);
  j["target"] = std::string(to_string(o.target));
  j["elements"] = o.elements;
  j["warmup"] = o.warmup;
  j["repetitions"] = o.repetitions;
  j["devices"] = report.devices;
  j["clocks"] = report.clocks;
  j["native_reference_backend"] = "vulkan";
  j["results"] = nlohmann::json::array();
  for (const Measurement& r : report.rows) {
    nlohmann::json row;
    row["op"] = r.op;
    row["backend"] = backend_key(r.backend);
    row["mode"] = mode_name(r.mode);
    row["ok"] = r.ok;
    row["not_applicable"] = r.not_applicable;
    row["steps"] = r.steps;
    row["note"] = r.note;
    row["seconds"] = r.seconds;
    row["median_seconds"] = r.median_seconds;
    row["min_seconds"] = r.min_seconds;
    row["ops_per_second"] = r.ops_per_second;
    row["time_vs_fp32"] = r.time_vs_fp32 ? nlohmann::json(*r.time_vs_fp32) : nlohmann::json(nullptr);
    row["time_vs_native"] = r.time_vs_native ? nlohmann::json(*r.time_vs_native) : nlohmann::json(nullptr);
    row["finite_output"] = r.finite_output;
    row["spirv_instructions"] = r.size.spirv_instructions;
    row["glsl_lines"] = r.size.glsl_lines;
    if (const Kernel* k = o.shader_path.empty() ? find_kernel(r.op) : nullptr) {
      row["flops_per_step"] = r.mode == Mode::Rte || r.mode == Mode::Df64Fast || r.mode == Mode::Df64Int || r.mode == Mode::Exact
                                  ? nlohmann::json(nullptr)
                                  : nlohmann::json(r.mode == Mode::Df64 ? k->rule_flops : k->fp32_flops);
      row["emitted_flops_per_step"] =
          r.emitted_flops_per_step >= 0 ? nlohmann::json(r.emitted_flops_per_step) : nlohmann::json(nullptr);
      row["bits"] = r.bits >= 0 ? nlohmann::json(r.bits) : nlohmann::json(nullptr);
    }
    j["results"].push_back(std::move(row));
  }
  j["notes"] = report.notes;
  return j.dump(2) + "\n";
}

}  // namespace doublet::bench
