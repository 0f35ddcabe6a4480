#include "verify/graphics_harness.hpp"

#include <algorithm>

#include "doublet/split.hpp"
#include "verify/bytes.hpp"
#include "verify/inputs.hpp"
#include "verify/relations.hpp"
#include "verify/words.hpp"

namespace doublet::verify {
namespace {

using runner::GraphicsInterface;

constexpr uint32_t kMaxPerDraw = 65536;     // the runner's grid
constexpr uint32_t kDefaultPerDraw = 64;    // samples per draw when uniforms vary per draw

std::string type_name(char scalar, int components, bool matrix) {
  const bool is_double = scalar == 'd';
  if (matrix) return std::string(is_double ? "dmat" : "mat") + "(" + std::to_string(components) + " values)";
  static const std::pair<char, std::pair<const char*, const char*>> kNames[] = {
      {'f', {"float", "vec"}}, {'d', {"double", "dvec"}}, {'i', {"int", "ivec"}}, {'u', {"uint", "uvec"}}, {'b', {"bool", "bvec"}}};
  for (const auto& [letter, names] : kNames)
    if (letter == scalar) return components == 1 ? names.first : names.second + std::to_string(components);
  return "?";
}

// "world[2]" (an element of a geometry shader's per-vertex input array) → {"world", "[2]"}; any
// other name → {name, ""}.
std::pair<std::string, std::string> array_element(const std::string& name) {
  const size_t open = name.find('[');
  if (open == std::string::npos || name.back() != ']' || name.find('.') != std::string::npos) return {name, ""};
  return {name.substr(0, open), name.substr(open)};
}

std::vector<std::string> lowered_names(const Manifest& manifest, const std::string& element_name) {
  const auto [name, element] = array_element(element_name);
  for (const auto& v : manifest.variables)
    if (v.name == name && v.split && v.lowered_names.size() == 2) return {v.lowered_names[0] + element, v.lowered_names[1] + element};
  return {element_name};
}

bool has_output(const GraphicsInterface& s, const std::string& name) {
  return std::any_of(s.outputs.begin(), s.outputs.end(), [&](const auto& o) { return o.name == name; });
}

// `instance.member` of an in/out block the lowering flattened (targets without I/O blocks): the
// manifest's BLOCK_member variable, when exactly one flattened block has that member; else "".
std::string flattened_block_member(const Manifest& manifest, const std::string& name) {
  const size_t dot = name.find('.');
  if (dot == std::string::npos) return {};
  const std::string member = name.substr(dot + 1);
  std::string found;
  for (const auto& v : manifest.variables) {
    if (v.block.empty() || v.name != v.block + "_" + member) continue;
    if (!found.empty()) return {};  // two blocks with this member: the instance name cannot tell which
    found = v.name;
  }
  return found;
}

// An output's name in the lowered shader: split pairs from the manifest; a flattened block member
// its BLOCK_member variable; gl_FragColor becomes the
// printer's declared `df_frag_color` on targets without it (src/emit/printer.cpp), gl_FragData[k]
// its `df_frag_data_k`, and on es100 a
// fragment shader's only output becomes gl_FragColor.
std::vector<std::string> lowered_output_names(const Manifest& manifest, const GraphicsInterface& native_if,
                                              const GraphicsInterface& lowered_if, const std::string& name) {
  if (!has_output(lowered_if, name)) {
    if (name == "gl_FragColor" && has_output(lowered_if, "df_frag_color")) return {"df_frag_color"};
    // gl_FragData[k] -> the printer's df_frag_data_k.
    if (name.rfind("gl_FragData[", 0) == 0 && name.back() == ']') {
      const std::string slot = "df_frag_data_" + name.substr(12, name.size() - 13);
      if (has_output(lowered_if, slot)) return {slot};
    }
    if (native_if.outputs.size() == 1 && has_output(lowered_if, "gl_FragColor")) return {"gl_FragColor"};
    if (std::string flat = flattened_block_member(manifest, name); !flat.empty()) return lowered_names(manifest, flat);
  }
  return lowered_names(manifest, name);
}

// Mode exact: the word variables a double became (manifest) and their uints per sample (the
// lowered shader's reflection); false when one is missing.
bool word_variables(const Manifest& manifest, const std::string& element_name,
                    const std::vector<runner::StageVariable>* stage,
                    const std::vector<runner::ShaderInterface::Uniform>* uniforms, std::vector<std::string>* names,
                    std::vector<int>* components) {
  const auto [name, element] = array_element(element_name);
  for (const auto& v : manifest.variables) {
    if (v.name != name || v.encoding.empty()) continue;
    for (const std::string& lowered : v.lowered_names) {
      const std::string n = lowered + element;
      int c = 0;
      if (stage)
        for (const auto& s : *stage) c = s.name == n ? s.components : c;
      if (uniforms)
        for (const auto& u : *uniforms) c = u.name == n ? u.components : c;
      if (c == 0) return false;
      names->push_back(n);
      components->push_back(c);
    }
    return true;
  }
  return false;
}

const runner::ShaderInterface::UniformBlock* find_block(const GraphicsInterface& s, const std::string& name) {
  for (const auto& b : s.uniform_blocks)
    if (b.name == name) return &b;
  return nullptr;
}

const BlockMember* find_manifest_member(const Manifest& manifest, const std::string& block, const std::string& member) {
  for (const auto& v : manifest.variables)
    if (v.name == block && v.storage == "uniform")
      for (const auto& m : v.members)
        if (m.name == member) return &m;
  return nullptr;
}

}  // namespace

std::string GraphicsHarness::plan(runner::GraphicsStage stage, const std::string& native_glsl,
                                  const std::string& lowered_glsl, const Manifest& manifest, const Spec& spec,
                                  uint64_t samples) {
  stage_ = stage;
  native_glsl_ = native_glsl;
  lowered_glsl_ = lowered_glsl;
  words_ = carries_words(manifest);
  GraphicsInterface native_if, lowered_if;
  std::string error;
  if (!runner::reflect_graphics(stage, native_glsl, &native_if, &error))
    return "the shader cannot run as native fp64 (#version 450): " + error;
  if (!runner::reflect_graphics(stage, lowered_glsl, &lowered_if, &error))
    return "the lowered shader cannot run: " + error;

  for (const auto& u : native_if.uniforms) {
    if (u.components == 0) {
      notes_.push_back("uniform '" + u.name + "' is not a scalar, vector or matrix: left at 0");
      continue;
    }
    const bool integer = u.scalar != 'f' && u.scalar != 'd';
    if (integer && !spec.inputs.count(u.name)) {
      notes_.push_back("uniform '" + u.name + "' is an int/uint/bool: left at 0 (give it a --range or spec values)");
      continue;
    }
    Variable v{u.name, true, u.is_double, u.components, lowered_names(manifest, u.name)};
    v.scalar = u.scalar;
    v.columns = u.columns;
    if (words_ && u.is_double) {
      v.lowered.clear();
      if (!word_variables(manifest, u.name, nullptr, &lowered_if.uniforms, &v.lowered, &v.word_components))
        notes_.push_back("uniform '" + u.name + "' is not used by the lowered shader: fed to the native one only");
    }
    if (u.columns > 1) notes_.push_back("uniform '" + u.name + "' is a matrix: fed column by column");
    inputs_.push_back(std::move(v));
  }
  add_block_members(native_if, lowered_if, manifest);
  for (const std::string& sampler : native_if.samplers)
    notes_.push_back("sampler '" + sampler + "' reads the runner's " + std::to_string(runner::kTextureSize) +
                     "-texel RGBA32F test texture (NEAREST) in both runs");
  for (const auto& in : native_if.inputs) {
    if (in.scalar != 'f' && in.scalar != 'd') {
      notes_.push_back("input '" + in.name + "' is an integer: left at 0");
      continue;
    }
    const std::string flat = flattened_block_member(manifest, in.name);
    Variable v{in.name, false, in.scalar == 'd', in.components, lowered_names(manifest, flat.empty() ? in.name : flat)};
    v.scalar = in.scalar;
    if (words_ && v.is_double) {
      v.lowered.clear();
      if (!word_variables(manifest, flat.empty() ? in.name : flat, &lowered_if.inputs, nullptr, &v.lowered, &v.word_components))
        notes_.push_back("input '" + in.name + "' is not used by the lowered shader: fed to the native one only");
    }
    inputs_.push_back(std::move(v));
  }
  for (const auto& out : native_if.outputs) {
    if (out.scalar != 'f' && out.scalar != 'd') {
      notes_.push_back("output '" + out.name + "' is an integer: not compared");
      continue;
    }
    Variable v{out.name, false, out.scalar == 'd', out.components, lowered_output_names(manifest, native_if, lowered_if, out.name)};
    v.scalar = out.scalar;
    if (words_ && v.is_double) {
      v.lowered.clear();
      const std::string flat = flattened_block_member(manifest, out.name);
      if (!word_variables(manifest, flat.empty() ? out.name : flat, &lowered_if.outputs, nullptr, &v.lowered, &v.word_components))
        return "output '" + out.name + "' has no binary64 word outputs in the lowered shader";
    }
    for (const std::string& n : v.lowered)
      if (!has_output(lowered_if, n)) return "output '" + out.name + "' has no '" + n + "' in the lowered shader";
    outputs_.push_back(std::move(v));
  }
  if (outputs_.empty()) return "the shader has no float/double output: nothing to compare";

  for (const auto& [name, in] : spec.inputs) {
    auto it = std::find_if(inputs_.begin(), inputs_.end(), [&name = name](const Variable& v) { return v.name == name; });
    if (it == inputs_.end() && in.from_initializer) continue;
    // A per-vertex input array of a geometry or tessellation shader by its own name: every element.
    if (it == inputs_.end() && apply_to_parts(inputs_, name, in)) continue;
    // A member of a uniform block by the name the shader reads it by (`center` of an anonymous block
    // listed as Camera.center, as `doublet plan` names it), where one block has it.
    if (it == inputs_.end() && name.find('.') == std::string::npos) {
      const std::string suffix = "." + name;
      const auto member = [&](const Variable& v) {
        return v.is_uniform && v.name.size() > suffix.size() &&
               v.name.compare(v.name.size() - suffix.size(), suffix.size(), suffix) == 0 &&
               v.name.find('.') == v.name.size() - suffix.size();
      };
      if (std::count_if(inputs_.begin(), inputs_.end(), member) == 1) it = std::find_if(inputs_.begin(), inputs_.end(), member);
    }
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
    if (out.join_hi_lo && (it->is_double || it->components % 2 != 0))
      return "output '" + name + "': join hi_lo needs a vec2 or vec4";
    it->output = out;
  }

  relations_ = spec.relations;
  for (const InputRelation& r : relations_)
    for (const std::string& n : {r.a, r.b})
      if (std::none_of(inputs_.begin(), inputs_.end(), [&](const Variable& v) { return v.name == n; }))
        return "relation: no input named '" + n + "'";
  const bool uniforms = std::any_of(inputs_.begin(), inputs_.end(), [](const Variable& v) { return v.is_uniform; });
  per_draw_ = uniforms ? spec.array_length.value_or(kDefaultPerDraw) : static_cast<uint32_t>(std::min<uint64_t>(samples, kMaxPerDraw));
  per_draw_ = std::clamp<uint32_t>(per_draw_, 1, kMaxPerDraw);
  records_ = native_if.records_per_sample;
  draws_ = (samples + per_draw_ - 1) / per_draw_;
  return {};
}

// Members of named uniform blocks are per-draw inputs like loose uniforms; the native values go to
// their std140 places (glslang reflection), the lowered ones to the manifest's (hi and lo of a
// split member) or, for a block without doubles, to the lowered shader's reflected places.
void GraphicsHarness::add_block_members(const GraphicsInterface& native_if, const GraphicsInterface& lowered_if,
                                        const Manifest& manifest) {
  for (const auto& block : native_if.uniform_blocks) {
    const auto* lowered_block = find_block(lowered_if, block.name);
    native_block_sizes_[block.name] = block.size;
    lowered_block_sizes_[block.name] = lowered_block ? lowered_block->size : 0;
    for (const auto& m : block.members) {
      const std::string name = block.name + "." + m.name;
      if (m.components == 0 || (m.scalar != 'f' && m.scalar != 'd')) {
        notes_.push_back("uniform block member '" + name + "' is not a float/double scalar, vector or matrix: left at 0");
        continue;
      }
      Variable v{name, true, m.scalar == 'd', m.components, {name}};
      v.scalar = m.scalar;
      v.columns = m.columns;
      v.block = block.name;
      const int rows = m.components / m.columns;
      v.native_place = {m.offset, runner::std140_column_stride(v.is_double, rows), v.is_double};
      if (words_) {  // the original bytes at the original places
        v.lowered_places.push_back(v.native_place);
      } else if (const BlockMember* bm = find_manifest_member(manifest, block.name, m.name); bm && bm->hi_offset >= 0) {
        for (int part : {bm->hi_offset, bm->lo_offset})
          v.lowered_places.push_back({static_cast<uint32_t>(bm->offset + part), static_cast<uint32_t>(bm->matrix_stride), false});
      } else if (lowered_block) {
        auto it = std::find_if(lowered_block->members.begin(), lowered_block->members.end(),
                               [&](const auto& lm) { return lm.name == m.name; });
        if (it != lowered_block->members.end())
          v.lowered_places.push_back({it->offset, runner::std140_column_stride(it->is_double, rows), it->is_double});
      }
      if (v.lowered_places.empty())
        notes_.push_back("uniform block member '" + name + "' is not used by the lowered shader: fed to the native one only");
      inputs_.push_back(std::move(v));
    }
  }
}

void GraphicsHarness::generate(uint64_t seed) {
  InputGenerator gen(seed, words_);
  values_.assign(draws_, {});
  for (uint64_t d = 0; d < draws_; ++d)
    for (const Variable& v : inputs_) {
      const size_t count = (v.is_uniform ? 1 : size_t{per_draw_}) * static_cast<size_t>(v.components);
      std::vector<double> vals(count);
      for (size_t k = 0; k < count; ++k) {
        vals[k] = gen.next(v.input.component(k % static_cast<size_t>(v.components)), v.is_double, d * count + k);
        if (v.scalar != 'f' && v.scalar != 'd') vals[k] = integer_value(vals[k], v.scalar);
      }
      values_[d].push_back(std::move(vals));
    }
  beyond_float_range_ = gen.beyond_float_range();
  if (beyond_float_range_ > 0) notes_.push_back(beyond_float_range_note(beyond_float_range_));
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ull);
  for (uint64_t d = 0; d < draws_; ++d) {
    std::vector<RelatedInput> related;
    for (size_t i = 0; i < inputs_.size(); ++i)
      related.push_back({inputs_[i].name, !inputs_[i].is_uniform, inputs_[i].components, inputs_[i].is_double,
                         &inputs_[i].input, &values_[d][i]});
    if (std::string note = apply_relations(relations_, related, rng); !note.empty() && d == 0) notes_.push_back(note);
  }
}

