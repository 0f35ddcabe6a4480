// Host-side packing driven by the manifest that `doublet lower --manifest` writes: which
// lowered variables a double became (X -> X_hi, X_lo), their float types and locations.
// With it, host code fills uniforms, vertex buffers and float-float arrays for the
// lowered shader without hard-coding the suffixes or the split.
//
//   auto m = doublet::pack::parse_manifest(json);                 // std::optional<Manifest>
//   for (auto& u : doublet::pack::uniform_values(*m->find("eye"), eye_xyz))
//     glUniform3fv(glGetUniformLocation(prog, u.name.c_str()), 1, u.value.data());
//
//   auto layout = doublet::pack::vertex_layout(*m, {"position", "uv"});
//   std::vector<float> vbo;
//   doublet::pack::pack_vertices(layout, {{"position", positions}, {"uv", uvs}}, vbo);
//   for (auto& s : layout.slots)  // location from the manifest, else glGetAttribLocation
//     glVertexAttribPointer(loc(s), s.components, GL_FLOAT, GL_FALSE,
//                           layout.stride_floats * 4, (void*)(s.offset_floats * 4));
//
// Mode exact (`--mode exact`, manifest "encoding": "binary64-words"): a double is the two uint
// words of its binary64 pattern, low word first, so the host's raw doubles are the data:
//   for (auto& u : doublet::pack::uniform_words(*m->find("eye"), eye_xyz))   // dvec3 -> eye_xy, eye_z
//     glUniform4uiv / glUniform2uiv (by u.components)(location(u.name), u.count, u.words.data());
//   for (auto& a : doublet::pack::word_attributes(*m->find("position"), offsetof(Vertex, position)))
//     glVertexAttribIPointer(loc(a), a.components, GL_UNSIGNED_INT, sizeof(Vertex), (void*)a.offset_bytes);
//   uniform dmat4 M -> uniform_words(*m->find("M"), column_major_doubles): one uvec4[8], glUniform4uiv
// and a uniform/storage block takes the std140/std430 bytes of its doubles unchanged (dmat members
// too: column-major, std140/std430 column strides).
//
// Header-only, C++20, standard library only (the manifest parser is a small JSON reader).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "doublet/split.hpp"

namespace doublet::pack {

// One interface variable of the original shader and what it became (see the manifest).
struct Variable {
  std::string name;          // as written in the shader, e.g. "position"
  std::string storage;       // "in", "out", "uniform", "attribute", "varying", "buffer"
  std::string type;          // original type, e.g. "dvec3"
  bool split = false;        // true: lowered_names are {hi, lo}
  std::string lowered_type;  // e.g. "vec3"
  std::vector<std::string> lowered_names;
  std::vector<int> locations;  // explicit locations of lowered_names, when the shader has them
  std::string encoding;        // "binary64-words" (mode exact), else empty
  std::vector<std::string> lowered_types;  // mode exact: one per lowered name ("uvec4", "uvec2[3]")
  // A uniform declared with an initializer: its value, every component (the manifest's "default").
  // GLSL ES has no uniform initializers, so the host sets it: uniform_values(v, v.default_value).
  std::vector<double> default_value;

  // Floats per lowered variable: 1 for float, N for vecN; 0 for other types.
  int components() const {
    if (lowered_type == "float") return 1;
    if (lowered_type.size() == 4 && lowered_type.starts_with("vec") && lowered_type[3] >= '2' &&
        lowered_type[3] <= '4')
      return lowered_type[3] - '0';
    return 0;
  }
  int location(std::size_t part) const { return part < locations.size() ? locations[part] : -1; }
};

struct Manifest {
  std::string stage;   // "vert", "frag", "comp"
  std::string target;  // "es300", ...
  std::vector<Variable> variables;
  std::string guard_kind;     // "precise", "uniform" or "none"
  std::string guard_uniform;  // for "uniform": leave it at GL's default 0

