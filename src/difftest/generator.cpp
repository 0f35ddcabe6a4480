// Program generator for the differential tester; see generator.hpp. One Generator per program: it
// keeps the variables in scope (with a rough bound on their magnitude) and writes the text as it
// decides. Every choice draws from one seeded engine, so a seed names a program.
#include "difftest/generator.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

namespace doublet::difftest {
namespace {

enum class Ty { D, V2, V3, V4, M2, M3, I, B };

const char* type_name(Ty t) {
  switch (t) {
    case Ty::D: return "double";
    case Ty::V2: return "dvec2";
    case Ty::V3: return "dvec3";
    case Ty::V4: return "dvec4";
    case Ty::M2: return "dmat2";
    case Ty::M3: return "dmat3";
    case Ty::I: return "int";
    case Ty::B: return "bool";
  }
  return "?";
}
int size_of(Ty t) {  // components of a vector, columns of a matrix
  switch (t) {
    case Ty::V2: case Ty::M2: return 2;
    case Ty::V3: case Ty::M3: return 3;
    case Ty::V4: return 4;
    default: return 1;
  }
}
Ty vec_of(int n) { return n == 1 ? Ty::D : n == 2 ? Ty::V2 : n == 3 ? Ty::V3 : Ty::V4; }
bool is_vec(Ty t) { return t == Ty::V2 || t == Ty::V3 || t == Ty::V4; }
bool is_num(Ty t) { return t == Ty::D || is_vec(t); }
bool is_mat(Ty t) { return t == Ty::M2 || t == Ty::M3; }

constexpr double kWrap = 1e8;     // a product bound above this is clamped
constexpr double kClampTo = 1e6;  // ... to this

struct Ex {
  std::string s;
  double b = 1;  // rough bound on |value|
};

// A name in scope. Arrays hold `len` elements of `ty`; a struct variable's fields are a (double)
// and b (the program's struct vector type).
struct Var {
  std::string name;
  Ty ty = Ty::D;
  double b = 1;
  bool writable = true;
  int len = 0;          // > 0: an array
  bool is_struct = false;
};

struct Func {
  std::string name;
  Ty ret = Ty::D;
  std::vector<std::pair<std::string, Ty>> params;  // qualifier ("in", "inout", "out") and type
  bool pure() const {
    return std::all_of(params.begin(), params.end(), [](const auto& p) { return p.first == "in"; });
  }
};

std::string literal(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s + "lf";
}

class Generator {
 public:
  explicit Generator(uint64_t seed) : rng_(seed) { program_.seed = seed; }

  Program run() {
    const int which = pick(0, 10);
    stage_ = which < 6 ? "comp" : which < 8 ? "vert" : which < 10 ? "frag" : "geom";
    // Half the geometry seeds make tessellation shaders (chosen by the seed: other programs stay).
    if (stage_ == "geom" && program_.seed % 4 >= 2) stage_ = program_.seed % 4 == 2 ? "tese" : "tesc";
    program_.stage = stage_;
    feature("stage:" + stage_);
    // One compute or vertex program in three is continuous, for the bound oracle (oracles.hpp). Decided
    // by the seed, not the engine, so the other programs stay what their seeds made before.
    continuous_ = (stage_ == "comp" || stage_ == "vert") && program_.seed % 3 == 0;
    allow_rounding_ = chance(0.3);
    struct_vec_ = vec_of(pick(2, 4));
    const int inputs = pick(1, 4), outputs = pick(1, 3);
    std::string head = "#version 450\n";
    if (stage_ == "comp") head += "layout(local_size_x = 64) in;\n";
    // A geometry shader: one point in, one emitted (verify compares each emitted vertex).
    if (stage_ == "geom") head += "layout(points) in;\nlayout(points, max_vertices = 1) out;\n";
    // Tessellation (docs/verify.md): a control shader of one control point per patch; an evaluation
    // shader on triangles, its inputs the corners weighted by gl_TessCoord.
    if (stage_ == "tesc") head += "layout(vertices = 1) out;\n";
    if (stage_ == "tese") head += "layout(triangles, equal_spacing, ccw) in;\n";
    std::string spec = "{\n  \"inputs\": {";
    for (int i = 0; i < inputs; ++i) {
      const Ty t = vec_of(pick(1, 4));
      const std::string name = "in" + std::to_string(i);
      if (stage_ == "comp") {
        const bool std140 = chance(0.25);
        if (std140) feature("layout:std140");
        head += "layout(" + std::string(std140 ? "std140" : "std430") + ", binding = " + std::to_string(i) +
                ") readonly buffer In" + std::to_string(i) + " { " + type_name(t) + " " + name + "[]; };\n";
      } else {
        head += std::string(stage_ == "frag" ? "flat in " : "in ") + type_name(t) + " " + name +
                (per_vertex() ? "[]" : "") + ";\n";
      }
      const bool positive = chance(0.4);
      // A per-vertex input is fed element by element (verify names them in0[0], in0[1], ...).
      const int elements = stage_ == "tese" ? 3 : 1;
      for (int k = 0; k < elements; ++k)
        spec += std::string(i || k ? "," : "") + "\n    \"" + name + (per_vertex() ? "[" + std::to_string(k) + "]" : "") +
                "\": { \"range\": " + (positive ? "[0.25, 4]" : "[-3, 3]") + " }";
      inputs_.push_back({name, t, 4, false});
    }
    std::string output_spec;
    for (int o = 0; o < outputs; ++o) {
      const std::string name = "r" + std::to_string(o);
      if (stage_ == "comp") {
        const Ty t = vec_of(pick(1, 4));
        head += "layout(std430, binding = " + std::to_string(inputs + o) + ") writeonly buffer Out" + std::to_string(o) +
                " { " + type_name(t) + " " + name + "[]; };\n";
        outputs_.push_back({name, t});
      } else if (stage_ != "frag") {
        const Ty t = vec_of(pick(1, 4));
        head += "out " + std::string(type_name(t)) + " " + name + (stage_ == "tesc" ? "[]" : "") + ";\n";
        outputs_.push_back({name, t});
      } else {
        // A fragment shader cannot output doubles: (hi, lo) float pairs, compared joined.
        const Ty t = vec_of(pick(1, 2));
        head += "layout(location = " + std::to_string(o) + ") out vec4 " + name + ";\n";
        outputs_.push_back({name, t});
        output_spec += std::string(output_spec.empty() ? "" : ",") + "\n    \"" + name + "\": { \"join\": \"hi_lo\" }";
      }
    }
    if (stage_ != "comp" && chance(0.3)) {
      // A std140 uniform block (verify feeds it in the vertex and fragment stages only).
      feature("block:uniform");
      head += "layout(std140) uniform Params {\n";
      for (int m = pick(1, 2); m > 0; --m) {
        const Ty t = vec_of(pick(1, 3));
        const std::string name = fresh("b");
        head += "  " + std::string(type_name(t)) + " " + name + ";\n";
        spec += ",\n    \"Params." + name + "\": { \"range\": [-2, 2] }";
        block_members_.push_back({name, t, 2, false});
      }
      head += "};\n";
    }
    spec += "\n  }";
    if (!output_spec.empty()) spec += ",\n  \"outputs\": {" + output_spec + "\n  }";
    spec += "\n}\n";
    if (chance(0.5)) {
      feature("struct");
      head += std::string("struct S { double a; ") + type_name(struct_vec_) + " b; };\n";
      has_struct_ = true;
    }
    head += "double scratch;\n";
    scope_.insert(scope_.end(), block_members_.begin(), block_members_.end());
    // Globals: constants, initialised globals, a uniform with an initializer.
    for (int g = pick(0, 2); g > 0; --g) {
      const Ty t = vec_of(pick(1, 4));
      const Ex init = literal_of(t);
      const bool is_const = chance(0.5);
      const std::string name = fresh(is_const ? "C" : "g");
      feature(is_const ? "global:const" : "global:initialised");
      head += std::string(is_const ? "const " : "") + type_name(t) + " " + name + " = " + init.s + ";\n";
      scope_.push_back({name, t, init.b, !is_const});
    }
    if (!continuous_ && chance(0.15)) {  // (a bound oracle's scene has the spec's inputs only)
      feature("global:uniform-initialised");
      const std::string name = fresh("u");
      const Ex init = literal_of(Ty::D);
      head += "uniform double " + name + " = " + init.s + ";\n";
      scope_.push_back({name, Ty::D, init.b, false});
    }
    text_ = head;
    if (!continuous_)
      for (int f = pick(0, 2); f > 0; --f) function();
    main_function();
    program_.glsl = text_;
    program_.spec_json = spec;
    return program_;
  }

