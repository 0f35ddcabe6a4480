#include "bench/kernels.hpp"

#include <cstdint>
#include <cstring>
#include <algorithm>
#include <cstdlib>

#include "rules/rule_library.hpp"

namespace doublet::bench {

namespace {
// The "Flops:" count of the rule `name` at `width` (rules/*.glsl headers, which docs/rules.md
// repeats and tests/rules checks); -1 when the library has no such rule.
int rule_flops(const std::string& name, int width) {
  for (const rules::RuleInfo& info : rules::RuleLibrary::builtin().info())
    if (info.name == name && std::find(info.widths.begin(), info.widths.end(), width) != info.widths.end()) {
      // "210 (W = 4; 110 for W = 2, 160 for W = 3)": the count for this width where one is named.
      const std::string at = " for W = " + std::to_string(width);
      if (const size_t p = info.flops.find(at); p != std::string::npos) {
        size_t start = info.flops.find_last_not_of("0123456789", p - 1);
        start = start == std::string::npos ? 0 : start + 1;
        return std::atoi(info.flops.c_str() + start);
      }
      return std::atoi(info.flops.c_str());
    }
  return -1;
}
}  // namespace

const std::vector<Kernel>& kernels() {
  // Flops come from the rule headers (so they follow the rules); bits are measured per run.
  static const std::vector<Kernel> k = {
      {"add", "df_add", rule_flops("df_add", 1), 1, 2048},
      {"sub", "df_sub", rule_flops("df_sub", 1), 1, 2048},
      {"mul", "df_mul", rule_flops("df_mul", 1), 1, 2048},
      {"div", "df_div", rule_flops("df_div", 1), 1, 2048},
      {"sqrt", "df_sqrt", rule_flops("df_sqrt", 1), 1, 2048},
      {"add3", "df_add (3 components)", 3 * rule_flops("df_add", 1), 3, 1024},
      {"dot3", "df_dot (3)", rule_flops("df_dot", 3), 5, 1024},
      {"length3", "df_length (2-4)", rule_flops("df_length", 3), 6, 1024},
      {"mat4", "df_mul_dmatCxR_dvecC (4 × df_dot 4)", 4 * rule_flops("df_dot", 4), 28, 256},
      // The transcendental extension (docs/transcendentals.md): each step adds a negation or an
      // addition to keep the chain bounded; native fp64 has no such function, so no native row.
      {"exp", "df_exp", rule_flops("df_exp", 1), 2, 128},
      {"log", "df_log", rule_flops("df_log", 1), 2, 128},
      {"cos", "df_cos", rule_flops("df_cos", 1), 1, 128},
      {"atan", "df_atan", rule_flops("df_atan", 1), 2, 128},
      {"pow", "df_pow", rule_flops("df_pow", 1), 2, 64},
  };
  return k;
}

const Kernel* find_kernel(const std::string& op) {
  for (const Kernel& k : kernels())
    if (k.op == op) return &k;
  return nullptr;
}

int rounded_steps(int steps) { return steps < kUnroll ? kUnroll : (steps + kUnroll - 1) / kUnroll * kUnroll; }

namespace {
struct Body {
  const char* setup;  // declarations from `p` (dvec4 of the element's inputs)
  const char* step;   // one dependent step
  const char* store;  // vec4 written to outp[i]
};

Body body(const std::string& op) {
  // y near 1 for mul/div keeps the chain's magnitude bounded; dot3 weights sum below 1 and
  // length3 grows like sqrt(steps), so no chain overflows or underflows.
  if (op == "add") return {"double x = p.x; double y = p.y;", "x = x + y;", "vec4(float(x))"};
  if (op == "sub") return {"double x = p.x; double y = p.y;", "x = x - y;", "vec4(float(x))"};
  if (op == "mul") return {"double x = p.x; double y = 1.0 + p.y * 0.001;", "x = x * y;", "vec4(float(x))"};
  if (op == "div") return {"double x = p.x; double y = 1.0 + p.y * 0.001;", "x = x / y;", "vec4(float(x))"};
  if (op == "sqrt") return {"double x = p.x + p.y;", "x = sqrt(x);", "vec4(float(x))"};
  // add3: a vector operation (mode exact runs its components in a loop, docs/performance.md).
  if (op == "add3") return {"dvec3 v = p.xyz; dvec3 w = p.wzy;", "v = v + w;", "vec4(vec3(v), 0.0)"};
  if (op == "dot3") return {"dvec3 v = p.xyz; dvec3 w = p.wzy * 0.3;", "v.x = dot(v, w);", "vec4(vec3(v), 0.0)"};
  if (op == "length3") return {"dvec3 v = p.xyz;", "v.x = length(v);", "vec4(vec3(v), 0.0)"};
  // Fixed points keep these chains bounded: exp(-x) -> 0.567, log(x + 2) -> 1.146, cos(x) -> 0.739,
  // atan(x) + 1 -> 2.132, x^0.5 + 1 -> 2.618.
  if (op == "exp") return {"double x = p.x;", "x = exp(-x);", "vec4(float(x))"};
  if (op == "log") return {"double x = p.x;", "x = log(x + 2.0);", "vec4(float(x))"};
  if (op == "cos") return {"double x = p.x;", "x = cos(x);", "vec4(float(x))"};
  if (op == "atan") return {"double x = p.x;", "x = atan(x) + 1.0;", "vec4(float(x))"};
  if (op == "pow") return {"double x = p.x; double y = 0.5;", "x = pow(x, y) + 1.0;", "vec4(float(x))"};
  return {"dmat4 m = dmat4(dvec4(mcol[0]), dvec4(mcol[1]), dvec4(mcol[2]), dvec4(mcol[3])); dvec4 v = p;",
          "v = m * v;", "vec4(v)"};
}
}  // namespace

std::string kernel_step(const Kernel& k) { return body(k.op).step; }

std::string kernel_accuracy_source(const Kernel& k) {
  const std::string r = k.op == "add3" || k.op == "dot3" || k.op == "length3" || k.op == "mat4" ? "v.x" : "x";
  const std::string plain = "outp[i] = " + std::string(body(k.op).store) + ";";
  std::string s = kernel_source(k, kUnroll);
  s.replace(s.find(plain), plain.size(),
            "outp[i] = vec4(float(" + r + "), float(" + r + " - double(float(" + r + "))), 0.0, 0.0);");
  // Inputs with a lo word: a float plus another float times 2^-24 (exact in fp64 and in
  // float-float), so the chain's sums and products have rounding errors to show; the float
  // inputs of the timing kernel would make add and sub exact.
  const std::string input = "dvec4 p = dvec4(inp[i]);";
  s.replace(s.find(input), input.size(), "dvec4 p = dvec4(inp[i]) + dvec4(inp[i].wzyx) * 5.9604644775390625e-8lf;");
  return s;
}

long double stored_hi_lo(const std::vector<uint8_t>& outp, size_t i) {
  float w[2];
  std::memcpy(w, outp.data() + 16 * i, 8);
  return static_cast<long double>(w[0]) + static_cast<long double>(w[1]);
}

std::string kernel_source(const Kernel& k, int steps) {
  const Body b = body(k.op);
  std::string unrolled;
  for (int u = 0; u < kUnroll; ++u) unrolled += std::string("    ") + b.step + "\n";
  std::string s =
      "#version 450\n"
      "layout(local_size_x = " + std::to_string(kLocalSize) + ") in;\n"
      "layout(std430, binding = 0) readonly buffer Inputs { vec4 inp[]; };\n"
      "layout(std430, binding = 1) writeonly buffer Outputs { vec4 outp[]; };\n";
  if (k.op == "mat4") s += "layout(std430, binding = 2) readonly buffer Matrix { vec4 mcol[4]; };\n";
  s += "void main() {\n"
       "  uint i = gl_GlobalInvocationID.x;\n"
       "  dvec4 p = dvec4(inp[i]);\n"
       "  " + std::string(b.setup) + "\n"
       "  for (int k = 0; k < " + std::to_string(rounded_steps(steps) / kUnroll) + "; ++k) {\n" +
       unrolled +
       "  }\n"
       "  outp[i] = " + b.store + ";\n"
       "}\n";
  return s;
}

std::vector<std::vector<uint8_t>> kernel_buffers(const Kernel& k, int elements) {
  std::vector<float> in(static_cast<size_t>(elements) * 4);
  uint32_t state = 12345;
  for (float& v : in) {  // xorshift: reproducible, no <random> distribution differences
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    v = 0.5f + static_cast<float>(state >> 8) * (0.5f / 16777216.0f);
  }
  std::vector<std::vector<uint8_t>> buffers{bytes_of(in), std::vector<uint8_t>(in.size() * sizeof(float))};
  if (k.op == "mat4") {
    // Entries in [0.1, 0.24): every row sums below 1, so repeated m * v stays bounded.
    std::vector<float> m(16);
    for (size_t j = 0; j < m.size(); ++j) m[j] = 0.1f + 0.01f * static_cast<float>((j * 7) % 15);
    buffers.push_back(bytes_of(m));
  }
  return buffers;
}

}  // namespace doublet::bench