// A uniform block member's values (column-major) at its places in the block's bytes: the native
// place, or the lowered one(s) (hi then lo of a split member).
void GraphicsHarness::write_block_member(const Variable& v, const std::vector<double>& values, bool native,
                                         std::vector<uint8_t>* bytes) {
  const size_t rows = static_cast<size_t>(v.components / v.columns);
  const std::vector<BlockPlace> places = native ? std::vector<BlockPlace>{v.native_place} : v.lowered_places;
  for (size_t part = 0; part < places.size(); ++part)
    for (size_t k = 0; k < values.size(); ++k) {
      double x = values[k];
      if (places.size() == 2) {
        const FloatPair p = split(x);
        x = part == 0 ? p.hi : p.lo;
      }
      const BlockPlace& place = places[part];
      write_value(*bytes, place.offset + (k / rows) * place.column_stride + (k % rows) * scalar_width(place.is_double),
                  place.is_double, x, v.scalar);
    }
}

std::vector<runner::GraphicsJob> GraphicsHarness::jobs(bool native) const {
  std::vector<runner::GraphicsJob> out(draws_);
  for (uint64_t d = 0; d < draws_; ++d) {
    runner::GraphicsJob& job = out[d];
    job.stage = stage_;
    job.glsl = native ? native_glsl_ : lowered_glsl_;
    job.strict_fp64 = native && words_;  // mode exact is compared with fp64 evaluated as written
    job.count = per_draw_;
    for (const auto& [block, size] : native ? native_block_sizes_ : lowered_block_sizes_)
      job.uniform_blocks[block].assign(size, 0);
    for (size_t i = 0; i < inputs_.size(); ++i) {
      const Variable& v = inputs_[i];
      if (!v.block.empty()) {
        write_block_member(v, values_[d][i], native, &job.uniform_blocks[v.block]);
        continue;
      }
      const std::vector<std::string> names = native ? std::vector<std::string>{v.name} : v.lowered;
      if (!native && !v.word_components.empty()) {  // mode exact: uvec2/uvec4 words
        const auto parts = word_parts(values_[d][i], v.components, v.word_components);
        for (size_t part = 0; part < names.size(); ++part) {
          std::vector<double>& words = (v.is_uniform ? job.uniforms : job.inputs)[names[part]];
          words = parts[part];
          // A dmat3 uniform (9 doubles) fills 4.5 uvec4s of `uvec4 M[5]`: the last two words are unused.
          if (v.is_uniform && words.size() < size_t(v.word_components[part])) words.resize(size_t(v.word_components[part]), 0.0);
        }
        continue;
      }
      for (size_t part = 0; part < names.size(); ++part) {
        // A split pair gets hi in part 0 and lo in part 1; anything else gets the value itself.
        std::vector<double> vals = values_[d][i];
        if (names.size() == 2)
          for (double& x : vals) {
            const FloatPair p = split(x);
            x = part == 0 ? p.hi : p.lo;
          }
        (v.is_uniform ? job.uniforms : job.inputs)[names[part]] = std::move(vals);
      }
    }
  }
  return out;
}