 private:
  // ---- randomness ----
  int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  template <class T>
  const T& one_of(const std::vector<T>& v) { return v[static_cast<size_t>(pick(0, static_cast<int>(v.size()) - 1))]; }
  std::string fresh(const std::string& prefix) { return prefix + std::to_string(counter_++); }
  void feature(const std::string& f) { program_.features.insert(f); }

  // ---- scope ----
  std::vector<const Var*> vars_where(const std::function<bool(const Var&)>& keep) const {
    std::vector<const Var*> out;
    for (const Var& v : scope_)
      if (keep(v)) out.push_back(&v);
    return out;
  }
  Var* find(const std::string& name) {
    for (Var& v : scope_)
      if (v.name == name) return &v;
    return nullptr;
  }
  void grow(const std::string& name, double b) {
    if (Var* v = find(name)) v->b = std::max(v->b, b);
  }

  // ---- expressions ----
  Ex literal_of(Ty t) {
    auto scalar = [&]() -> double {
      switch (pick(0, 3)) {
        case 0: return pick(-4, 4);
        case 1: return pick(-64, 64) / 16.0;
        default: return std::uniform_real_distribution<double>(-4, 4)(rng_);  // all 53 bits
      }
    };
    if (t == Ty::D) {
      const double v = scalar();
      return {literal(v), std::max(1.0, std::fabs(v))};
    }
    if (is_vec(t)) {
      if (chance(0.4)) {
        const double v = scalar();
        return {std::string(type_name(t)) + "(" + literal(v) + ")", std::max(1.0, std::fabs(v))};
      }
      std::string s = std::string(type_name(t)) + "(";
      double b = 1;
      for (int c = 0; c < size_of(t); ++c) {
        const double v = scalar();
        s += (c ? ", " : "") + literal(v);
        b = std::max(b, std::fabs(v));
      }
      return {s + ")", b};
    }
    if (is_mat(t)) return {std::string(type_name(t)) + "(" + literal(pick(1, 3)) + ")", 3};
    if (t == Ty::I) return {std::to_string(pick(-3, 5)), 5};
    return {chance(0.5) ? "true" : "false", 1};
  }

  Ex gen(Ty t, int depth) {
    if (t == Ty::B) return gen_bool(depth);
    if (t == Ty::I) return gen_int(depth);
    if (is_mat(t)) return gen_mat(t, depth);
    if (depth <= 0 || chance(0.2)) return leaf(t);
    for (;;) {
      Ex e;
      if (num_production(t, depth, &e)) return wrap(e);
    }
  }

  Ex wrap(Ex e) {
    if (e.b <= kWrap) return e;
    feature("fn:clamp");
    return {"clamp(" + e.s + ", " + literal(-kClampTo) + ", " + literal(kClampTo) + ")", kClampTo};
  }

  // clamp() has no matrix form: a matrix keeps its value, and its bound stops growing (a program
  // whose matrices overflow is still checked; the oracles skip non-finite samples).
  static Ex capped(Ex e) {
    e.b = std::min(e.b, kClampTo);
    return e;
  }