  const Variable* find(std::string_view name) const {
    for (const Variable& v : variables)
      if (v.name == name) return &v;
    return nullptr;
  }
};

namespace detail {

// Just enough JSON for manifests: objects, arrays, strings, numbers, true/false/null.
struct Json {
  enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<Json> items;         // Array elements, or Object values
  std::vector<std::string> keys;   // Object keys, parallel to items

  const Json* get(std::string_view key) const {
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (keys[i] == key) return &items[i];
    return nullptr;
  }
  std::string string_at(std::string_view key) const {
    const Json* j = get(key);
    return j && j->kind == Kind::String ? j->string : std::string();
  }
};

class JsonReader {
 public:
  explicit JsonReader(std::string_view text) : s_(text) {}

  bool parse(Json& out, std::string& error) {
    if (!value(out, 0) || (skip_space(), pos_ != s_.size())) {
      error = "manifest: invalid JSON near offset " + std::to_string(pos_);
      return false;
    }
    return true;
  }

 private:
  void skip_space() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\n' || s_[pos_] == '\r' || s_[pos_] == '\t')) ++pos_;
  }
  bool eat(char c) {
    skip_space();
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  bool literal(std::string_view word) {
    if (s_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }
  static void append_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  bool string(std::string& out) {
    if (!eat('"')) return false;
    while (pos_ < s_.size() && s_[pos_] != '"') {
      char c = s_[pos_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= s_.size()) return false;
      char e = s_[pos_++];
      switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          if (pos_ + 4 > s_.size()) return false;
          unsigned cp = 0;
          for (int i = 0; i < 4; ++i) {
            char h = s_[pos_++];
            cp = cp * 16 + (h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : 99);
            if (cp > 0xFFFF) return false;
          }
          append_utf8(out, cp);  // names are ASCII; surrogate pairs are not needed here
          break;
        }
        default: out += e;  // \" \\ \/
      }
    }
    return pos_ < s_.size() && s_[pos_++] == '"';
  }
  bool value(Json& out, int depth) {
    if (depth > 32) return false;
    skip_space();
    if (pos_ >= s_.size()) return false;
    char c = s_[pos_];
    if (c == '{') {
      ++pos_;
      out.kind = Json::Kind::Object;
      if (eat('}')) return true;
      do {
        std::string key;
        Json item;
        if (!string(key) || !eat(':') || !value(item, depth + 1)) return false;
        out.keys.push_back(std::move(key));
        out.items.push_back(std::move(item));
      } while (eat(','));
      return eat('}');
    }
    if (c == '[') {
      ++pos_;
      out.kind = Json::Kind::Array;
      if (eat(']')) return true;
      do {
        Json item;
        if (!value(item, depth + 1)) return false;
        out.items.push_back(std::move(item));
      } while (eat(','));
      return eat(']');
    }
    if (c == '"') return out.kind = Json::Kind::String, string(out.string);
    if (literal("true")) return out.kind = Json::Kind::Bool, out.boolean = true, true;
    if (literal("false")) return out.kind = Json::Kind::Bool, true;
    if (literal("null")) return true;
    std::size_t start = pos_;
    while (pos_ < s_.size() && (std::string_view("+-.eE0123456789").find(s_[pos_]) != std::string_view::npos)) ++pos_;
    if (pos_ == start) return false;
    try {
      out.number = std::stod(std::string(s_.substr(start, pos_ - start)));
    } catch (...) {
      return false;
    }
    out.kind = Json::Kind::Number;
    return true;
  }

  std::string_view s_;
  std::size_t pos_ = 0;
};

}  // namespace detail

