#include "plan/planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string_view>
#include <nlohmann/json.hpp>

#include "frontend/frontend.hpp"
#include "frontend/import.hpp"
#include "frontend/text_scan.hpp"
#include "plan/analysis.hpp"

namespace doublet::plan {
namespace {

std::string num(double x, int digits = 3) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

bool is_interface(const ir::Var* v) {
  using S = ir::Storage;
  return v->storage == S::In || v->storage == S::Out || v->storage == S::Uniform || v->storage == S::Buffer ||
         v->storage == S::BuiltIn || v->storage == S::Shared;
}

std::string kind_of(const ir::Var* v) {
  using S = ir::Storage;
  switch (v->storage) {
    case S::In: case S::Uniform: return "input";
    case S::Out: case S::BuiltIn: return "output";
    case S::Buffer: return is_readonly(v) ? "input" : is_writeonly(v) ? "output" : "buffer";
    case S::ParamIn: case S::ParamOut: case S::ParamInOut: return "parameter";
    case S::Local: return "local";
    default: return "global";
  }
}

// The line declaring interface variable `name`: after a storage word (in, out, uniform, buffer,
// attribute, varying) or inside a block that one opens, `name` as a whole word with nothing but
// an optional array size before the `;`. glslang places interface variables at their first use;
// the table wants the declaration. A scanner, not a regex: libstdc++'s matcher recurses per
// character, and a user's 4 MB line would overflow the stack.
int declaration_line(std::string_view source, const std::string& name, int fallback) {
  static const std::set<std::string_view> storage{"in", "out", "uniform", "buffer", "attribute", "varying"};
  bool storage_seen = false, in_block = false;
  int line = 1;
  size_t i = 0;
  while (i < source.size()) {
    const char c = source[i];
    if (c == '\n') ++line;
    if (c == ';' || c == '{' || c == '}') {
      if (c == '{') in_block = storage_seen;
      if (c == '}') in_block = false;
      storage_seen = false;
      ++i;
      continue;
    }
    if (!frontend::is_word_char(c)) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < source.size() && frontend::is_word_char(source[end])) ++end;
    const std::string_view word = source.substr(i, end - i);
    i = end;
    if (storage.count(word)) storage_seen = true;
    if ((!storage_seen && !in_block) || word != name) continue;
    std::string_view rest = frontend::trim_blanks(source.substr(end, 200));
    if (!rest.empty() && rest.front() == '[') {
      const size_t close = rest.find_first_of("]");
      if (close == std::string_view::npos) continue;
      rest = frontend::trim_blanks(rest.substr(close + 1));
    }
    if (!rest.empty() && rest.front() == ';') return line;
  }
  return fallback;
}

// A cheaper candidate may spend at most half of each output's slack (requirement minus the
// all-df64 estimate): one bit of margin for what the linear model leaves out (second-order
// terms, the drivers' deviations).
bool accepts(const Analysis& a, const Scene& s, const Candidate& c, const std::map<std::string, double>& base) {
  for (const auto& [name, req] : s.outputs) {
    const double b = base.at(name);
    if (!(a.error_estimate(name, c) - b <= (req.abs_error - b) / 2)) return false;
  }
  return true;
}

}  // namespace