  // A variable, a component, an element, a field or a literal of type t (double or dvecN).
  Ex leaf(Ty t) {
    std::vector<Ex> options;
    for (const Var* v : vars_where([&](const Var& v) { return v.ty == t && v.len == 0 && !v.is_struct; }))
      options.push_back({v->name, v->b});
    if (t == Ty::D)
      for (const Var* v : vars_where([&](const Var& v) { return is_vec(v.ty) && v.len == 0 && !v.is_struct; })) {
        const int c = pick(0, size_of(v->ty) - 1);
        options.push_back({v->name + (chance(0.5) ? std::string(".") + "xyzw"[c] : "[" + std::to_string(c) + "]"), v->b});
      }
    if (is_vec(t))
      for (const Var* v : vars_where([&](const Var& v) { return is_vec(v.ty) && v.len == 0 && !v.is_struct; })) {
        std::string sw;
        for (int c = 0; c < size_of(t); ++c) sw += "xyzw"[pick(0, size_of(v->ty) - 1)];
        feature("swizzle:read");
        options.push_back({v->name + "." + sw, v->b});
      }
    if (is_vec(t))
      for (const Var* v : vars_where([&](const Var& v) { return is_mat(v.ty) && size_of(v.ty) == size_of(t) && v.len == 0; }))
        options.push_back({v->name + "[" + std::to_string(pick(0, size_of(t) - 1)) + "]", v->b});
    if (t == Ty::D)
      for (const Var* v : vars_where([&](const Var& v) { return is_mat(v.ty) && v.len == 0; }))
        options.push_back({v->name + "[" + std::to_string(pick(0, size_of(v->ty) - 1)) + "][" +
                               std::to_string(pick(0, size_of(v->ty) - 1)) + "]", v->b});
    for (const Var* v : vars_where([&](const Var& v) { return v.len > 0 && (v.is_struct || v.ty == t); })) {
      std::string index = std::to_string(pick(0, v->len - 1));
      const auto loops = vars_where([](const Var& x) { return x.ty == Ty::I && !x.writable && x.name[0] == 'k'; });
      if (!loops.empty() && chance(0.5)) index = one_of(loops)->name + " % " + std::to_string(v->len);
      const std::string element = v->name + "[" + index + "]";
      if (!v->is_struct) options.push_back({element, v->b});
      else if (t == Ty::D) options.push_back({element + ".a", v->b});
      else if (t == struct_vec_) options.push_back({element + ".b", v->b});
    }
    for (const Var* v : vars_where([&](const Var& v) { return v.is_struct && v.len == 0; })) {
      if (t == Ty::D) options.push_back({v->name + ".a", v->b});
      if (t == struct_vec_) options.push_back({v->name + ".b", v->b});
    }
    if (options.empty() || chance(0.15)) return literal_of(t);
    return one_of(options);
  }

  Ex scalar_or_same(Ty t, int depth) { return gen(is_vec(t) && chance(0.3) ? Ty::D : t, depth); }
  std::string denominator_floor() { return pick(0, 1) ? "1.0lf" : "1.5lf"; }

