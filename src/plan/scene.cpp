#include "plan/scene.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace doublet::plan {
namespace {

using nlohmann::json;

// Skips whitespace, then one JSON value starting at `i` (the text is valid JSON).
size_t skip_ws(std::string_view t, size_t i) {
  while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
  return i;
}
size_t skip_string(std::string_view t, size_t i) {  // i at the opening quote
  for (++i; i < t.size() && t[i] != '"'; ++i)
    if (t[i] == '\\') ++i;
  return i + 1;
}
size_t skip_value(std::string_view t, size_t i) {
  i = skip_ws(t, i);
  if (i >= t.size()) return i;
  if (t[i] == '"') return skip_string(t, i);
  if (t[i] == '{' || t[i] == '[') {
    int depth = 0;
    for (; i < t.size(); ++i) {
      if (t[i] == '"') { i = skip_string(t, i) - 1; continue; }
      if (t[i] == '{' || t[i] == '[') ++depth;
      if ((t[i] == '}' || t[i] == ']') && --depth == 0) return i + 1;
    }
    return i;
  }
  while (i < t.size() && t[i] != ',' && t[i] != '}' && t[i] != ']' && t[i] != ' ' && t[i] != '\n') ++i;
  return i;
}

std::string unescape_key(std::string_view raw) {
  try {
    return json::parse(raw).get<std::string>();
  } catch (...) {
    return std::string(raw);
  }
}

// The value of key/index `step` inside the object/array at `i`; npos when absent.
size_t child(std::string_view t, size_t i, const std::string& step) {
  i = skip_ws(t, i);
  if (i >= t.size()) return std::string_view::npos;
  if (t[i] == '{') {
    i = skip_ws(t, i + 1);
    while (i < t.size() && t[i] == '"') {
      const size_t end = skip_string(t, i);
      const std::string key = unescape_key(t.substr(i, end - i));
      i = skip_ws(t, end) + 1;  // past ':'
      const size_t value = skip_ws(t, i);
      if (key == step) return value;
      i = skip_ws(t, skip_value(t, value));
      if (i < t.size() && t[i] == ',') i = skip_ws(t, i + 1);
    }
  } else if (t[i] == '[') {
    size_t n = 0;
    for (char c : step)
      if (c < '0' || c > '9') return std::string_view::npos;
    const size_t want = std::stoul(step.empty() ? "0" : step);
    i = skip_ws(t, i + 1);
    while (i < t.size() && t[i] != ']') {
      if (n++ == want) return i;
      i = skip_ws(t, skip_value(t, i));
      if (i < t.size() && t[i] == ',') i = skip_ws(t, i + 1);
    }
  }
  return std::string_view::npos;
}

Diagnostic at_offset(const std::string& file, std::string_view text, size_t offset, const std::string& message) {
  Diagnostic d{file, 1, 1, Severity::Error, message};
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') { ++d.line; d.column = 1; }
    else ++d.column;
  }
  return d;
}

// A positive finite number (strtod strings accepted, as in verify specs).
bool to_number(const json& j, double* out) {
  if (j.is_number()) *out = j.get<double>();
  else if (j.is_string()) {
    const std::string s = j.get<std::string>();
    char* end = nullptr;
    *out = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0') return false;
  } else return false;
  return std::isfinite(*out);
}

struct Parser {
  Scene& scene;
  std::string error_path, error_message;

  bool fail(const std::string& path, const std::string& message) {
    error_path = path;
    error_message = message;
    return false;
  }

  // One number or an array of numbers (one per component).
  bool numbers(const json& j, const std::string& path, std::vector<double>* out) {
    if (j.is_array()) {
      if (j.empty() || j.size() > 16) return fail(path, "expected 1 to 16 numbers");
      for (size_t i = 0; i < j.size(); ++i) {
        double d = 0;
        if (!to_number(j[i], &d)) return fail(path + "/" + std::to_string(i), "expected a finite number");
        out->push_back(d);
      }
      return true;
    }
    double d = 0;
    if (!to_number(j, &d)) return fail(path, "expected a finite number or an array of them");
    out->push_back(d);
    return true;
  }

  bool input(const std::string& name, const json& j, const std::string& path) {
    if (!j.is_object()) return fail(path, "an input is {\"abs_max\": X} or {\"min\": LO, \"max\": HI}");
    InputRange r;
    r.path = path;
    std::vector<double> abs_max, lo, hi;
    for (const auto& [key, v] : j.items()) {
      const std::string p = path + "/" + key;
      if (key == "abs_max") {
        if (!numbers(v, p, &abs_max)) return false;
        for (double m : abs_max)
          if (m < 0) return fail(p, "abs_max must not be negative");
      } else if (key == "min") {
        if (!numbers(v, p, &lo)) return false;
      } else if (key == "max") {
        if (!numbers(v, p, &hi)) return false;
      } else {
        return fail(p, "unknown field '" + key + "' (expected abs_max, or min and max)");
      }
    }
    if (!abs_max.empty()) {
      if (!lo.empty() || !hi.empty()) return fail(path, "give abs_max or min/max, not both");
      for (double m : abs_max) r.components.push_back({-m, m});
    } else {
      if (lo.empty() || hi.empty()) return fail(path, "input '" + name + "' needs abs_max, or both min and max");
      if (lo.size() != hi.size() && lo.size() != 1 && hi.size() != 1)
        return fail(path, "min and max have different numbers of components");
      const size_t n = std::max(lo.size(), hi.size());
      for (size_t i = 0; i < n; ++i) {
        const Interval c{lo[lo.size() == 1 ? 0 : i], hi[hi.size() == 1 ? 0 : i]};
        if (c.lo > c.hi) return fail(path, "min is greater than max (component " + std::to_string(i) + ")");
        r.components.push_back(c);
      }
    }
    scene.inputs[name] = std::move(r);
    return true;
  }