PlanOutcome make_plan(std::string_view source, const Options& options, const Scene& scene) {
  PlanOutcome out;
  frontend::ParsedShader parsed;
  if (!frontend::parse(source, options, parsed, out.diagnostics)) return out;
  ir::Module module;
  if (!frontend::import_module(parsed, options, module, out.diagnostics)) return out;
  Analysis a;
  if (!a.run(module, scene, &out.diagnostics)) return out;
  out.ok = true;
  out.notes = a.notes();

  // Functions whose bodies do double arithmetic, in source order.
  std::vector<const ir::Function*> functions;
  for (const auto& f : module.functions) functions.push_back(f.get());

  Candidate all_df64, all_fp32, all_exact;
  all_exact.base = Mode::Exact;
  for (const ir::Function* f : functions) all_fp32.function_mode[f] = Mode::Fp32;
  for (const ir::Var* v : a.double_vars()) all_fp32.fp32_vars.insert(v);
  out.feasible = true;
  std::map<std::string, double> base;
  std::vector<std::string> df64_misses;
  for (const auto& [name, req] : scene.outputs) {
    base[name] = a.error_estimate(name, all_df64);
    OutputRow row{name, req.abs_error, 0, a.error_estimate(name, all_df64), a.error_estimate(name, all_fp32),
                  a.error_estimate(name, all_exact)};
    if (!(row.estimate_df64 <= req.abs_error)) {
      out.feasible = false;
      df64_misses.push_back(std::isinf(row.estimate_df64)
                                ? "output '" + name + "': no error bound can be proven with df64 (a value beyond float's "
                                                      "range, an unbounded range, a loop, or a built-in without a known bound)"
                                : "output '" + name + "': even df64 everywhere is estimated at " +
                                      num(row.estimate_df64) + " > the required " + num(req.abs_error));
    }
    out.outputs.push_back(row);
  }
  // Name the values float-float cannot hold (finite, beyond FLT_MAX): the usual reason for exact.
  std::string beyond_float;
  for (const ir::Var* v : a.double_vars()) {
    const double m = Analysis::hull(a.range(v)).mag();
    if (!(m > kFloatMax) || std::isinf(m)) continue;
    const ir::Function* f = a.owner(v);
    beyond_float += (beyond_float.empty() ? "" : ", ") + (f ? f->name + "." : std::string()) + v->name + " reaches " + num(m);
  }
  if (!beyond_float.empty())
    out.notes.push_back("beyond float's range (3.4e38), where float-float overflows: " + beyond_float);
  // Where float-float cannot keep a promise (values beyond float's range, or more than its ~48
  // bits), binary64 in integer arithmetic may: mode exact for the whole shader (it does not mix
  // with other modes), on every target but ES 1.00, which has no 32-bit integers.
  const bool exact_keeps_all = std::all_of(out.outputs.begin(), out.outputs.end(),
                                           [](const OutputRow& r) { return r.estimate_exact <= r.required; });
  const bool exact_target = options.target != Target::Es100;
  // Before the whole shader: df64 with exact functions (docs/modes.md, "Exact functions"), when the
  // outputs' promises hold with main in df64. Start from every function but main exact, give back
  // to df64 each one the promises do not need, and keep the result only if doublet lowers it (an
  // exact function must not read double globals, ...); else the whole shader goes exact.
  std::optional<Candidate> mixed_exact;
  if (!out.feasible && exact_keeps_all && exact_target && options.target != Target::Wgsl) {
    Candidate mixed = all_df64;
    for (const ir::Function* f : functions)
      if (f->name != "main") mixed.function_mode[f] = Mode::Exact;
    auto keeps_all = [&](const Candidate& c) {
      return std::all_of(scene.outputs.begin(), scene.outputs.end(),
                         [&](const auto& o) { return a.error_estimate(o.first, c) <= o.second.abs_error; });
    };
    if (!mixed.function_mode.empty() && keeps_all(mixed)) {
      for (const ir::Function* f : functions) {
        if (f->name == "main") continue;
        Candidate c = mixed;
        c.function_mode.erase(f);
        if (keeps_all(c)) mixed = c;
      }
      Options trial = options;
      trial.target = Target::Glsl450;  // has every stage: what is tried is the exact functions' limits
      trial.mode = Mode::Df64;
      trial.mode_for.clear();
      for (const auto& [f, m] : mixed.function_mode) trial.mode_for.emplace_back(f->name, m);
      if (lower(source, trial).ok) {
        out.feasible = true;
        mixed_exact = mixed;
        for (const auto& [name, req] : scene.outputs) base[name] = a.error_estimate(name, mixed);
        for (const std::string& miss : df64_misses)
          out.notes.push_back(miss + "; binary64 in the functions the plan makes exact keeps it");
      }
    }
  }
  if (!out.feasible && exact_keeps_all && exact_target) {
    out.feasible = true;
    out.mode = Mode::Exact;
    for (const std::string& miss : df64_misses)
      out.notes.push_back(miss + "; binary64 (mode exact) keeps it: the plan is mode exact for the whole shader");
  } else if (!mixed_exact) {
    for (const std::string& miss : df64_misses) {
      std::string why = ": everything stays df64";
      if (exact_keeps_all && !exact_target)
        why = "; mode exact would keep it, but target " + std::string(to_string(options.target)) +
              " has no 32-bit integers for it: everything stays df64";
      out.notes.push_back(miss + why);
    }
  }

  // Cheapest first: whole functions in float (fp32, then rte), then df64-fast where no operand
  // can cancel; then, inside df64 functions, each declaration stored as float.
  Candidate plan = out.mode == Mode::Exact ? all_exact : mixed_exact ? *mixed_exact : all_df64;
  if (out.feasible && out.mode != Mode::Exact) {
    for (const ir::Function* f : functions) {
      if (plan.mode_of(f) == Mode::Exact) continue;
      for (Mode m : {Mode::Fp32, Mode::Rte, Mode::Df64Fast}) {
        if (m == Mode::Df64Fast && a.may_cancel(f)) continue;
        Candidate c = plan;
        c.function_mode[f] = m;
        if (accepts(a, scene, c, base)) {
          plan = c;
          break;
        }
      }
    }
    std::vector<const ir::Var*> vars = a.double_vars();
    std::stable_sort(vars.begin(), vars.end(), [](const ir::Var* x, const ir::Var* y) { return x->loc.line < y->loc.line; });
    for (const ir::Var* v : vars) {
      if (is_interface(v) || v->declared_type.is_array() || v->declared_type.base != ir::Base::Double) continue;
      const ir::Function* f = a.owner(v);
      if (f && (plan.mode_of(f) == Mode::Fp32 || plan.mode_of(f) == Mode::Rte || plan.mode_of(f) == Mode::Exact)) continue;
      Candidate c = plan;
      // Every declaration of the same qualified name moves together (mode_for names them so).
      for (const ir::Var* w : vars)
        if (w->name == v->name && a.owner(w) == f) c.fp32_vars.insert(w);
      if (accepts(a, scene, c, base)) plan = c;
    }
  }
  for (OutputRow& row : out.outputs) row.estimate = a.error_estimate(row.name, plan);
  out.flops_df64 = a.flops(all_df64);
  out.flops_plan = a.flops(plan);

  // Table rows and mode_for: functions, then declared doubles in source order.
  for (const ir::Function* f : functions) {
    PlanRow r;
    r.name = f->name + "()";
    r.kind = "function";
    r.line = f->loc.line;
    r.mode = plan.mode_of(f);
    r.flops = a.flops(plan, f);
    r.note = "arithmetic of the body";
    out.rows.push_back(r);
    if (r.mode != out.mode) out.mode_for.emplace_back(f->name, r.mode);
  }
  std::vector<const ir::Var*> vars = a.double_vars();
  std::stable_sort(vars.begin(), vars.end(), [](const ir::Var* x, const ir::Var* y) { return x->loc.line < y->loc.line; });
  for (const ir::Var* v : vars) {
    const ir::Function* f = a.owner(v);
    PlanRow r;
    r.name = f ? f->name + "." + v->name : v->name;
    if (std::any_of(out.rows.begin(), out.rows.end(), [&](const PlanRow& x) { return x.name == r.name; })) continue;
    r.kind = kind_of(v);
    r.line = is_interface(v) ? declaration_line(source, v->name, v->loc.line) : v->loc.line;
    r.range = Analysis::hull(a.range(v));
    for (const auto& [name, req] : scene.outputs) r.budget = std::min(r.budget, a.budget(name, v));
    const double m = r.range.mag();
    r.bits = std::isinf(r.budget) || m == 0 ? 0 : r.budget == 0 ? kInf : std::max(0.0, std::log2(m / r.budget) + 1);
    const bool fp32 = plan.fp32_vars.count(v) || (f && (plan.mode_of(f) == Mode::Fp32 || plan.mode_of(f) == Mode::Rte));
    r.mode = fp32 ? Mode::Fp32 : f ? plan.mode_of(f) : plan.base;
    r.flops = a.flops_of(v, plan);
    if (is_interface(v)) r.note = "interface: keeps its declared type";
    if (std::isinf(r.budget)) r.note = r.note.empty() ? "no scene output depends on it" : r.note;
    if (plan.fp32_vars.count(v)) {
      r.note = "stored as float: demoted once where assigned";
      out.mode_for.emplace_back(r.name, Mode::Fp32);
    }
    out.rows.push_back(r);
  }
  std::stable_sort(out.rows.begin() + static_cast<long>(functions.size()), out.rows.end(),
                   [](const PlanRow& x, const PlanRow& y) { return x.line < y.line; });
  return out;
}