  bool num_production(Ty t, int depth, Ex* out) {
    const int d = depth - 1;
    const int n = size_of(t);
    const int kind = pick(0, 19);
    // A continuous program: no production that jumps (rounding to integers, comparisons, ?:) and
    // none the planner has no error bound for (ldexp, determinant, the identity through words).
    if (continuous_ && (kind == 11 || kind == 13 || kind == 17 || kind >= 19 || (kind == 18 && t == Ty::D))) return false;
    switch (kind) {
      case 0: {
        const Ex a = gen(t, d);
        feature("op:neg");
        *out = {"-" + paren(a.s), a.b};
        return true;
      }
      case 1: case 2: {
        const bool add = chance(0.5);
        Ex a = gen(t, d), b = scalar_or_same(t, d);
        if (chance(0.5)) std::swap(a, b);
        feature(add ? "op:+" : "op:-");
        *out = {"(" + a.s + (add ? " + " : " - ") + b.s + ")", a.b + b.b};
        return true;
      }
      case 3: case 4: {
        Ex a = gen(t, d), b = scalar_or_same(t, d);
        if (chance(0.5)) std::swap(a, b);
        feature("op:*");
        *out = {"(" + a.s + " * " + b.s + ")", a.b * b.b};
        return true;
      }
      case 5: {
        const Ex a = gen(t, d), b = scalar_or_same(t, d);
        feature("op:/");
        feature("fn:abs");
        *out = {"(" + a.s + " / (" + denominator_floor() + " + abs(" + b.s + ")))", a.b};
        return true;
      }
      case 6: {
        static const std::vector<std::string> kUnary = {"abs", "sign", "floor", "ceil", "fract", "sqrt", "inversesqrt",
                                                        "trunc", "round", "roundEven"};
        const std::string f = one_of(kUnary);
        if (!allow_rounding_ && (f == "trunc" || f == "round" || f == "roundEven")) return false;
        if (continuous_ && f != "abs" && f != "sqrt" && f != "inversesqrt") return false;
        const Ex a = gen(t, d);
        feature("fn:" + f);
        if (f == "sqrt") *out = {"sqrt(abs(" + a.s + "))", std::sqrt(a.b)};
        else if (f == "inversesqrt") *out = {"inversesqrt(" + denominator_floor() + " + abs(" + a.s + "))", 1};
        else *out = {f + "(" + a.s + ")", f == "sign" || f == "fract" ? 1 : a.b + 1};
        return true;
      }
      case 7: {
        static const std::vector<std::string> kBinary = {"min", "max", "mod", "step"};
        const std::string f = one_of(kBinary);
        if (continuous_ && f != "min" && f != "max") return false;
        const Ex a = gen(t, d), b = scalar_or_same(t, d);
        feature("fn:" + f);
        if (f == "mod") *out = {"mod(" + a.s + ", " + denominator_floor() + " + abs(" + b.s + "))", b.b + 2};
        else if (f == "step") *out = {"step(" + b.s + ", " + a.s + ")", 1};
        else *out = {f + "(" + a.s + ", " + b.s + ")", std::max(a.b, b.b)};
        return true;
      }
      case 8: {
        const Ex a = gen(t, d), b = gen(t, d), c = gen(t, d);
        feature("fn:fma");
        *out = {"fma(" + a.s + ", " + b.s + ", " + c.s + ")", a.b * b.b + c.b};
        return true;
      }
      case 9: {
        const Ex a = gen(t, d);
        const Ex b = gen(t, d);
        // Constant ends, aliased ends and a weight that is one of them are all generated: verify's
        // native reference evaluates mix as written since its built-ins are NoContraction
        // (docs/robustness.md, findings; tests/difftest/cases hold the forms that once differed).
        if (continuous_ || chance(0.5)) {
          const Ex w = scalar_or_same(t, d);
          feature("fn:mix");
          *out = {"mix(" + a.s + ", " + b.s + ", " + w.s + ")", (a.b + b.b) * (1 + w.b)};
        } else {
          const Ex c = is_vec(t) ? Ex{"lessThan(" + gen(t, d).s + ", " + gen(t, d).s + ")", 1} : gen_bool(d);
          feature("fn:mix(bool)");
          *out = {"mix(" + a.s + ", " + b.s + ", " + c.s + ")", std::max(a.b, b.b)};
        }
        return true;
      }
      case 10: {
        const Ex a = gen(t, d);
        const double lim = pick(1, 8) / 2.0;
        if (continuous_ || chance(0.5)) {
          feature("fn:clamp");
          *out = {"clamp(" + a.s + ", " + literal(-lim) + ", " + literal(lim) + ")", lim};
        } else {
          feature("fn:smoothstep");
          *out = {"smoothstep(" + literal(-lim) + ", " + literal(lim) + ", " + a.s + ")", 1};
        }
        return true;
      }
      case 11: {
        const Ex c = gen_bool(d), a = gen(t, d), b = gen(t, d);
        feature("op:?:");
        *out = {"(" + c.s + " ? " + a.s + " : " + b.s + ")", std::max(a.b, b.b)};
        return true;
      }
      case 12: {
        if (comma_used_ || t != Ty::D) return false;
        comma_used_ = true;
        const Ex a = gen(Ty::D, d), b = gen(Ty::D, d);
        feature("op:,");
        // A function has its own scratch, so a call inside a comma expression cannot write this one.
        const std::string sink = in_function_ ? "local_scratch" : "scratch";
        *out = {"(" + sink + " = " + a.s + ", " + sink + " * " + b.s + ")", a.b * b.b};
        return true;
      }
      case 13: {
        std::vector<const Func*> pure;
        for (const Func& f : funcs_)
          if (f.pure() && f.ret == t) pure.push_back(&f);
        if (pure.empty()) return false;
        const Func& f = *one_of(pure);
        std::string s = f.name + "(";
        for (size_t i = 0; i < f.params.size(); ++i) s += (i ? ", " : "") + gen(f.params[i].second, d).s;
        feature("call:expression");
        *out = {s + ")", 1e4};
        return true;
      }
      case 14: {
        if (t == Ty::D) {
          const Ex a = gen(Ty::D, d);
          switch (continuous_ ? 0 : pick(0, 2)) {
            case 0: feature("conv:float"); *out = {"double(float(" + a.s + "))", a.b}; return true;
            case 1:
              feature("conv:int");
              *out = {"double(int(clamp(" + a.s + ", -1000.0lf, 1000.0lf)))", std::min(a.b, 1000.0)};
              return true;
            default: {
              const auto ints = vars_where([](const Var& v) { return v.ty == Ty::I; });
              if (ints.empty()) return false;
              feature("conv:from-int");
              *out = {"double(" + one_of(ints)->name + ")", 16};
              return true;
            }
          }
        }
        const Ex a = gen(t, d);
        feature("conv:vec");
        *out = {std::string(type_name(t)) + "(vec" + std::to_string(n) + "(" + a.s + "))", a.b};
        return true;
      }
      case 15: {  // geometric built-ins
        if (t == Ty::D) {
          const Ty v = vec_of(pick(2, 4));
          const Ex a = gen(v, d), b = gen(v, d);
          switch (pick(0, 2)) {
            case 0: feature("fn:dot"); *out = {"dot(" + a.s + ", " + b.s + ")", 4 * a.b * b.b}; return true;
            case 1: feature("fn:length"); *out = {"length(" + a.s + ")", 2 * a.b}; return true;
            default: feature("fn:distance"); *out = {"distance(" + a.s + ", " + b.s + ")", 2 * (a.b + b.b)}; return true;
          }
        }
        const Ex a = gen(t, d), b = gen(t, d);
        switch (pick(0, continuous_ ? 2 : 4)) {
          case 0:
            feature("fn:normalize");
            *out = {"normalize(abs(" + a.s + ") + " + type_name(t) + "(0.25lf))", 1};
            return true;
          case 1:
            if (t != Ty::V3) return false;
            feature("fn:cross");
            *out = {"cross(" + a.s + ", " + b.s + ")", 2 * a.b * b.b};
            return true;
          case 2:
            // Constant normals included (seed 70272 once differed: docs/robustness.md, findings).
            feature("fn:reflect");
            *out = {"reflect(" + a.s + ", " + b.s + ")", a.b * (1 + 8 * b.b * b.b)};
            return true;
          case 3: {
            const Ex c = gen(t, d);
            feature("fn:faceforward");
            *out = {"faceforward(" + a.s + ", " + b.s + ", " + c.s + ")", a.b};
            return true;
          }
          default:
            // eta may be a constant (seed 4927 once differed: docs/robustness.md, findings).
            feature("fn:refract");
            *out = {"refract(" + a.s + ", normalize(abs(" + b.s + ") + " + type_name(t) + "(0.5lf)), clamp(" +
                        gen(Ty::D, d).s + ", 0.25lf, 2.0lf))", 4 * a.b + 4};
            return true;
        }
      }
      case 16: {  // matrix times vector
        if (t != Ty::V2 && t != Ty::V3) return false;
        const Ex m = gen_mat(t == Ty::V2 ? Ty::M2 : Ty::M3, d), v = gen(t, d);
        const bool left = chance(0.5);
        feature(left ? "op:mat*vec" : "op:vec*mat");
        *out = {"(" + (left ? m.s + " * " + v.s : v.s + " * " + m.s) + ")", n * m.b * v.b};
        return true;
      }
      case 17: {
        const Ex a = gen(t, d);
        const int e = pick(-4, 4);
        feature("fn:ldexp");
        *out = {"ldexp(" + a.s + ", " + (t == Ty::D ? std::to_string(e) : "ivec" + std::to_string(n) + "(" + std::to_string(e) + ")") + ")",
                a.b * 16};
        return true;
      }
      case 18: {
        if (t == Ty::D) {
          const Ex a = gen(Ty::D, d);
          feature("fn:packDouble2x32");
          *out = {"packDouble2x32(unpackDouble2x32(" + a.s + "))", a.b};
          return true;
        }
        const Ex m = gen_mat(t == Ty::V2 ? Ty::M2 : Ty::M3, d);
        if (t == Ty::V4) return false;
        feature("matrix:column");
        *out = {paren(m.s) + "[" + std::to_string(pick(0, n - 1)) + "]", m.b};
        return true;
      }
      default: {
        if (t != Ty::D) return false;
        const Ex m = gen_mat(chance(0.5) ? Ty::M2 : Ty::M3, d);
        feature("fn:determinant");
        *out = {"determinant(" + m.s + ")", 6 * m.b * m.b * m.b};
        return true;
      }
    }
  }
  static std::string paren(const std::string& s) { return s.front() == '(' ? s : "(" + s + ")"; }