std::string GraphicsHarness::describe_sample(uint64_t draw, uint32_t sample) const {
  std::string s;
  for (size_t i = 0; i < inputs_.size(); ++i) {
    const Variable& v = inputs_[i];
    const size_t comps = static_cast<size_t>(v.components);
    const size_t first = v.is_uniform ? 0 : sample * comps;
    s += (s.empty() ? "" : " ") + v.name + "=";
    if (comps > 1) s += "(";
    for (size_t c = 0; c < comps; ++c) s += (c ? ", " : "") + hex(values_[draw][i][first + c]);
    if (comps > 1) s += ")";
  }
  return (draws_ > 1 ? "draw " + std::to_string(draw) + " " : std::string()) + "sample " + std::to_string(sample) +
         ": " + s;
}

std::vector<std::string> GraphicsHarness::describe_inputs() const {
  std::vector<std::string> out;
  for (const Variable& v : inputs_)
    out.push_back(v.name + " (" + (v.is_uniform ? "uniform " : "in ") +
                  type_name(v.scalar, v.components, v.columns > 1) + ")");
  return out;
}

std::vector<OutputStats> GraphicsHarness::compare(const std::vector<runner::GraphicsResult>& native,
                                                  const std::vector<runner::GraphicsResult>& lowered,
                                                  std::optional<double> default_min_bits) const {
  std::vector<OutputStats> all;
  static const char* kComponent = "xyzw";
  for (const Variable& v : outputs_) {
    const int step = v.output.join_hi_lo ? 2 : 1;
    const size_t comps = static_cast<size_t>(v.components);
    for (int c = 0; c < v.components; c += step) {
      std::string name = v.name;
      if (v.components > 1) name += std::string(".") + std::string(kComponent + c, static_cast<size_t>(step));
      const std::string type = v.output.join_hi_lo ? "float hi+lo" : v.is_double ? "double" : "float";
      StatsBuilder stats(name, type, v.output.abs_floor.value_or(0x1p-126));
      for (uint64_t d = 0; d < draws_; ++d) {
        const std::vector<double>& want_v = native[d].outputs.at(v.name);
        const std::vector<double>& hi_v = lowered[d].outputs.at(v.lowered[0]);
        std::vector<const std::vector<double>*> word_outputs;
        for (const std::string& n : v.word_components.empty() ? std::vector<std::string>{} : v.lowered)
          word_outputs.push_back(&lowered[d].outputs.at(n));
        // A geometry or tessellation control sample has several records (records_).
        for (uint32_t s = 0; s < per_draw_ * records_; ++s) {
          const size_t k = s * comps + static_cast<size_t>(c);
          double want = want_v[k], got = word_outputs.empty() ? hi_v[k] : 0;
          if (!word_outputs.empty()) {
            got = joined_word(word_outputs, v.word_components, s, c);
          } else if (v.output.join_hi_lo) {
            want = join(static_cast<float>(want), static_cast<float>(want_v[k + 1]));
            got = join(static_cast<float>(got), static_cast<float>(hi_v[k + 1]));
          } else if (v.lowered.size() == 2) {
            got = join(static_cast<float>(got), static_cast<float>(lowered[d].outputs.at(v.lowered[1])[k]));
          }
          stats.add(got, want, d * per_draw_ * records_ + s);
        }
      }
      OutputStats s = stats.finish();
      const uint64_t sample = s.worst_sample / records_;
      s.worst_input = describe_sample(sample / per_draw_, static_cast<uint32_t>(sample % per_draw_));
      if (records_ > 1) s.worst_input += " (emitted vertex " + std::to_string(s.worst_sample % records_) + ")";
      s.min_bits_required = v.output.min_bits.value_or(default_min_bits.value_or(-1));
      s.max_abs_err_allowed = v.output.max_abs_error.value_or(-1);
      all.push_back(std::move(s));
    }
  }
  return all;
}

}  // namespace doublet::verify