// Reads the manifest JSON. On malformed input returns std::nullopt and, if `error` is
// given, says why.
inline std::optional<Manifest> parse_manifest(std::string_view json, std::string* error = nullptr) {
  using detail::Json;
  Json root;
  std::string why;
  auto fail = [&](std::string message) -> std::optional<Manifest> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  if (!detail::JsonReader(json).parse(root, why)) return fail(why);
  if (root.kind != Json::Kind::Object) return fail("manifest: not a JSON object");
  Manifest m;
  m.stage = root.string_at("stage");
  m.target = root.string_at("target");
  if (const Json* guard = root.get("guard"); guard && guard->kind == Json::Kind::Object) {
    m.guard_kind = guard->string_at("kind");
    m.guard_uniform = guard->string_at("uniform");
  }
  const Json* vars = root.get("variables");
  if (!vars || vars->kind != Json::Kind::Array) return fail("manifest: no \"variables\" array");
  for (const Json& e : vars->items) {
    if (e.kind != Json::Kind::Object) return fail("manifest: a variable is not an object");
    Variable v;
    v.name = e.string_at("name");
    v.storage = e.string_at("storage");
    v.type = e.string_at("type");
    v.lowered_type = e.string_at("lowered_type");
    if (const Json* s = e.get("split")) v.split = s->kind == Json::Kind::Bool && s->boolean;
    if (const Json* names = e.get("lowered_names"); names && names->kind == Json::Kind::Array)
      for (const Json& n : names->items) v.lowered_names.push_back(n.string);
    if (const Json* locs = e.get("locations"); locs && locs->kind == Json::Kind::Array)
      for (const Json& n : locs->items) v.locations.push_back(static_cast<int>(n.number));
    v.encoding = e.string_at("encoding");
    if (const Json* d = e.get("default"); d && d->kind == Json::Kind::Array)
      for (const Json& x : d->items) v.default_value.push_back(x.number);
    if (const Json* types = e.get("lowered_types"); types && types->kind == Json::Kind::Array)
      for (const Json& t : types->items) v.lowered_types.push_back(t.string);
    const bool words = v.encoding == "binary64-words";
    if (words && !v.lowered_types.empty() && v.lowered_types.size() != v.lowered_names.size())
      return fail("manifest: variable '" + v.name + "' has " + std::to_string(v.lowered_types.size()) +
                  " lowered_types for " + std::to_string(v.lowered_names.size()) + " lowered_names");
    if (v.name.empty() || v.lowered_names.empty() || (v.split && !words && v.lowered_names.size() != 2))
      return fail("manifest: variable '" + v.name + "' lacks a name or lowered names");
    m.variables.push_back(std::move(v));
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// Uniforms

// The value to give one lowered uniform: value[0..components) are meaningful.
struct LoweredUniform {
  std::string name;
  int components = 0;
  std::array<float, 4> value{};
};

// For `uniform dvec3 eye` (split into eye_hi/eye_lo): {eye_hi, hi parts}, {eye_lo, lo
// parts}. For a variable that was not split: one entry with the value rounded to float.
// `value` holds one double per component; on a size mismatch the result is empty.
inline std::vector<LoweredUniform> uniform_values(const Variable& v, std::span<const double> value) {
  const int n = v.components();
  if (n == 0 || value.size() != static_cast<std::size_t>(n)) return {};
  std::vector<LoweredUniform> out;
  for (const std::string& name : v.lowered_names) out.push_back({name, n, {}});
  for (int c = 0; c < n; ++c) {
    FloatPair p = split(value[static_cast<std::size_t>(c)]);
    out[0].value[static_cast<std::size_t>(c)] = p.hi;
    if (v.split) out[1].value[static_cast<std::size_t>(c)] = p.lo;
  }
  return out;
}
inline std::vector<LoweredUniform> uniform_values(const Variable& v, std::initializer_list<double> value) {
  return uniform_values(v, std::span<const double>(value.begin(), value.size()));
}

// ---------------------------------------------------------------------------------------
// Vertex attributes, interleaved in one buffer

enum class Part { Whole, Hi, Lo };

struct AttributeSlot {
  std::string name;        // the lowered attribute, e.g. "position_hi"
  std::string variable;    // the original one, e.g. "position"
  Part part = Part::Whole;
  int location = -1;       // from the manifest; -1: ask GL (glGetAttribLocation)
  int components = 0;      // floats (1..4)
  std::size_t offset_floats = 0;
};

struct VertexLayout {
  std::vector<AttributeSlot> slots;
  std::size_t stride_floats = 0;  // floats per vertex
  std::string error;              // non-empty: a named input is not a float/vecN input
  bool ok() const { return error.empty(); }
};

// Interleaved layout of the named vertex inputs, in the order given; a split input takes
// two consecutive slots (hi then lo).
inline VertexLayout vertex_layout(const Manifest& m, std::span<const std::string_view> inputs) {
  VertexLayout layout;
  for (std::string_view name : inputs) {
    const Variable* v = m.find(name);
    if (!v || (v->storage != "in" && v->storage != "attribute")) {
      layout.error = "'" + std::string(name) + "' is not a vertex input in the manifest";
      return layout;
    }
    const int n = v->components();
    if (n == 0) {
      layout.error = "'" + std::string(name) + "' has type " + v->lowered_type + ", not float or vecN";
      return layout;
    }
    for (std::size_t part = 0; part < v->lowered_names.size(); ++part) {
      Part p = !v->split ? Part::Whole : part == 0 ? Part::Hi : Part::Lo;
      layout.slots.push_back({v->lowered_names[part], v->name, p, v->location(part), n, layout.stride_floats});
      layout.stride_floats += static_cast<std::size_t>(n);
    }
  }
  return layout;
}
inline VertexLayout vertex_layout(const Manifest& m, std::initializer_list<std::string_view> inputs) {
  return vertex_layout(m, std::span<const std::string_view>(inputs.begin(), inputs.size()));
}

// The doubles of one original input: components × vertex count values, vertex-major.
struct AttributeData {
  std::string_view variable;
  std::span<const double> values;
};

// Fills `out` (resized to vertex count × stride) following `layout`. Every input of the
// layout needs data with the same vertex count; returns false (and says why) otherwise.
inline bool pack_vertices(const VertexLayout& layout, std::span<const AttributeData> data, std::vector<float>& out,
                          std::string* error = nullptr) {
  auto fail = [&](std::string message) {
    if (error) *error = std::move(message);
    return false;
  };
  if (!layout.ok()) return fail(layout.error);
  std::size_t vertices = 0;
  std::vector<const AttributeData*> source(layout.slots.size(), nullptr);
  for (std::size_t s = 0; s < layout.slots.size(); ++s) {
    const AttributeSlot& slot = layout.slots[s];
    for (const AttributeData& d : data)
      if (d.variable == slot.variable) source[s] = &d;
    if (!source[s]) return fail("no data for vertex input '" + slot.variable + "'");
    const std::size_t n = static_cast<std::size_t>(slot.components);
    if (source[s]->values.size() % n != 0)
      return fail("data for '" + slot.variable + "' is not a whole number of vec" + std::to_string(n));
    std::size_t count = source[s]->values.size() / n;
    if (s > 0 && count != vertices) return fail("vertex inputs have different vertex counts");
    vertices = count;
  }
  out.assign(vertices * layout.stride_floats, 0.0f);
  for (std::size_t s = 0; s < layout.slots.size(); ++s) {
    const AttributeSlot& slot = layout.slots[s];
    const std::size_t n = static_cast<std::size_t>(slot.components);
    const double* src = source[s]->values.data();
    float* dst = out.data() + slot.offset_floats;
    for (std::size_t v = 0; v < vertices; ++v, dst += layout.stride_floats)
      for (std::size_t c = 0; c < n; ++c) {
        FloatPair p = split(src[v * n + c]);
        dst[c] = slot.part == Part::Lo ? p.lo : p.hi;  // Whole: the float nearest the double
      }
  }
  return true;
}
inline bool pack_vertices(const VertexLayout& layout, std::initializer_list<AttributeData> data, std::vector<float>& out,
                          std::string* error = nullptr) {
  return pack_vertices(layout, std::span<const AttributeData>(data.begin(), data.size()), out, error);
}

// ---------------------------------------------------------------------------------------
// Mode exact: binary64 words

namespace detail {
// Elements of an array type spelled "T[N]" (1 when not an array, 0 when unsized).
inline std::size_t array_elements(std::string_view type) {
  const std::size_t open = type.find('[');
  if (open == std::string_view::npos) return 1;
  std::size_t n = 0;
  for (std::size_t i = open + 1; i < type.size() && type[i] >= '0' && type[i] <= '9'; ++i) n = n * 10 + (type[i] - '0');
  return n;
}
// uints per element of "uvec2"/"uvec4" (arrays too); 0 otherwise.
inline int uint_components(std::string_view type) {
  if (type.starts_with("uvec2")) return 2;
  if (type.starts_with("uvec4")) return 4;
  return 0;
}
// doubles per element of "double"/"dvecN" (arrays too); 0 otherwise.
inline int double_components(std::string_view type) {
  if (type.starts_with("double")) return 1;
  if (type.size() >= 5 && type.starts_with("dvec") && type[4] >= '2' && type[4] <= '4') return type[4] - '0';
  return 0;
}
// doubles per element of "dmatC"/"dmatCxR" (arrays too: "dmat4[2]"); 0 otherwise.
inline int matrix_doubles(std::string_view type) {
  if (type.size() < 5 || !type.starts_with("dmat") || type[4] < '2' || type[4] > '4') return 0;
  const int cols = type[4] - '0';
  if (type.size() >= 7 && type[5] == 'x' && type[6] >= '2' && type[6] <= '4') return cols * (type[6] - '0');
  return cols * cols;
}
}  // namespace detail

inline bool is_binary64_words(const Variable& v) { return v.encoding == "binary64-words"; }

// The uints of one lowered uniform: glUniform{components}uiv(location(name), count, words.data()).
struct UniformWords {
  std::string name;
  int components = 0;  // 2 or 4
  int count = 0;       // array elements (1 for a plain variable)
  std::vector<std::uint32_t> words;  // count × components
};

// The words of `uniform double/dvecN X[...]` lowered by mode exact, from its value as the host holds
// it (elements × components doubles, element after element). For double and dvec2 the words are the
// value's bytes as they are; dvec3/dvec4 split each element into X_xy (first two components) and
// X_z/X_zw. A dmatCxR[n] takes its C*R*n doubles column-major, matrix after matrix (one uvec4 array
// in the host's bytes). Empty when `v` is not a mode-exact double uniform or the size does not match.
inline std::vector<UniformWords> uniform_words(const Variable& v, std::span<const double> value) {
  if (const int m = detail::matrix_doubles(v.type)) {
    // `uniform dmatCxR M[n]` -> `uvec4 M[ceil(n*C*R/2)]`: the column-major doubles' words as they are
    // (glUniform4uiv(location(M), count, words)); an odd number of doubles (dmat3) pads 2 zero words.
    const std::size_t doubles = detail::array_elements(v.type) * static_cast<std::size_t>(m);
    if (!is_binary64_words(v) || doubles == 0 || value.size() != doubles || v.lowered_names.size() != 1 ||
        v.lowered_types.size() != 1 || detail::uint_components(v.lowered_types[0]) != 4 ||
        detail::array_elements(v.lowered_types[0]) != (doubles + 1) / 2)
      return {};
    UniformWords u{v.lowered_names[0], 4, static_cast<int>((doubles + 1) / 2), {}};
    for (const double x : value) {
      const ExactWords w = exact_words(x);
      u.words.push_back(w.lo);
      u.words.push_back(w.hi);
    }
    u.words.resize(static_cast<std::size_t>(u.count) * 4, 0u);
    return {u};
  }
  const int n = detail::double_components(v.type);
  const std::size_t elements = detail::array_elements(v.type);
  if (!is_binary64_words(v) || n == 0 || elements == 0 || value.size() != elements * static_cast<std::size_t>(n) ||
      v.lowered_types.size() != v.lowered_names.size())
    return {};
  std::vector<UniformWords> out;
  int first = 0;  // the first component each lowered variable holds
  for (std::size_t part = 0; part < v.lowered_names.size(); ++part) {
    UniformWords u{v.lowered_names[part], detail::uint_components(v.lowered_types[part]), static_cast<int>(elements), {}};
    const int doubles = u.components / 2;
    for (std::size_t e = 0; e < elements; ++e)
      for (int c = first; c < first + doubles; ++c) {
        const ExactWords w = exact_words(value[e * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)]);
        u.words.push_back(w.lo);
        u.words.push_back(w.hi);
      }
    first += doubles;
    out.push_back(std::move(u));
  }
  return out;
}
inline std::vector<UniformWords> uniform_words(const Variable& v, std::initializer_list<double> value) {
  return uniform_words(v, std::span<const double>(value.begin(), value.size()));
}

// One lowered vertex attribute of a mode-exact double input, read straight from the host's doubles:
// glVertexAttribIPointer(location, components, GL_UNSIGNED_INT, host stride, offset_bytes).
struct WordAttribute {
  std::string name;
  int location = -1;       // from the manifest; -1: ask GL (glGetAttribLocation)
  int components = 0;      // uints: 2 or 4
  std::size_t offset_bytes = 0;
};

// The attributes of vertex input `v` (double/dvecN) whose doubles start `offset_bytes` into each
// vertex of the host's buffer (offsetof(Vertex, position)); empty when `v` is not one.
inline std::vector<WordAttribute> word_attributes(const Variable& v, std::size_t offset_bytes) {
  if (!is_binary64_words(v) || (v.storage != "in" && v.storage != "attribute") ||
      v.lowered_types.size() != v.lowered_names.size())
    return {};
  std::vector<WordAttribute> out;
  for (std::size_t part = 0; part < v.lowered_names.size(); ++part) {
    const int components = detail::uint_components(v.lowered_types[part]);
    out.push_back({v.lowered_names[part], v.location(part), components, offset_bytes});
    offset_bytes += static_cast<std::size_t>(components) * 4;
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Float-float arrays in uniform/storage blocks

enum class BlockLayout { Std140, Std430 };

// Where hi and lo of one element lie in an array of `struct { vecN hi; vecN lo; }` (the
// lowered df_vecN pair) under a block layout, in floats. vec3 members are 16-byte aligned
// in both layouts; std140 also rounds each array element up to 16 bytes.
struct PairLayout {
  std::size_t hi_offset = 0, lo_offset = 0, stride = 0;
};

inline PairLayout pair_layout(int components, BlockLayout layout) {
  const std::size_t n = static_cast<std::size_t>(components);
  const std::size_t align = n == 1 ? 1 : n == 2 ? 2 : 4;  // floats
  PairLayout p{0, align, 0};
  std::size_t size = p.lo_offset + n;
  std::size_t struct_align = layout == BlockLayout::Std140 ? 4 : align;
  p.stride = (size + struct_align - 1) / struct_align * struct_align;
  return p;
}

// Writes `values` (components doubles per element) as float-float pairs into `out`
// (resized to elements × stride floats; padding is zero), ready for glBufferData.
inline void pack_pairs(std::span<const double> values, int components, BlockLayout layout, std::vector<float>& out) {
  const std::size_t n = static_cast<std::size_t>(components);
  const PairLayout p = pair_layout(components, layout);
  const std::size_t elements = n ? values.size() / n : 0;
  out.assign(elements * p.stride, 0.0f);
  for (std::size_t e = 0; e < elements; ++e)
    for (std::size_t c = 0; c < n; ++c) {
      FloatPair fp = split(values[e * n + c]);
      out[e * p.stride + p.hi_offset + c] = fp.hi;
      out[e * p.stride + p.lo_offset + c] = fp.lo;
    }
}

}  // namespace doublet::pack