  Ex gen_mat(Ty t, int depth) {
    const int n = size_of(t);
    const Ty col = vec_of(n);
    const int d = depth - 1;
    const auto vars = vars_where([&](const Var& v) { return v.ty == t && v.len == 0; });
    if (depth <= 0 || chance(0.2)) {
      if (!vars.empty() && chance(0.7)) {
        const Var* v = one_of(vars);
        return {v->name, v->b};
      }
      return literal_of(t);
    }
    int kind = pick(0, 7);
    if (continuous_ && (kind == 1 || kind == 6)) kind = 0;  // outerProduct and inverse: no bound in the planner
    switch (kind) {
      case 0: {
        std::string s = std::string(type_name(t)) + "(";
        double b = 1;
        for (int c = 0; c < n; ++c) {
          const Ex e = gen(col, d);
          s += (c ? ", " : "") + e.s;
          b = std::max(b, e.b);
        }
        feature("matrix:construct");
        return {s + ")", b};
      }
      case 1: {
        const Ex a = gen(col, d), b = gen(col, d);
        feature("fn:outerProduct");
        return capped({"outerProduct(" + a.s + ", " + b.s + ")", a.b * b.b});
      }
      case 2: {
        const Ex a = gen_mat(t, d);
        feature("fn:transpose");
        return {"transpose(" + a.s + ")", a.b};
      }
      case 3: {
        const Ex a = gen_mat(t, d), b = gen_mat(t, d);
        feature("op:mat*mat");
        return capped({"(" + a.s + " * " + b.s + ")", n * a.b * b.b});
      }
      case 4: {
        const Ex a = gen_mat(t, d), b = gen_mat(t, d);
        const bool add = chance(0.5);
        feature(add ? "op:mat+mat" : "fn:matrixCompMult");
        return capped({add ? "(" + a.s + " + " + b.s + ")" : "matrixCompMult(" + a.s + ", " + b.s + ")",
                     add ? a.b + b.b : a.b * b.b});
      }
      case 5: {
        const Ex a = gen_mat(t, d), s = gen(Ty::D, d);
        feature("op:mat*scalar");
        return capped({"(" + a.s + " * " + s.s + ")", a.b * s.b});
      }
      case 6: {
        // Diagonally dominant, so never singular while the bound holds.
        const Ex a = gen_mat(t, d);
        feature("fn:inverse");
        return {"inverse(" + a.s + " + " + type_name(t) + "(" + literal(std::ceil(2 * n * a.b + 1)) + "))", 1};
      }
      default: {
        if (vars.empty()) return literal_of(t);
        const Var* v = one_of(vars);
        return {v->name, v->b};
      }
    }
  }

  Ex gen_int(int depth) {
    const auto ints = vars_where([](const Var& v) { return v.ty == Ty::I && v.len == 0; });
    if (depth <= 0 || chance(0.4)) {
      if (!ints.empty() && chance(0.6)) return {one_of(ints)->name, 16};
      return literal_of(Ty::I);
    }
    if (chance(0.5)) {
      const Ex a = gen(Ty::D, depth - 1);
      feature("conv:int");
      return {"int(clamp(" + a.s + ", -64.0lf, 64.0lf))", 64};
    }
    const Ex a = gen_int(depth - 1), b = gen_int(depth - 1);
    feature("op:int");
    return {"(" + a.s + (chance(0.5) ? " + " : " - ") + b.s + ")", a.b + b.b};
  }

  Ex gen_bool(int depth) {
    const int d = depth - 1;
    switch (depth <= 0 ? pick(0, 1) : pick(0, 6)) {
      case 0: case 1: {
        static const std::vector<std::string> kCompare = {"<", "<=", ">", ">=", "==", "!="};
        const std::string op = one_of(kCompare);
        const Ex a = gen(Ty::D, d), b = gen(Ty::D, d);
        feature("cmp:" + op);
        return {"(" + a.s + " " + op + " " + b.s + ")", 1};
      }
      case 2: {
        const Ty v = vec_of(pick(2, 4));
        static const std::vector<std::string> kVec = {"lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual"};
        const std::string f = one_of(kVec);
        const Ex a = gen(v, d), b = gen(v, d);
        const bool any = chance(0.5);
        feature("fn:" + f);
        feature(any ? "fn:any" : "fn:all");
        return {std::string(any ? "any(" : "all(") + f + "(" + a.s + ", " + b.s + "))", 1};
      }
      case 3: {
        const Ex a = gen_bool(d), b = gen_bool(d);
        const bool both = chance(0.5);
        feature(both ? "op:&&" : "op:||");
        return {"(" + a.s + (both ? " && " : " || ") + b.s + ")", 1};
      }
      case 4: {
        const Ex a = gen_bool(d);
        feature("op:!");
        return {"!" + paren(a.s), 1};
      }
      case 5: {
        const Ex a = gen(Ty::D, d);
        const bool nan = chance(0.5);
        feature(nan ? "fn:isnan" : "fn:isinf");
        return {std::string(nan ? "isnan(" : "isinf(") + a.s + ")", 1};
      }
      default: {
        const Ex a = gen_int(d), b = gen_int(d);
        feature("cmp:int");
        return {"(" + a.s + " < " + b.s + ")", 1};
      }
    }
  }

  // ---- statements ----
  void line(const std::string& s) { text_ += std::string(static_cast<size_t>(2 * indent_), ' ') + s + "\n"; }
  int depth_for_expr() { return pick(1, 2); }
  Ty random_value_type() {
    const int r = pick(0, 9);
    return r < 4 ? Ty::D : r < 6 ? Ty::V2 : r < 7 ? Ty::V3 : r < 8 ? Ty::V4 : r < 9 ? Ty::M2 : Ty::M3;
  }

  void block(int statements, int nesting) {
    const size_t mark = scope_.size();
    for (int i = 0; i < statements; ++i) statement(nesting);
    scope_.resize(mark);
  }

  void braced(int statements, int nesting) {
    ++indent_;
    block(statements, nesting);
    --indent_;
  }

  std::vector<const Var*> writable(const std::function<bool(const Var&)>& keep) {
    return vars_where([&](const Var& v) { return v.writable && keep(v); });
  }

  void statement(int nesting) {
    comma_used_ = false;
    const int r = pick(0, continuous_ ? 7 : nesting > 1 ? 11 : 17);
    if (r <= 2) return declaration();
    if (r <= 5) return assignment();
    if (r == 6) return compound_assignment();
    if (r == 7) return increment();
    if (r == 8) return out_call();
    if (r == 9) return aggregate();
    if (r == 10) return modf_frexp();
    if (r == 11) return early_exit();
    if (r == 12 || r == 13) return if_statement(nesting);
    if (r == 14) return for_loop(nesting);
    if (r == 15) return while_loop(nesting);
    if (r == 16) return switch_statement(nesting);
    return do_loop(nesting);
  }

  void declaration() {
    const Ty t = random_value_type();
    const Ex e = gen(t, depth_for_expr());
    const std::string name = fresh("v");
    feature("stmt:declaration");
    line(std::string(type_name(t)) + " " + name + " = " + e.s + ";");
    scope_.push_back({name, t, std::max(1.0, e.b)});
  }

