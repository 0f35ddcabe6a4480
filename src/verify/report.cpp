#include "verify/report.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace doublet::verify {
namespace {

std::string backend_id(runner::Backend b) {
  switch (b) {
    case runner::Backend::Vulkan: return "vulkan";
    case runner::Backend::Gles: return "gles";
    case runner::Backend::WebGl2: return "webgl2";
    case runner::Backend::WebGpu: return "webgpu";
  }
  return "?";
}

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

// JSON has no Inf/NaN: those become null.
nlohmann::json num(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace

std::string format_table(const VerifyReport& r) {
  std::string s = "doublet verify " + r.shader + " (stage " + r.stage + ", target " + r.target + ", sabotage " +
                  r.sabotage + ", " + std::to_string(r.samples) + " samples, seed " + std::to_string(r.seed) + ")\n";
  if (!r.input_error.empty()) return s + "error: " + r.input_error + "\n";
  for (const std::string& in : r.inputs) s += "  input  " + in + "\n";
  for (const std::string& n : r.notes) s += "  note   " + n + "\n";
  for (const BackendRun& run : r.runs) {
    s += "\n[" + backend_id(run.backend) + "] lowered on " + (run.driver.empty() ? "?" : run.driver) +
         ", native fp64 on " + run.reference_driver + "\n";
    s += "  probe: " + describe(run.probe) + "\n";
    if (!run.error.empty()) {
      s += "  error: " + run.error + "\n";
      continue;
    }
    char line[512];
    std::snprintf(line, sizeof line, "  %-22s %-11s %8s %10s %10s %10s %10s %8s %8s %6s\n", "output", "type", "samples",
                  "max_rel", "p99_rel", "median_rel", "max_abs", "min_bits", "p1_bits", "class");
    s += line;
    for (const OutputStats& o : run.outputs) {
      std::snprintf(line, sizeof line, "  %-22s %-11s %8llu %10.3g %10.3g %10.3g %10.3g %8.2f %8.2f %6llu%s\n",
                    o.name.c_str(), o.type.c_str(), static_cast<unsigned long long>(o.samples), o.max_rel_err,
                    o.p99_rel_err, o.median_rel_err, o.max_abs_err, o.min_bits, o.p1_bits,
                    static_cast<unsigned long long>(o.class_mismatches),
                    o.passed()             ? ""
                    : !o.identical_passed() ? "  FAIL (bits differ)"
                    : !o.abs_passed()       ? ("  FAIL (max_abs > " + fmt("%.3g", o.max_abs_err_allowed) + ")").c_str()
                    : !o.beyond_float_passed()
                        ? ("  FAIL (median " + fmt("%.1f", o.median_bits()) + " bits: float alone keeps " +
                           fmt("%.1f", o.float_median_bits) + ")").c_str()
                                            : ("  FAIL (< " + fmt("%.1f", o.min_bits_required) + ")").c_str());
      s += line;
      if (o.require_identical)
        s += "      identical bits required: " + std::to_string(o.differing) + " of " + std::to_string(o.samples) +
             " differ" + (o.nan_payloads ? " (" + std::to_string(o.nan_payloads) + " NaN with another NaN's payload apart)" : "") +
             "\n";
      if (o.min_bits < kMaxBits)
        s += "      worst: " + o.worst_input + " -> got " + hex(o.worst_got) + ", want " + hex(o.worst_want) + "\n";
    }
    if (run.probe.denormals_flushed)
      s += "  caveat: this stage flushes denormals; results below ~1e-38 (lo below ~1e-31) lose precision\n";
  }
  s += r.passed() ? "\nresult: PASS\n" : "\nresult: FAIL\n";
  return s;
}

std::string to_json(const VerifyReport& r) {
  nlohmann::json j;
  j["schema"] = kJsonSchema;
  j["shader"] = r.shader;
  j["stage"] = r.stage;
  j["target"] = r.target;
  j["mode"] = r.mode;
  j["sabotage"] = r.sabotage;
  j["samples"] = r.samples;
  j["seed"] = r.seed;
  j["dispatches"] = r.dispatches;
  j["passed"] = r.passed();
  j["error"] = r.input_error.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.input_error);
  j["inputs"] = r.inputs;
  j["notes"] = r.notes;
  j["inputs_beyond_float_range"] = r.inputs_beyond_float_range;
  j["runs"] = nlohmann::json::array();
  for (const BackendRun& run : r.runs) {
    nlohmann::json jr;
    jr["backend"] = backend_id(run.backend);
    jr["driver"] = run.driver;
    jr["reference_driver"] = run.reference_driver;
    jr["stage"] = r.stage;
    jr["target"] = r.target;
    jr["mode"] = r.mode;
    jr["probe"] = {{"stage", run.probe.stage},
                   {"unprotected_two_sum_survives", run.probe.two_sum_survives},
                   {"fma_fused", run.probe.fma_fused},
                   {"denormals_flushed", run.probe.denormals_flushed},
                   {"error", run.probe.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.probe.error)}};
    jr["error"] = run.error.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.error);
    jr["outputs"] = nlohmann::json::array();
    for (const OutputStats& o : run.outputs) {
      jr["outputs"].push_back({{"name", o.name},
                               {"type", o.type},
                               {"samples", o.samples},
                               {"max_rel_err", num(o.max_rel_err)},
                               {"p99_rel_err", num(o.p99_rel_err)},
                               {"median_rel_err", num(o.median_rel_err)},
                               {"max_abs_err", num(o.max_abs_err)},
                               {"min_bits", o.min_bits},
                               {"p1_bits", o.p1_bits},
                               {"worst_input", o.worst_input},
                               {"worst_got", hex(o.worst_got)},
                               {"worst_want", hex(o.worst_want)},
                               {"class_mismatches", o.class_mismatches},
                               {"differing", o.differing},
                               {"nan_payloads", o.nan_payloads},
                               {"identical_required", o.require_identical},
                               {"abs_floor", o.abs_floor},
                               {"min_bits_required", o.min_bits_required < 0 ? nlohmann::json(nullptr)
                                                                              : nlohmann::json(o.min_bits_required)},
                               {"passed", o.passed()}});
    }
    j["runs"].push_back(std::move(jr));
  }
  return j.dump(2) + "\n";
}

}  // namespace doublet::verify
