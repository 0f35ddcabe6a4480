#include "verify/spec.hpp"

#include <cstdlib>
#include <nlohmann/json.hpp>

namespace doublet::verify {
namespace {

// A number, or a string strtod accepts in full ("0x1.8p-3", "1e-30", "inf").
bool to_double(const nlohmann::json& j, double* out) {
  if (j.is_number()) {
    *out = j.get<double>();
    return true;
  }
  if (!j.is_string()) return false;
  const std::string s = j.get<std::string>();
  char* end = nullptr;
  *out = std::strtod(s.c_str(), &end);
  return !s.empty() && end && *end == '\0';
}

bool parse_number(const std::string& s, double* out) { return to_double(nlohmann::json(s), out); }

std::string check_range(const InputSpec& in) {
  if (*in.lo > *in.hi) return "range is empty (LO > HI)";
  return {};
}

}  // namespace

InputSpec InputSpec::component(size_t c) const {
  if (component_ranges.empty()) return *this;
  InputSpec s = *this;
  const auto& r = component_ranges[component_ranges.size() == 1 ? 0 : c % component_ranges.size()];
  s.lo = r.first;
  s.hi = r.second;
  return s;
}

std::string parse_range(const std::string& text, std::string* name, InputSpec* out) {
  const size_t eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos)
    return "expected NAME=LO:HI, got '" + text + "'";
  double lo = 0, hi = 0;
  if (!parse_number(text.substr(eq + 1, colon - eq - 1), &lo) || !parse_number(text.substr(colon + 1), &hi))
    return "bad number in range '" + text + "'";
  *name = text.substr(0, eq);
  out->lo = lo;
  out->hi = hi;
  return check_range(*out);
}

std::string parse_spec(const std::string& json_text, Spec* out) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const std::exception& e) {
    return std::string("spec is not valid JSON: ") + e.what();
  }
  if (!j.is_object()) return "spec must be a JSON object";
  for (const auto& [key, value] : j.items()) {
    if (key == "array_length") {
      if (!value.is_number_unsigned() || value.get<unsigned>() == 0) return "array_length must be a positive integer";
      out->array_length = value.get<unsigned>();
    } else if (key == "groups") {
      if (!value.is_array() || value.empty() || value.size() > 3) return "groups must be [x] .. [x, y, z]";
      for (size_t d = 0; d < value.size(); ++d) {
        if (!value[d].is_number_unsigned() || value[d].get<unsigned>() == 0) return "groups must be positive integers";
        out->groups[d] = value[d].get<unsigned>();
      }
    } else if (key == "inputs") {
      if (!value.is_object()) return "inputs must be an object of NAME: {range|values}";
      for (const auto& [name, in] : value.items()) {
        InputSpec& spec = out->inputs[name];
        for (const auto& [field, v] : in.items()) {
          if (field == "range") {
            double lo = 0, hi = 0;
            if (!v.is_array() || v.size() != 2 || !to_double(v[0], &lo) || !to_double(v[1], &hi))
              return "inputs." + name + ".range must be [LO, HI]";
            spec.lo = lo;
            spec.hi = hi;
            if (std::string e = check_range(spec); !e.empty()) return "inputs." + name + ": " + e;
          } else if (field == "values") {
            if (!v.is_array() || v.empty()) return "inputs." + name + ".values must be a non-empty array";
            for (const auto& x : v) {
              double d = 0;
              if (!to_double(x, &d)) return "inputs." + name + ".values: not a number: " + x.dump();
              spec.values.push_back(d);
            }
          } else if (field == "elements_per_invocation" && v.is_number_unsigned() && v.get<unsigned>() > 0) {
            spec.elements_per_invocation = v.get<unsigned>();
          } else {
            return "inputs." + name + ": unknown field or bad value '" + field + "'";
          }
        }
      }
    } else if (key == "outputs") {
      if (!value.is_object()) return "outputs must be an object of NAME: {min_bits, abs_floor, join}";
      for (const auto& [name, o] : value.items()) {
        OutputSpec& spec = out->outputs[name];
        for (const auto& [field, v] : o.items()) {
          double d = 0;
          if (field == "min_bits" && to_double(v, &d)) spec.min_bits = d;
          else if (field == "abs_floor" && to_double(v, &d) && d > 0) spec.abs_floor = d;
          else if (field == "join" && v == "hi_lo") spec.join_hi_lo = true;
          else if (field == "elements_per_invocation" && v.is_number_unsigned() && v.get<unsigned>() > 0)
            spec.elements_per_invocation = v.get<unsigned>();
          else return "outputs." + name + "." + field + ": unknown field or bad value " + v.dump();
        }
      }
    } else {
      return "unknown spec field '" + key + "'";
    }
  }
  return {};
}

}  // namespace doublet::verify