  void assignment() {
    const auto targets = writable([](const Var& v) { return v.len == 0 && !v.is_struct && (is_num(v.ty) || is_mat(v.ty)); });
    if (targets.empty()) return declaration();
    const Var v = *one_of(targets);
    const int n = size_of(v.ty);
    if (is_vec(v.ty) && chance(0.4)) {  // a swizzle or a component on the left
      std::string order = std::string("xyzw").substr(0, static_cast<size_t>(n));
      std::shuffle(order.begin(), order.end(), rng_);
      const int k = pick(1, n);
      const Ex e = gen(vec_of(k), depth_for_expr());
      feature(k == 1 ? "stmt:assign-component" : "swizzle:write");
      const std::string lhs = k == 1 && chance(0.5) ? v.name + "[" + std::to_string(std::string("xyzw").find(order[0])) + "]"
                                                    : v.name + "." + order.substr(0, static_cast<size_t>(k));
      line(lhs + " = " + e.s + ";");
      grow(v.name, e.b);
      return;
    }
    if (is_mat(v.ty) && chance(0.5)) {
      const Ex e = gen(vec_of(n), depth_for_expr());
      feature("matrix:assign-column");
      line(v.name + "[" + std::to_string(pick(0, n - 1)) + "] = " + e.s + ";");
      grow(v.name, e.b);
      return;
    }
    const Ex e = gen(v.ty, depth_for_expr());
    feature("stmt:assign");
    line(v.name + " = " + e.s + ";");
    grow(v.name, e.b);
  }

  void compound_assignment() {
    const auto targets = writable([](const Var& v) { return v.len == 0 && !v.is_struct && is_num(v.ty); });
    if (targets.empty()) return declaration();
    const Var v = *one_of(targets);
    const Ex e = scalar_or_same(v.ty, depth_for_expr());
    switch (pick(0, 3)) {
      case 0: feature("op:+="); line(v.name + " += " + e.s + ";"); grow(v.name, v.b + e.b); break;
      case 1: feature("op:-="); line(v.name + " -= " + e.s + ";"); grow(v.name, v.b + e.b); break;
      case 2:
        feature("op:*=");
        if (v.b * e.b > kWrap) {
          line(v.name + " *= clamp(" + e.s + ", -2.0lf, 2.0lf);");
          grow(v.name, 2 * v.b);
        } else {
          line(v.name + " *= " + e.s + ";");
          grow(v.name, v.b * e.b);
        }
        break;
      default: feature("op:/="); line(v.name + " /= (1.0lf + abs(" + e.s + "));"); break;
    }
  }

  void increment() {
    const auto targets = writable([](const Var& v) { return v.len == 0 && !v.is_struct && is_num(v.ty); });
    if (targets.empty()) return declaration();
    const Var& v = *one_of(targets);
    static const std::vector<std::string> kForms = {"++", "--"};
    const std::string op = one_of(kForms);
    feature("op:" + op);
    line(chance(0.5) ? v.name + op + ";" : op + v.name + ";");
    grow(v.name, v.b + 1);
  }

  // A call of a function with out/inout parameters, at statement level: its arguments are distinct
  // variables (or, for a double parameter, a component of a vector) that nothing else reads.
  void out_call() {
    std::vector<const Func*> impure;
    for (const Func& f : funcs_)
      if (!f.pure()) impure.push_back(&f);
    if (impure.empty()) return assignment();
    const Func& f = *one_of(impure);
    std::vector<std::string> used;
    std::string args;
    for (size_t i = 0; i < f.params.size(); ++i) {
      const auto& [qualifier, type] = f.params[i];
      std::string arg;
      if (qualifier == "in") {
        arg = gen(type, 1).s;
      } else {
        auto candidates = writable([&, &type = type](const Var& v) {
          return v.len == 0 && !v.is_struct && std::find(used.begin(), used.end(), v.name) == used.end() &&
                 (v.ty == type || (type == Ty::D && is_vec(v.ty)));
        });
        if (candidates.empty()) {
          const std::string name = fresh("v");
          const Ex init = literal_of(type);
          line(std::string(type_name(type)) + " " + name + " = " + init.s + ";");
          scope_.push_back({name, type, init.b});
          arg = name;
        } else {
          const Var* v = one_of(candidates);
          arg = v->ty == type ? v->name : v->name + "." + "xyzw"[pick(0, size_of(v->ty) - 1)];
          if (v->ty != type) feature("call:component-out-argument");
          grow(v->name, 1e4);
        }
        used.push_back(arg.substr(0, arg.find('.')));
      }
      args += (i ? ", " : "") + arg;
    }
    // The result goes to a new variable, so it is not one of the arguments.
    const std::string name = fresh("v");
    feature("call:out-arguments");
    line(std::string(type_name(f.ret)) + " " + name + " = " + f.name + "(" + args + ");");
    scope_.push_back({name, f.ret, 1e4});
  }

  void aggregate() {
    if (has_struct_ && chance(0.5)) {
      const Ex a = gen(Ty::D, 2), b = gen(struct_vec_, 2);
      const std::string name = fresh("s");
      if (chance(0.5)) {
        feature("struct:local");
        line("S " + name + " = S(" + a.s + ", " + b.s + ");");
        scope_.push_back({name, Ty::D, std::max(a.b, b.b), true, 0, true});
        if (chance(0.5)) {
          const Ex c = gen(Ty::D, 2);
          feature("struct:field-write");
          line(name + ".a = " + c.s + ";");
          grow(name, c.b);
        }
      } else {
        const Ex c = gen(Ty::D, 2), e = gen(struct_vec_, 2);
        feature("struct:array");
        line("S " + name + "[2] = S[2](S(" + a.s + ", " + b.s + "), S(" + c.s + ", " + e.s + "));");
        scope_.push_back({name, Ty::D, std::max({a.b, b.b, c.b, e.b}), true, 2, true});
      }
      return;
    }
    const Ty t = vec_of(pick(1, 3));
    const int len = pick(2, 4);
    std::string s = std::string(type_name(t)) + "[" + std::to_string(len) + "](";
    double b = 1;
    for (int i = 0; i < len; ++i) {
      const Ex e = gen(t, 1);
      s += (i ? ", " : "") + e.s;
      b = std::max(b, e.b);
    }
    const std::string name = fresh("a");
    feature("array:local");
    line(std::string(type_name(t)) + " " + name + "[" + std::to_string(len) + "] = " + s + ");");
    scope_.push_back({name, t, b, true, len});
    if (chance(0.5)) {
      const Ex e = gen(t, 2);
      feature("array:element-write");
      line(name + "[" + std::to_string(pick(0, len - 1)) + "] = " + e.s + ";");
      grow(name, e.b);
    }
  }