std::string format_table(const PlanOutcome& p) {
  std::string s;
  char line[512];
  // The value column fits the longest name (22 at least), so long FUNCTION.LOCAL names stay aligned.
  int width = 22;
  for (const PlanRow& r : p.rows) width = std::max(width, static_cast<int>(std::min<size_t>(r.name.size(), 100)));
  std::snprintf(line, sizeof line, "%-*s %-9s %5s  %-23s %9s %6s  %-9s %7s  %s\n", width, "value", "kind", "line",
                "range", "budget", "bits", "mode", "flops", "note");
  s += line;
  for (const PlanRow& r : p.rows) {
    const bool fn = r.kind == "function";
    const std::string range = fn ? "" : "[" + num(r.range.lo) + ", " + num(r.range.hi) + "]";
    std::snprintf(line, sizeof line, "%-*s %-9s %5d  %-23s %9s %6s  %-9s %7s  %s\n", width, r.name.c_str(), r.kind.c_str(),
                  r.line, range.c_str(), fn || std::isinf(r.budget) ? "-" : num(r.budget).c_str(),
                  fn || r.bits == 0 ? "-" : num(r.bits, 3).c_str(), std::string(to_string(r.mode)).c_str(),
                  num(r.flops, 4).c_str(), r.note.c_str());
    s += line;
  }
  s += "\noutput                 required  estimate(plan)  estimate(all df64)  estimate(all fp32)  estimate(exact)\n";
  for (const OutputRow& o : p.outputs) {
    std::snprintf(line, sizeof line, "%-22s %9s  %14s  %18s  %18s  %15s\n", o.name.c_str(), num(o.required).c_str(),
                  num(o.estimate).c_str(), num(o.estimate_df64).c_str(), num(o.estimate_fp32).c_str(),
                  num(o.estimate_exact).c_str());
    s += line;
  }
  s += "\ndouble flops per invocation: " + num(p.flops_plan, 5) + " with the plan, " + num(p.flops_df64, 5) +
       " all df64 (docs/rules.md" + (p.mode == Mode::Exact ? "; mode exact counts fp32-time equivalents measured on lavapipe" : "") +
       ")\n";
  for (const std::string& n : p.notes) s += "note: " + n + "\n";
  return s;
}