  bool relation(const json& j, const std::string& path) {
    if (!j.is_object()) return fail(path, "a relation is {\"difference\": [A, B], \"abs_max\": R}");
    Relation r;
    r.path = path;
    bool have_difference = false, have_bound = false;
    for (const auto& [key, v] : j.items()) {
      const std::string p = path + "/" + key;
      if (key == "difference") {
        if (!v.is_array() || v.size() != 2 || !v[0].is_string() || !v[1].is_string())
          return fail(p, "difference must name two inputs: [\"A\", \"B\"]");
        r.a = v[0].get<std::string>();
        r.b = v[1].get<std::string>();
        if (r.a == r.b) return fail(p, "a difference needs two different inputs");
        have_difference = true;
      } else if (key == "abs_max") {
        if (!to_number(v, &r.abs_max) || r.abs_max < 0) return fail(p, "abs_max must be a non-negative number");
        have_bound = true;
      } else {
        return fail(p, "unknown field '" + key + "' (expected difference and abs_max)");
      }
    }
    if (!have_difference || !have_bound) return fail(path, "a relation needs difference and abs_max");
    for (const std::string& n : {r.a, r.b})
      if (!scene.inputs.count(n) && !is_computed_value(n))
        return fail(path + "/difference", "'" + n + "' is not among the scene's inputs (nor a FUNCTION.LOCAL value)");
    scene.relations.push_back(std::move(r));
    return true;
  }

  bool output(const std::string& name, const json& j, const std::string& path) {
    if (!j.is_object()) return fail(path, "an output is {\"abs_error\": E}");
    OutputRequirement o;
    o.path = path;
    bool have = false;
    for (const auto& [key, v] : j.items()) {
      if (key != "abs_error") return fail(path + "/" + key, "unknown field '" + key + "' (expected abs_error)");
      if (!to_number(v, &o.abs_error) || !(o.abs_error > 0)) return fail(path + "/abs_error", "abs_error must be a positive number");
      have = true;
    }
    if (!have) return fail(path, "output '" + name + "' needs abs_error");
    scene.outputs[name] = o;
    return true;
  }

  bool document(const json& j) {
    if (!j.is_object()) return fail("", "a scene is a JSON object with inputs, relations and outputs");
    // Inputs first: relations refer to them.
    if (j.contains("inputs")) {
      const json& in = j["inputs"];
      if (!in.is_object()) return fail("/inputs", "inputs must be an object of NAME: range");
      for (const auto& [name, v] : in.items())
        if (!input(name, v, "/inputs/" + name)) return false;
    }
    for (const auto& [key, v] : j.items()) {
      if (key == "inputs") continue;
      if (key == "relations") {
        if (!v.is_array()) return fail("/relations", "relations must be an array");
        for (size_t i = 0; i < v.size(); ++i)
          if (!relation(v[i], "/relations/" + std::to_string(i))) return false;
      } else if (key == "outputs") {
        if (!v.is_object()) return fail("/outputs", "outputs must be an object of NAME: {abs_error}");
        for (const auto& [name, o] : v.items())
          if (!output(name, o, "/outputs/" + name)) return false;
      } else if (key != "comment") {
        return fail("/" + key, "unknown field '" + key + "' (expected inputs, relations, outputs, comment)");
      }
    }
    if (scene.outputs.empty()) return fail("", "the scene names no outputs: nothing to plan for");
    return true;
  }
};

}  // namespace

Diagnostic json_syntax_diagnostic(std::string_view text, const std::string& file, const std::string& what,
                                  const std::exception& e, size_t byte) {
  // `byte` is the 1-based offset of the character that stopped the parser.
  std::string message = e.what();
  if (const size_t p = message.find("parse error"); p != std::string::npos) message = message.substr(p);
  return at_offset(file, text, byte > 0 ? byte - 1 : 0, what + " is not valid JSON: " + message);
}

size_t json_value_offset(std::string_view text, const std::string& pointer) {
  size_t at = skip_ws(text, 0);
  size_t i = 1;
  while (i <= pointer.size() && !pointer.empty()) {
    const size_t next = pointer.find('/', i);
    std::string step = pointer.substr(i, next == std::string::npos ? std::string::npos : next - i);
    const size_t c = child(text, at, step);
    if (c == std::string_view::npos) return at;
    at = c;
    if (next == std::string::npos) break;
    i = next + 1;
  }
  return at;
}

Diagnostic scene_diagnostic(const Scene& scene, const std::string& pointer, const std::string& message) {
  return at_offset(scene.file, scene.text, json_value_offset(scene.text, pointer), message);
}

bool parse_scene(std::string_view text, const std::string& file, Scene* out, Diagnostic* error) {
  out->file = file;
  out->text = std::string(text);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    *error = json_syntax_diagnostic(text, file, "scene", e, e.byte);
    return false;
  }
  Parser p{*out, {}, {}};
  if (!p.document(j)) {
    *error = scene_diagnostic(*out, p.error_path, p.error_message);
    return false;
  }
  return true;
}

}  // namespace doublet::plan