  void modf_frexp() {
    const Ty t = vec_of(pick(1, 4));
    const Ex x = gen(t, 2);
    const std::string result = fresh("v"), part = fresh("q");
    if (chance(0.5)) {
      feature("fn:modf");
      line(std::string(type_name(t)) + " " + part + ";");
      line(std::string(type_name(t)) + " " + result + " = modf(" + x.s + ", " + part + ");");
      scope_.push_back({part, t, x.b});
    } else {
      feature("fn:frexp");
      line((t == Ty::D ? std::string("int") : "ivec" + std::to_string(size_of(t))) + " " + part + ";");
      line(std::string(type_name(t)) + " " + result + " = frexp(" + x.s + ", " + part + ");");
      if (t == Ty::D) scope_.push_back({part, Ty::I, 64, false});
    }
    scope_.push_back({result, t, std::max(1.0, x.b)});
  }

  void early_exit() {
    const Ex c = gen_bool(2);
    if (in_function_) {
      const Ex e = gen(return_type_, 2);
      feature("stmt:early-return");
      line("if " + paren(c.s) + " return " + e.s + ";");
      return;
    }
    if (stage_ == "frag" && chance(0.3)) {
      feature("stmt:discard");
      line("if " + paren(c.s) + " discard;");
      return;
    }
    feature("stmt:early-return-main");
    line("if " + paren(c.s) + " {");
    ++indent_;
    write_outputs();
    if (stage_ == "geom") line("EmitVertex();");
    line("return;");
    --indent_;
    line("}");
  }

  void if_statement(int nesting) {
    const Ex c = gen_bool(2);
    feature("stmt:if");
    line("if " + paren(c.s) + " {");
    braced(pick(1, 3), nesting + 1);
    if (chance(0.5)) {
      feature("stmt:else");
      line("} else {");
      braced(pick(1, 3), nesting + 1);
    }
    line("}");
  }

  void loop_control() {
    if (!chance(0.4)) return;
    const Ex c = gen_bool(1);
    const bool brk = chance(0.5);
    feature(brk ? "stmt:break" : "stmt:continue");
    line("if " + paren(c.s) + (brk ? " break;" : " continue;"));
  }

  void for_loop(int nesting) {
    const std::string k = fresh("k");
    feature("stmt:for");
    line("for (int " + k + " = 0; " + k + " < " + std::to_string(pick(1, 4)) + "; ++" + k + ") {");
    scope_.push_back({k, Ty::I, 4, false});
    ++indent_;
    loop_control();
    block(pick(1, 3), nesting + 1);
    --indent_;
    scope_.pop_back();
    line("}");
  }

  void while_loop(int nesting) {
    const std::string w = fresh("w");
    feature("stmt:while");
    line("int " + w + " = 0;");
    line("while (" + w + " < " + std::to_string(pick(1, 3)) + ") {");
    ++indent_;
    line(w + "++;");  // first, so a continue cannot skip it
    loop_control();
    block(pick(1, 3), nesting + 1);
    --indent_;
    line("}");
  }

  void do_loop(int nesting) {
    const std::string w = fresh("w");
    feature("stmt:do");
    line("int " + w + " = 0;");
    line("do {");
    ++indent_;
    line(w + "++;");
    loop_control();
    block(pick(1, 3), nesting + 1);
    --indent_;
    line("} while (" + w + " < " + std::to_string(pick(1, 3)) + ");");
  }

  void switch_statement(int nesting) {
    const Ex selector = gen_int(2);
    feature("stmt:switch");
    line("switch (" + selector.s + " & 3) {");
    ++indent_;
    for (const char* label : {"case 0:", "case 1:", "default:"}) {
      line(label);
      if (std::string(label) == "case 1:" && chance(0.3)) {
        feature("stmt:fallthrough");
        continue;
      }
      line("{");
      braced(pick(1, 2), nesting + 1);
      line("}");
      line("break;");
    }
    --indent_;
    line("}");
  }

  void write_outputs() {
    for (const auto& [name, type] : outputs_) {
      const Ex e = gen(type, 2);
      if (stage_ == "comp") {
        line(name + "[gid] = " + e.s + ";");
      } else if (stage_ == "tesc") {
        line(name + "[gl_InvocationID] = " + e.s + ";");
      } else if (stage_ != "frag") {
        line(name + " = " + e.s + ";");
      } else {
        // hi = float(t), lo = float(t - hi): both exact functions of the double t.
        const std::string t = fresh("t");
        line("{");
        line("  " + std::string(type_name(type)) + " " + t + " = " + e.s + ";");
        if (type == Ty::D)
          line("  " + name + " = vec4(float(" + t + "), float(" + t + " - double(float(" + t + "))), 0.0, 1.0);");
        else
          line("  " + name + " = vec4(float(" + t + ".x), float(" + t + ".x - double(float(" + t + ".x))), float(" + t +
               ".y), float(" + t + ".y - double(float(" + t + ".y))));");
        line("}");
      }
    }
  }

  void function() {
    Func f;
    f.name = fresh("f");
    f.ret = vec_of(pick(1, 4));
    const int params = pick(1, 3);
    const bool pure = chance(0.5);
    for (int i = 0; i < params; ++i) {
      const Ty t = vec_of(pick(1, 4));
      std::string q = "in";
      if (!pure && i > 0) q = chance(0.5) ? "inout" : "out";
      f.params.push_back({q, t});
    }
    feature(pure ? "function:pure" : "function:out-parameters");
    std::string head = std::string(type_name(f.ret)) + " " + f.name + "(";
    const size_t mark = scope_.size();
    std::vector<std::string> outs;
    for (size_t i = 0; i < f.params.size(); ++i) {
      const std::string name = "p" + std::to_string(i);
      head += (i ? ", " : "") + (f.params[i].first == "in" ? "" : f.params[i].first + " ") + type_name(f.params[i].second) + " " + name;
      // An out parameter holds no value until it is written: it joins the scope after that.
      if (f.params[i].first == "out") outs.push_back(name);
      else scope_.push_back({name, f.params[i].second, 16, true});
    }
    line(head + ") {");
    in_function_ = true;
    return_type_ = f.ret;
    ++indent_;
    line("double local_scratch;");
    // Globals a function could write are left alone: a call's effects then stay in its arguments.
    for (Var& v : scope_)
      if (v.name[0] == 'g') v.writable = false;
    for (const std::string& o : outs) {
      const Ty t = f.params[static_cast<size_t>(std::stoi(o.substr(1)))].second;
      const Ex e = gen(t, 2);
      line(o + " = " + e.s + ";");
      scope_.push_back({o, t, std::max(1.0, e.b), true});
    }
    block(pick(1, 3), 1);
    line("return " + gen(f.ret, 2).s + ";");
    --indent_;
    line("}");
    for (Var& v : scope_)
      if (v.name[0] == 'g') v.writable = true;
    in_function_ = false;
    scope_.resize(mark);
    funcs_.push_back(f);
  }