std::string plan_to_json(const PlanOutcome& p) {
  nlohmann::ordered_json j;
  j["version"] = 1;
  j["mode"] = std::string(to_string(p.mode));
  j["mode_for"] = nlohmann::ordered_json::object();
  for (const auto& [name, m] : p.mode_for) j["mode_for"][name] = std::string(to_string(m));
  return j.dump(2) + "\n";
}

bool load_plan(std::string_view text, const std::string& file, Options* options, Diagnostic* error) {
  Scene located;  // only for placing diagnostics
  located.file = file;
  located.text = std::string(text);
  nlohmann::ordered_json j;
  try {
    j = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    *error = json_syntax_diagnostic(text, file, "plan", e, e.byte);
    return false;
  }
  auto fail = [&](const std::string& pointer, const std::string& message) {
    *error = scene_diagnostic(located, pointer, message);
    return false;
  };
  if (!j.is_object()) return fail("", "a plan is {\"version\": 1, \"mode\": MODE, \"mode_for\": {NAME: MODE}}");
  for (const auto& [key, v] : j.items())
    if (key != "version" && key != "mode" && key != "mode_for")
      return fail("/" + key, "unknown field '" + key + "' (expected version, mode, mode_for)");
  if (!j.contains("version") || j["version"] != 1) return fail("/version", "version must be 1");
  if (j.contains("mode")) {
    const auto m = j["mode"].is_string() ? parse_mode(j["mode"].get<std::string>()) : std::nullopt;
    if (!m) return fail("/mode", "mode must be one of fp32, rte, df64-fast, df64, df64-int, native, exact, rte-exact");
    options->mode = *m;
  }
  if (j.contains("mode_for")) {
    if (!j["mode_for"].is_object()) return fail("/mode_for", "mode_for must be an object of NAME: MODE");
    for (const auto& [name, v] : j["mode_for"].items()) {
      const auto m = v.is_string() ? parse_mode(v.get<std::string>()) : std::nullopt;
      if (!m) return fail("/mode_for/" + name, "'" + name + "': mode must be one of fp32, rte, df64-fast, df64, df64-int, native, exact, rte-exact");
      options->mode_for.emplace_back(name, *m);
    }
  }
  return true;
}

}  // namespace doublet::plan
