#include "verify/compute_harness.hpp"

#include <algorithm>
#include <cstring>
#include <map>

#include "doublet/split.hpp"
#include "verify/bytes.hpp"
#include "verify/inputs.hpp"
#include "verify/relations.hpp"
#include "verify/words.hpp"

namespace doublet::verify {
namespace {

using runner::ShaderInterface;

std::string type_name(bool is_double, int components) {
  if (components == 1) return is_double ? "double" : "float";
  return std::string(is_double ? "dvec" : "vec") + std::to_string(components);
}

uint32_t width(bool is_double) { return scalar_width(is_double); }

// One past the last byte of `elements` elements of `element_bytes` each, `stride` apart from `offset`.
uint32_t end_of_elements(uint32_t offset, uint32_t elements, uint32_t stride, uint32_t element_bytes) {
  return offset + (elements > 0 ? (elements - 1) * stride : 0) + element_bytes;
}

// Grows `sizes` so that binding `binding` holds `end` bytes.
void make_room(std::vector<uint32_t>& sizes, int binding, uint32_t end) {
  if (sizes.size() <= static_cast<size_t>(binding)) sizes.resize(static_cast<size_t>(binding) + 1, 16);
  uint32_t& size = sizes[static_cast<size_t>(binding)];
  size = std::max(size, end);
}

// Bytes each binding needs, with runtime arrays holding `array_length` elements.
std::vector<uint32_t> buffer_sizes(const ShaderInterface& s, uint32_t array_length) {
  std::vector<uint32_t> sizes;
  for (const auto& m : s.members) {
    const auto& block = s.blocks[static_cast<size_t>(m.block)];
    if (block.binding < 0) continue;
    const uint32_t elements = m.array_size == 0 ? array_length : m.array_size;
    const uint32_t element_bytes = std::max<uint32_t>(m.components, 1) * width(m.is_double) * 4;  // generous for non-numeric
    make_room(sizes, block.binding,
              std::max(end_of_elements(m.offset, elements, m.array_stride, element_bytes), block.fixed_size));
  }
  for (uint32_t& size : sizes) size = (size + 15) / 16 * 16;
  return sizes;
}

// The split member `name` of a buffer block in the manifest (hi_offset/lo_offset set), or null; a
// member of an array of structs, reflected as "p.pos", is listed as "p[0].pos" (offset in element
// 0) and *stride becomes the array's ("p") stride.
const BlockMember* find_split_member(const Manifest& manifest, const std::string& reflected, uint32_t* stride) {
  for (const auto& v : manifest.variables) {
    // Reflection names a member of a block with an instance name (`buffer Io { ... } io;`) as
    // "Io.x"; the manifest lists it under the block as "x".
    const std::string prefix = v.type + ".";
    const std::string name = reflected.rfind(prefix, 0) == 0 ? reflected.substr(prefix.size()) : reflected;
    const size_t dot = name.find('.');
    const std::string array = dot == std::string::npos ? "" : name.substr(0, dot);
    const std::string element_name = array.empty() ? name : array + "[0]" + name.substr(dot);
    for (const auto& m : v.members) {
      if (m.hi_offset < 0 || m.lo_offset < 0 || m.matrix_stride != 0) continue;
      if (m.name == name) {
        *stride = static_cast<uint32_t>(m.array_stride);
        return &m;
      }
      if (m.name != element_name) continue;
      for (const auto& parent : v.members)
        if (parent.name == array) *stride = static_cast<uint32_t>(parent.array_stride);
      return &m;
    }
  }
  return nullptr;
}

const InterfaceVariable* find_in_manifest(const Manifest& manifest, const std::string& name) {
  for (const auto& v : manifest.variables)
    if (v.name == name) return &v;
  return nullptr;
}

}  // namespace

std::string ComputeHarness::add_variable(const ShaderInterface& native_if, const ShaderInterface& lowered_if,
                                         const Manifest& manifest, bool is_uniform, const std::string& name,
                                         bool as_input) {
  Variable v;
  v.name = name;
  auto slot_of = [&](const ShaderInterface& s, const std::string& n, Slot* out) {
    out->is_uniform = is_uniform;
    out->name = n;
    if (is_uniform) {
      for (const auto& u : s.uniforms)
        if (u.name == n) {
          out->is_double = u.is_double;
          out->scalar = u.scalar;
          out->components = u.components;
          return true;
        }
      return false;
    }
    for (const auto& m : s.members)
      if (m.name == n) {
        out->is_double = m.is_double;
        out->components = m.components;
        out->binding = s.blocks[static_cast<size_t>(m.block)].binding;
        out->offset = m.offset;
        out->stride = m.array_stride;
        out->elements = m.array_size;  // 0 (runtime) fixed up when the array length is known
        return true;
      }
    return false;
  };
  slot_of(native_if, name, &v.native);
  // Mode exact: a buffer member keeps its place and bytes; a double uniform becomes its word
  // variables (the manifest's lowered names, uvec2/uvec4 each).
  if (words_ && !is_uniform) {
    v.lowered = {v.native};
    (as_input ? inputs_ : outputs_).push_back(std::move(v));
    return {};
  }
  if (words_ && v.native.is_double) {
    const InterfaceVariable* mv = find_in_manifest(manifest, name);
    if (!mv) return "uniform '" + name + "' is not in the manifest";
    for (const std::string& n : mv->lowered_names) {
      Slot s;
      if (!slot_of(lowered_if, n, &s)) continue;  // inactive after lowering
      v.lowered.push_back(s);
    }
    (as_input ? inputs_ : outputs_).push_back(std::move(v));
    return {};
  }
  // A double buffer member lowered to a df_* struct (`dvec3 position[]` -> `df_dvec3
  // position[]`): reflection sees a struct, the manifest gives where hi and lo live in each element.
  Slot probe;
  if (!is_uniform && (!slot_of(lowered_if, name, &probe) || probe.components == 0))
    if (uint32_t stride = 0; const BlockMember* m = find_split_member(manifest, name, &stride)) {
      if (v.native.components == 0) return {};
      for (int offset : {m->hi_offset, m->lo_offset}) {
        Slot s = v.native;
        s.is_double = false;
        s.offset = static_cast<uint32_t>(m->offset + offset);
        s.stride = stride;
        v.lowered.push_back(s);
      }
      (as_input ? inputs_ : outputs_).push_back(std::move(v));
      return {};
    }
  const InterfaceVariable* mv = find_in_manifest(manifest, name);
  const std::vector<std::string> lowered_names =
      mv && mv->split && mv->lowered_names.size() == 2 ? mv->lowered_names : std::vector<std::string>{name};
  for (const std::string& n : lowered_names) {
    Slot s;
    if (!slot_of(lowered_if, n, &s)) {
      if (!as_input) return "output '" + name + "' has no '" + n + "' in the lowered shader";
      s = v.native;  // inactive after lowering: set it anyway (the runner ignores absent uniforms)
      s.name = n;
      s.is_double = false;
      if (!is_uniform) continue;
    }
    v.lowered.push_back(s);
  }
  if (!as_input && v.lowered.size() == 1 && v.lowered[0].components != v.native.components)
    return "output '" + name + "' changed shape in the lowered shader";
  (as_input ? inputs_ : outputs_).push_back(std::move(v));
  return {};
}

std::string ComputeHarness::plan(const std::string& native_glsl, const std::string& lowered_glsl,
                                 const Manifest& manifest, const Spec& spec, uint64_t samples) {
  native_glsl_ = native_glsl;
  lowered_glsl_ = lowered_glsl;
  words_ = carries_words(manifest);
  ShaderInterface native_if, lowered_if;
  std::string error;
  if (!runner::reflect_compute(native_glsl, &native_if, &error))
    return "the shader does not compile as native fp64 (#version 450):\n" + error;
  if (!runner::reflect_compute(lowered_glsl, &lowered_if, &error))
    return "the lowered shader does not compile for reflection:\n" + error;

  if (!native_if.uniform_blocks.empty() || !native_if.samplers.empty())
    return "compute verify does not feed named uniform blocks or samplers yet ('" +
           (native_if.uniform_blocks.empty() ? native_if.samplers[0] : native_if.uniform_blocks[0].name) +
           "'): use loose uniforms and buffers, or verify a vertex/fragment shader (which binds both)";
  for (const auto& u : native_if.uniforms) {
    if (u.components == 0) {
      notes_.push_back("uniform '" + u.name + "' is not a float/double scalar or vector: left at 0");
      continue;
    }
    if (u.scalar != 'f' && u.scalar != 'd' && !spec.inputs.count(u.name)) {
      notes_.push_back("uniform '" + u.name + "' is an int/uint/bool: left at 0 (give it a --range or spec values)");
      continue;
    }
    if (std::string e = add_variable(native_if, lowered_if, manifest, true, u.name, true); !e.empty()) return e;
  }
  for (const auto& m : native_if.members) {
    const auto& block = native_if.blocks[static_cast<size_t>(m.block)];
    if (m.components == 0) {
      notes_.push_back("buffer member '" + m.name + "' is not a float/double scalar or vector: " +
                       (block.readonly ? "left at 0" : "not compared"));
      continue;
    }
    if (!block.writeonly)
      if (std::string e = add_variable(native_if, lowered_if, manifest, false, m.name, true); !e.empty()) return e;
    if (!block.readonly)
      if (std::string e = add_variable(native_if, lowered_if, manifest, false, m.name, false); !e.empty()) return e;
  }
  if (outputs_.empty()) return "the shader writes no float/double buffer member: nothing to compare";

  for (const auto& [name, in] : spec.inputs) {
    auto it = std::find_if(inputs_.begin(), inputs_.end(), [&name = name](const Variable& v) { return v.name == name; });
    if (it == inputs_.end() && in.from_initializer) continue;
    if (it == inputs_.end() && apply_to_parts(inputs_, name, in)) continue;  // a struct's members: each
    if (it == inputs_.end()) {
      std::string known;
      for (const auto& v : inputs_) known += " " + v.name;
      return "no input named '" + name + "' (inputs:" + known + ")";
    }
    it->input = in;
  }
  for (const auto& [name, out] : spec.outputs) {
    auto it = std::find_if(outputs_.begin(), outputs_.end(), [&name = name](const Variable& v) { return v.name == name; });
    if (it == outputs_.end()) return "no output named '" + name + "'";
    if (out.join_hi_lo && (it->native.is_double || it->native.components % 2 != 0))
      return "output '" + name + "': join hi_lo needs a vec2 or vec4";
    it->output = out;
  }

  relations_ = spec.relations;
  for (const InputRelation& r : relations_)
    for (const std::string& n : {r.a, r.b})
      if (std::none_of(inputs_.begin(), inputs_.end(), [&](const Variable& v) { return v.name == n; }))
        return "relation: no input named '" + n + "'";
  // Batched when every value is per invocation: one dispatch covers all samples.
  auto runtime_array = [](const Variable& v) { return !v.native.is_uniform && v.native.elements == 0; };
  const bool batched = !spec.array_length && spec.groups[0] * spec.groups[1] * spec.groups[2] == 1 &&
                       std::all_of(inputs_.begin(), inputs_.end(), runtime_array) &&
                       std::all_of(outputs_.begin(), outputs_.end(), runtime_array);
  const uint64_t local = uint64_t{native_if.local_size[0]} * native_if.local_size[1] * native_if.local_size[2];
  if (batched) {
    groups_[0] = static_cast<uint32_t>((samples + local - 1) / local);
    array_length_ = static_cast<uint32_t>(groups_[0] * local);
    dispatches_ = 1;
  } else {
    std::copy(spec.groups, spec.groups + 3, groups_);
    array_length_ = spec.array_length.value_or(static_cast<uint32_t>(local * groups_[0] * groups_[1] * groups_[2]));
    dispatches_ = samples;
  }
  // A read-write member is both an input and an output: it gets the larger element count.
  std::map<std::string, unsigned> per_invocation;
  for (const Variable& v : inputs_) per_invocation[v.name] = v.input.elements_per_invocation;
  for (const Variable& v : outputs_)
    per_invocation[v.name] = std::max(per_invocation[v.name], v.output.elements_per_invocation);
  unsigned max_per_invocation = 1;
  for (auto* list : {&inputs_, &outputs_})
    for (Variable& v : *list) {
      const uint32_t elements = array_length_ * per_invocation[v.name];
      max_per_invocation = std::max(max_per_invocation, per_invocation[v.name]);
      if (v.native.elements == 0) v.native.elements = elements;
      for (Slot& s : v.lowered)
        if (s.elements == 0) s.elements = elements;
    }
  // Sized for the largest count (members verify does not feed get room too; over-allocating is harmless).
  native_sizes_ = buffer_sizes(native_if, array_length_ * max_per_invocation);
  lowered_sizes_ = buffer_sizes(lowered_if, array_length_ * max_per_invocation);
  // Split members placed from the manifest (reflection sees their df_* elements as struct
  // fields, not as an array): make room for every element of them too.
  for (auto* list : {&inputs_, &outputs_})
    for (const Variable& v : *list)
      for (const Slot& s : v.lowered)
        if (!s.is_uniform && s.binding >= 0 && s.elements > 0)
          make_room(lowered_sizes_, s.binding,
                    (end_of_elements(s.offset, s.elements, s.stride,
                                     static_cast<uint32_t>(s.components) * width(s.is_double)) + 15) / 16 * 16);
  const size_t n = std::max(native_sizes_.size(), lowered_sizes_.size());
  native_sizes_.resize(n, 16);
  lowered_sizes_.resize(n, 16);
  if (words_)  // one layout: both get the same bytes
    for (size_t b = 0; b < n; ++b) native_sizes_[b] = lowered_sizes_[b] = std::max(native_sizes_[b], lowered_sizes_[b]);
  return {};
}

void ComputeHarness::generate(uint64_t seed) {
  InputGenerator gen(seed, words_);
  values_.assign(dispatches_, {});
  for (uint64_t d = 0; d < dispatches_; ++d)
    for (const Variable& v : inputs_) {
      const size_t count = size_t{v.native.elements} * static_cast<size_t>(v.native.components);
      std::vector<double> vals(count);
      for (size_t k = 0; k < count; ++k) {
        vals[k] = gen.next(v.input.component(k % static_cast<size_t>(std::max(v.native.components, 1))),
                           v.native.is_double, d * count + k);
        if (v.native.scalar != 'f' && v.native.scalar != 'd') vals[k] = integer_value(vals[k], v.native.scalar);
      }
      values_[d].push_back(std::move(vals));
    }
  beyond_float_range_ = gen.beyond_float_range();
  if (beyond_float_range_ > 0) notes_.push_back(beyond_float_range_note(beyond_float_range_));
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  for (uint64_t d = 0; d < dispatches_; ++d) {
    std::vector<RelatedInput> related;
    for (size_t i = 0; i < inputs_.size(); ++i)
      related.push_back({inputs_[i].name, !inputs_[i].native.is_uniform, inputs_[i].native.components,
                         inputs_[i].native.is_double, &inputs_[i].input, &values_[d][i]});
    if (std::string note = apply_relations(relations_, related, rng); !note.empty() && d == 0) notes_.push_back(note);
  }
}

std::vector<runner::ComputeJob> ComputeHarness::jobs(bool native) const {
  std::vector<runner::ComputeJob> out(dispatches_);
  const std::vector<uint32_t>& sizes = native ? native_sizes_ : lowered_sizes_;
  for (uint64_t d = 0; d < dispatches_; ++d) {
    runner::ComputeJob& job = out[d];
    job.glsl = native ? native_glsl_ : lowered_glsl_;
    job.strict_fp64 = native && words_;  // mode exact is compared with fp64 evaluated as written
    job.groups_x = groups_[0];
    job.groups_y = groups_[1];
    job.groups_z = groups_[2];
    for (uint32_t size : sizes) job.buffers.emplace_back(size, 0);
    for (size_t i = 0; i < inputs_.size(); ++i) {
      const Variable& v = inputs_[i];
      const std::vector<double>& vals = values_[d][i];
      const std::vector<Slot> slots = native ? std::vector<Slot>{v.native} : v.lowered;
      if (!native && words_ && v.native.is_uniform && v.native.is_double) {  // uvec2/uvec4 word uniforms
        std::vector<int> components;
        for (const Slot& s : slots) components.push_back(s.components);
        const auto parts = word_parts(std::vector<double>(vals.begin(), vals.begin() + v.native.components),
                                      v.native.components, components);
        for (size_t part = 0; part < slots.size(); ++part) {
          job.uniforms[slots[part].name] = parts[part];
          // A dmat3 (9 doubles) fills 4.5 uvec4s of `uvec4 M[5]`: the last two words are unused.
          if (job.uniforms[slots[part].name].size() < size_t(slots[part].components))
            job.uniforms[slots[part].name].resize(size_t(slots[part].components), 0.0);
        }
        continue;
      }
      for (size_t part = 0; part < slots.size(); ++part) {
        const Slot& s = slots[part];
        // A split pair gets hi in part 0 and lo in part 1; anything else gets the value itself.
        auto value = [&](double x) {
          if (slots.size() != 2) return x;
          const FloatPair p = split(x);
          return static_cast<double>(part == 0 ? p.hi : p.lo);
        };
        if (s.is_uniform) {
          std::vector<double>& u = job.uniforms[s.name];
          for (int c = 0; c < s.components; ++c) u.push_back(value(vals[static_cast<size_t>(c)]));
          continue;
        }
        for (uint32_t e = 0; e < s.elements && e < v.native.elements; ++e)
          for (int c = 0; c < s.components; ++c)
            write_value(job.buffers[static_cast<size_t>(s.binding)],
                        s.offset + size_t{e} * s.stride + size_t(c) * width(s.is_double), s.is_double,
                        value(vals[size_t{e} * static_cast<size_t>(v.native.components) + static_cast<size_t>(c)]));
      }
    }
  }
  return out;
}

std::string ComputeHarness::describe_sample(uint64_t dispatch, uint32_t invocation) const {
  const uint32_t element = invocation;
  std::string s;
  for (size_t i = 0; i < inputs_.size(); ++i) {
    const Variable& v = inputs_[i];
    const uint32_t k = v.input.elements_per_invocation;
    for (uint32_t j = 0; j < k; ++j) {
      const uint32_t e = v.native.elements > 1 ? element * k + j : 0;
      if (e >= v.native.elements || (j > 0 && v.native.elements == 1)) continue;
      s += (s.empty() ? "" : " ") + v.name + (v.native.elements > 1 ? "[" + std::to_string(e) + "]" : "") + "=";
      const size_t comps = static_cast<size_t>(v.native.components);
      if (comps > 1) s += "(";
      for (size_t c = 0; c < comps; ++c) s += (c ? ", " : "") + hex(values_[dispatch][i][e * comps + c]);
      if (comps > 1) s += ")";
    }
  }
  if (dispatches_ > 1) s = "dispatch " + std::to_string(dispatch) + ": " + s;
  return s;
}

std::vector<std::string> ComputeHarness::describe_inputs() const {
  std::vector<std::string> out;
  for (const Variable& v : inputs_)
    out.push_back(v.name + (v.native.is_uniform ? "" : "[]") + " (" + (v.native.is_uniform ? "uniform " : "buffer ") +
                  type_name(v.native.is_double, v.native.components) + ")");
  return out;
}

std::vector<OutputStats> ComputeHarness::compare(const std::vector<runner::ComputeResult>& native,
                                                 const std::vector<runner::ComputeResult>& lowered,
                                                 std::optional<double> default_min_bits) const {
  std::vector<OutputStats> all;
  static const char* kComponent = "xyzw";
  for (const Variable& v : outputs_) {
    const int step = v.output.join_hi_lo ? 2 : 1;
    const bool array = v.native.elements > 1;
    for (int c = 0; c < v.native.components; c += step) {
      std::string name = v.name + (array ? "[]" : "");
      if (v.native.components > 1) name += std::string(".") + std::string(kComponent + c, static_cast<size_t>(step));
      const std::string type = v.output.join_hi_lo ? "float hi+lo" : v.native.is_double ? "double" : "float";
      StatsBuilder stats(name, type, v.output.abs_floor.value_or(0x1p-126));
      auto read = [&](const Slot& s, const runner::ComputeResult& r, uint32_t e, int comp) {
        return read_value(r.buffers[static_cast<size_t>(s.binding)],
                          s.offset + size_t{e} * s.stride + size_t(comp) * width(s.is_double), s.is_double);
      };
      for (uint64_t d = 0; d < dispatches_; ++d)
        for (uint32_t e = 0; e < v.native.elements; ++e) {
          double want = read(v.native, native[d], e, c);
          double got = 0;
          if (v.output.join_hi_lo) {
            want = join(static_cast<float>(want), static_cast<float>(read(v.native, native[d], e, c + 1)));
            got = join(static_cast<float>(read(v.lowered[0], lowered[d], e, c)),
                       static_cast<float>(read(v.lowered[0], lowered[d], e, c + 1)));
          } else if (v.lowered.size() == 2) {
            got = join(static_cast<float>(read(v.lowered[0], lowered[d], e, c)),
                       static_cast<float>(read(v.lowered[1], lowered[d], e, c)));
          } else {
            got = read(v.lowered[0], lowered[d], e, c);
          }
          stats.add(got, want, d * v.native.elements + e);
        }
      OutputStats s = stats.finish();
      const uint64_t worst_element = s.worst_sample % v.native.elements;
      s.worst_input = describe_sample(s.worst_sample / v.native.elements,
                                      static_cast<uint32_t>(worst_element / v.output.elements_per_invocation));
      if (v.native.elements > 1) s.worst_input = v.name + "[" + std::to_string(worst_element) + "] of " + s.worst_input;
      s.min_bits_required = v.output.min_bits.value_or(default_min_bits.value_or(-1));
      s.max_abs_err_allowed = v.output.max_abs_error.value_or(-1);
      all.push_back(std::move(s));
    }
  }
  return all;
}

}  // namespace doublet::verify