  void main_function() {
    line("void main() {");
    ++indent_;
    if (stage_ == "comp") line("uint gid = gl_GlobalInvocationID.x;");
    if (stage_ == "vert" || stage_ == "geom" || stage_ == "tese") line("gl_Position = vec4(0.0, 0.0, 0.0, 1.0);");
    if (stage_ == "tese") line("dvec3 tc = dvec3(gl_TessCoord);");
    for (const Var& in : inputs_) {
      const std::string name = "x" + in.name.substr(2);
      const std::string n = in.name;
      line(std::string(type_name(in.ty)) + " " + name + " = " +
           (stage_ == "comp"   ? n + "[gid];"
            : stage_ == "tese" ? n + "[0] * tc.x + " + n + "[1] * tc.y + " + n + "[2] * tc.z;"
            : per_vertex()     ? n + "[0];"
                               : n + ";"));
      scope_.push_back({name, in.ty, 4});
    }
    // Every block member is read once, so none is inactive (verify refuses a range for a uniform the
    // compiler removed).
    for (const Var& m : block_members_) {
      const std::string name = "y" + m.name;
      line(std::string(type_name(m.ty)) + " " + name + " = " + m.name + ";");
      scope_.push_back({name, m.ty, m.b});
    }
    block(pick(3, 8), 0);
    write_outputs();
    if (stage_ == "geom") line("EmitVertex();");
    --indent_;
    line("}");
  }

  std::mt19937_64 rng_;
  Program program_;
  std::string text_;
  std::vector<Var> scope_, inputs_, block_members_;
  std::vector<std::pair<std::string, Ty>> outputs_;
  std::vector<Func> funcs_;
  int counter_ = 0, indent_ = 0;
  std::string stage_ = "comp";
  bool per_vertex() const { return stage_ == "geom" || stage_ == "tesc" || stage_ == "tese"; }
  bool allow_rounding_ = false, has_struct_ = false, comma_used_ = false, in_function_ = false;
  bool continuous_ = false;  // no jump anywhere: the planner's bound applies (the bound oracle)
  Ty struct_vec_ = Ty::V2, return_type_ = Ty::D;
};

}  // namespace

Program generate(uint64_t seed) { return Generator(seed).run(); }

const std::vector<std::string>& all_features() {
  static const std::vector<std::string> list = {
      "op:neg", "op:+", "op:-", "op:*", "op:/", "op:?:", "op:,", "op:+=", "op:-=", "op:*=", "op:/=", "op:++", "op:--",
      "op:&&", "op:||", "op:!", "op:int", "op:mat*vec", "op:vec*mat", "op:mat*mat", "op:mat+mat", "op:mat*scalar",
      "cmp:<", "cmp:<=", "cmp:>", "cmp:>=", "cmp:==", "cmp:!=", "cmp:int",
      "fn:abs", "fn:sign", "fn:floor", "fn:ceil", "fn:fract", "fn:sqrt", "fn:inversesqrt", "fn:trunc", "fn:round",
      "fn:roundEven", "fn:min", "fn:max", "fn:mod", "fn:step", "fn:fma", "fn:mix", "fn:mix(bool)", "fn:clamp",
      "fn:smoothstep", "fn:dot", "fn:length", "fn:distance", "fn:normalize", "fn:cross", "fn:reflect",
      "fn:faceforward", "fn:refract", "fn:ldexp", "fn:frexp", "fn:modf", "fn:packDouble2x32", "fn:determinant",
      "fn:inverse", "fn:transpose", "fn:outerProduct", "fn:matrixCompMult", "fn:lessThan", "fn:lessThanEqual",
      "fn:greaterThan", "fn:greaterThanEqual", "fn:equal", "fn:notEqual", "fn:any", "fn:all", "fn:isnan", "fn:isinf",
      "conv:float", "conv:int", "conv:from-int", "conv:vec", "swizzle:read", "swizzle:write", "matrix:construct",
      "matrix:column", "matrix:assign-column", "stmt:declaration", "stmt:assign", "stmt:assign-component", "stmt:if",
      "stmt:else", "stmt:for", "stmt:while", "stmt:do", "stmt:switch", "stmt:fallthrough", "stmt:break",
      "stmt:continue", "stmt:early-return", "stmt:early-return-main", "call:expression", "call:out-arguments",
      "call:component-out-argument", "function:pure", "function:out-parameters", "struct", "struct:local",
      "struct:field-write", "struct:array", "array:local", "array:element-write", "global:const",
      "global:initialised", "global:uniform-initialised", "layout:std140", "stage:comp", "stage:vert", "stage:frag", "stage:geom", "stage:tesc", "stage:tese",
      "stmt:discard", "block:uniform"};
  return list;
}

bool reads_a_variable(const std::string& s) {
  const auto word = [&](size_t k) { return k < s.size() && (std::isalnum(static_cast<unsigned char>(s[k])) || s[k] == '_'); };
  for (size_t i = 0; i < s.size();) {
    if (!word(i)) {
      ++i;
      continue;
    }
    const size_t start = i;
    while (word(i)) ++i;
    const bool literal = std::isdigit(static_cast<unsigned char>(s[start]));
    const bool swizzle = start > 0 && s[start - 1] == '.';
    const bool call = i < s.size() && s[i] == '(';
    const std::string name = s.substr(start, i - start);
    if (!literal && !swizzle && !call && name != "true" && name != "false") return true;
  }
  return false;
}

bool uses_native_non_ieee(const Program& p) {
  // Rounding to an integer: lavapipe's fp64 trunc/round/roundEven are not IEEE for large values
  // (docs/extremes.md). smoothstep, reflect, refract and mix are checked: since native's built-ins
  // are NoContraction too (ComputeJob::strict_fp64), lavapipe no longer reassociates or folds their
  // expansions around constants or aliased operands (tests/difftest/cases).
  return p.features.count("fn:trunc") || p.features.count("fn:round") || p.features.count("fn:roundEven");
}

}  // namespace doublet::difftest
