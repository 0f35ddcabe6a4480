// GLSL → SPIR-V with glslang, plus SPIRV-Tools validation, for the Vulkan backend.
#include <glslang/Include/Types.h>  // TType qualifiers for readonly/writeonly blocks
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv-tools/libspirv.hpp>

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <mutex>
#include <sstream>

#include "runner/internal.hpp"

namespace doublet::runner {
namespace detail {
namespace {

constexpr const char* kGlobalBlockName = "doublet_GlobalUniforms";
constexpr int kGlFloat = 0x1406;  // GL_FLOAT, glslang's reflection type code for `float`

// Components of a float/double scalar or vector reflection type (GL type codes), 0 otherwise.
int float_components(int gl_type, bool* is_double) {
  *is_double = false;
  switch (gl_type) {
    case 0x1406: return 1;  // GL_FLOAT
    case 0x8B50: return 2;  // GL_FLOAT_VEC2
    case 0x8B51: return 3;
    case 0x8B52: return 4;
  }
  *is_double = true;
  switch (gl_type) {
    case 0x140A: return 1;  // GL_DOUBLE
    case 0x8FFC: return 2;  // GL_DOUBLE_VEC2
    case 0x8FFD: return 3;
    case 0x8FFE: return 4;
  }
  *is_double = false;
  return 0;
}

// Columns and rows of a float/double matrix reflection type (GL type codes); false otherwise.
bool matrix_shape(int gl_type, bool* is_double, int* columns, int* rows) {
  struct Shape { int type, columns, rows; };
  static constexpr Shape kFloat[] = {{0x8B5A, 2, 2}, {0x8B5B, 3, 3}, {0x8B5C, 4, 4}, {0x8B65, 2, 3}, {0x8B66, 2, 4},
                                     {0x8B67, 3, 2}, {0x8B68, 3, 4}, {0x8B69, 4, 2}, {0x8B6A, 4, 3}};
  static constexpr Shape kDouble[] = {{0x8F46, 2, 2}, {0x8F47, 3, 3}, {0x8F48, 4, 4}, {0x8F49, 2, 3}, {0x8F4A, 2, 4},
                                      {0x8F4B, 3, 2}, {0x8F4C, 3, 4}, {0x8F4D, 4, 2}, {0x8F4E, 4, 3}};
  for (int d = 0; d < 2; ++d)
    for (const Shape& s : d ? kDouble : kFloat)
      if (s.type == gl_type) {
        *is_double = d == 1;
        *columns = s.columns;
        *rows = s.rows;
        return true;
      }
  return false;
}

// Components of an int/uint/bool scalar or vector reflection type (GL type codes) and its scalar
// letter ('i', 'u', 'b'); 0 otherwise.
int integer_components(int gl_type, char* scalar) {
  struct Shape { int type; char scalar; int components; };
  static constexpr Shape kShapes[] = {{0x1404, 'i', 1}, {0x8B53, 'i', 2}, {0x8B54, 'i', 3}, {0x8B55, 'i', 4},
                                      {0x1405, 'u', 1}, {0x8DC6, 'u', 2}, {0x8DC7, 'u', 3}, {0x8DC8, 'u', 4},
                                      {0x8B56, 'b', 1}, {0x8B57, 'b', 2}, {0x8B58, 'b', 3}, {0x8B59, 'b', 4}};
  for (const Shape& s : kShapes)
    if (s.type == gl_type) {
      *scalar = s.scalar;
      return s.components;
    }
  return 0;
}

// A uniform's shape: vectors as float_components, matrices as columns × rows values, int/uint/bool
// scalars and vectors by their scalar letter; 0 components for anything else (arrays included).
void uniform_shape(int gl_type, int size, char* scalar, int* components, int* columns) {
  *components = 0;
  *columns = 1;
  *scalar = 'f';
  if (size != 1) {
    // An array of 4-component integer vectors (mode exact's uvec4 matrix words): its std140 stride is
    // 16 bytes, so its components are consecutive.
    if (size > 1 && integer_components(gl_type, scalar) == 4) *components = 4 * size;
    return;
  }
  int rows = 0;
  bool is_double = false;
  if (matrix_shape(gl_type, &is_double, columns, &rows)) *components = *columns * rows;
  else if (int n = integer_components(gl_type, scalar); n > 0) *components = n;
  else *components = float_components(gl_type, &is_double);
  if (is_double) *scalar = 'd';
}

ShaderInterface::Uniform uniform_of(const glslang::TObjectReflection& u, std::string name) {
  ShaderInterface::Uniform out{std::move(name)};
  uniform_shape(u.glDefineType, u.size, &out.scalar, &out.components, &out.columns);
  out.is_double = out.scalar == 'd';
  return out;
}

// sampler2D/3D/Cube (GL type codes); false for any other opaque type.
bool sampler_kind(int gl_type, TextureKind* kind) {
  switch (gl_type) {
    case 0x8B5E: *kind = TextureKind::Tex2D; return true;  // GL_SAMPLER_2D
    case 0x8B5F: *kind = TextureKind::Tex3D; return true;  // GL_SAMPLER_3D
    case 0x8B60: *kind = TextureKind::Cube; return true;   // GL_SAMPLER_CUBE
  }
  return false;
}

uint32_t descriptor_set_of(const glslang::TObjectReflection& r) {
  const glslang::TType* t = r.getType();
  return t && t->getQualifier().hasSet() ? t->getQualifier().layoutSet : 0;
}

// glslang keeps process-wide state (symbol tables); initialise it once and serialise compiles.
std::mutex& glslang_mutex() {
  static std::mutex mu;
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
  return mu;
}

}  // namespace

namespace {

std::string strip_array_suffix(std::string name) {
  if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
  return name;
}

void reflect(const glslang::TProgram& program, ShaderInterface* iface) {
  for (int d = 0; d < 3; ++d) iface->local_size[d] = program.getLocalSize(d);
  std::map<int, size_t> named_block;  // reflection index of a named uniform block -> uniform_blocks
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    const glslang::TObjectReflection& b = program.getUniformBlock(i);
    if (b.name == kGlobalBlockName) continue;
    named_block[i] = iface->uniform_blocks.size();
    iface->uniform_blocks.push_back({b.name, static_cast<uint32_t>(std::max(b.size, 0)), {}});
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    TextureKind kind;
    if (u.index < 0) {
      if (sampler_kind(u.glDefineType, &kind)) iface->samplers.push_back(u.name);
      continue;
    }
    auto block = named_block.find(u.index);
    if (block == named_block.end()) {
      iface->uniforms.push_back(uniform_of(u, u.name));
      continue;
    }
    ShaderInterface::UniformBlock& b = iface->uniform_blocks[block->second];
    // Members of an instance-named block are reflected as "Block.member".
    std::string name = u.name.rfind(b.name + ".", 0) == 0 ? u.name.substr(b.name.size() + 1) : u.name;
    ShaderInterface::UniformBlockMember m;
    static_cast<ShaderInterface::Uniform&>(m) = uniform_of(u, std::move(name));
    m.offset = static_cast<uint32_t>(std::max(u.offset, 0));
    b.members.push_back(m);
  }
  for (int i = 0; i < program.getNumBufferBlocks(); ++i) {
    const glslang::TObjectReflection& b = program.getBufferBlock(i);
    ShaderInterface::Block out{b.name, b.getBinding()};
    if (const glslang::TType* t = b.getType()) {
      out.readonly = t->getQualifier().readonly;
      out.writeonly = t->getQualifier().writeonly;
    }
    out.fixed_size = static_cast<uint32_t>(std::max(b.size, 0));
    iface->blocks.push_back(out);
  }
  for (int i = 0; i < program.getNumBufferVariables(); ++i) {
    const glslang::TObjectReflection& v = program.getBufferVariable(i);
    ShaderInterface::Member m{strip_array_suffix(v.name), v.index, static_cast<uint32_t>(v.offset)};
    m.components = float_components(v.glDefineType, &m.is_double);
    const glslang::TType* t = v.getType();
    if (t && t->isArray()) {
      m.array_size = t->isUnsizedArray() ? 0 : static_cast<uint32_t>(t->getOuterArraySize());
      m.array_stride = static_cast<uint32_t>(v.arrayStride > 0 ? v.arrayStride : v.topLevelArrayStride);
      // A member array inside an array of structs has two strides: not fed or compared.
      if (v.topLevelArrayStride > 0 && v.arrayStride > 0 && m.name.find('.') != std::string::npos) m.components = 0;
    } else if (v.topLevelArrayStride > 0) {
      // A member of an array of structs (`Particle p[]` -> "p.pos"): one value per element of p.
      m.array_size = static_cast<uint32_t>(std::max(v.topLevelArraySize, 0));
      m.array_stride = static_cast<uint32_t>(v.topLevelArrayStride);
    }
    iface->members.push_back(m);
  }
}

}  // namespace

bool compile_glsl(const std::string& glsl, SpirvProgram* out, std::string* error, ShaderInterface* iface,
                  bool strict_fp64) {
  return compile_glsl_stages({{Stage::Compute, glsl}}, out, error, iface, strict_fp64);
}

// SPIR-V 1.6 specification, 2.3 (physical layout) and 3.32 (opcodes): types before the code,
// decorations before the types.
void decorate_fp64_no_contraction(std::vector<uint32_t>& words) {
  constexpr uint32_t kOpTypeFloat = 22, kOpTypeVector = 23, kOpTypeMatrix = 24, kOpDecorate = 71;
  constexpr uint32_t kNoContraction = 42;
  // OpFNegate ... OpMatrixTimesMatrix, and OpExtInst (12): Mesa expands GLSL.std.450 built-ins
  // (refract, reflect, normalize, ...) into arithmetic that is exact only when the call's result
  // is NoContraction; otherwise NIR may reassociate it (docs/robustness.md, "Differential testing").
  static const std::set<uint32_t> kNoContractionOpcodes = {12, 127, 129, 131, 133, 136, 140, 141, 142, 143, 144, 145, 146, 147, 148};
  // Before the first instruction that is not a mode-setting, debug or annotation one.
  static const std::set<uint32_t> kPreamble = {2,  3,  4,  5,  6,  7,  8,  10, 11, 14, 15, 16,  17,
                                               71, 72, 73, 74, 317, 330, 331, 332, 5632, 5633};
  std::set<uint32_t> fp64_types, results;
  size_t insert_at = 0;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffff;
    if (count == 0 || i + count > words.size()) return;  // malformed: the validator says so
    if (!insert_at && !kPreamble.count(opcode)) insert_at = i;
    if (opcode == kOpTypeFloat && words[i + 2] == 64) fp64_types.insert(words[i + 1]);
    if ((opcode == kOpTypeVector || opcode == kOpTypeMatrix) && fp64_types.count(words[i + 2])) fp64_types.insert(words[i + 1]);
    if (kNoContractionOpcodes.count(opcode) && count >= 3 && fp64_types.count(words[i + 1])) results.insert(words[i + 2]);
    i += count;
  }
  std::vector<uint32_t> decorations;
  for (uint32_t id : results) decorations.insert(decorations.end(), {(3u << 16) | kOpDecorate, id, kNoContraction});
  if (insert_at) words.insert(words.begin() + static_cast<std::ptrdiff_t>(insert_at), decorations.begin(), decorations.end());
}

namespace {

// The members of the uniform block named `block` as the SPIR-V lays them out: byte offset by
// reflection name ("p.scale.hi"; element 0 of an array, as glslang's reflection names it: "ps.n").
// glslang's reflection gives a member that follows a nested struct member its offset without
// std140's rounding of the struct to 16 bytes (8 where the SPIR-V says 16), so the runner takes
// the SPIR-V's word for every member. Empty when the module has no such block.
std::map<std::string, uint32_t> block_member_offsets(const std::vector<uint32_t>& words, const std::string& block) {
  constexpr uint32_t kOpName = 5, kOpMemberName = 6, kOpTypeArray = 28, kOpTypeStruct = 30, kOpMemberDecorate = 72;
  constexpr uint32_t kDecorationOffset = 35;
  auto text = [&](size_t at, size_t end) {
    std::string s;
    for (size_t i = at; i < end; ++i)
      for (int b = 0; b < 4; ++b) {
        const char c = static_cast<char>((words[i] >> (8 * b)) & 0xff);
        if (c == '\0') return s;
        s += c;
      }
    return s;
  };
  std::map<uint32_t, std::string> names;
  std::map<uint32_t, std::map<uint32_t, std::string>> member_names;
  std::map<uint32_t, std::map<uint32_t, uint32_t>> member_offsets;
  std::map<uint32_t, std::vector<uint32_t>> struct_members;
  std::map<uint32_t, uint32_t> array_element;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffff;
    if (count == 0 || i + count > words.size()) break;  // malformed; the validator reports it
    if (opcode == kOpName && count > 2) names[words[i + 1]] = text(i + 2, i + count);
    if (opcode == kOpMemberName && count > 3) member_names[words[i + 1]][words[i + 2]] = text(i + 3, i + count);
    if (opcode == kOpMemberDecorate && count > 4 && words[i + 3] == kDecorationOffset)
      member_offsets[words[i + 1]][words[i + 2]] = words[i + 4];
    if (opcode == kOpTypeStruct && count > 1) struct_members[words[i + 1]].assign(words.begin() + i + 2, words.begin() + i + count);
    if (opcode == kOpTypeArray && count > 3) array_element[words[i + 1]] = words[i + 2];
    i += count;
  }
  std::map<std::string, uint32_t> offsets;
  auto walk = [&](auto&& self, uint32_t type, const std::string& prefix, uint32_t base) -> void {
    const std::vector<uint32_t>& members = struct_members[type];
    for (uint32_t m = 0; m < members.size(); ++m) {
      const std::string name = prefix + member_names[type][m];
      const uint32_t offset = base + member_offsets[type][m];
      uint32_t member_type = members[m];
      while (array_element.count(member_type)) member_type = array_element[member_type];
      if (struct_members.count(member_type)) self(self, member_type, name + ".", offset);
      else offsets[name] = offset;
    }
  };
  for (const auto& [id, name] : names)
    if (name == block && struct_members.count(id)) walk(walk, id, "", 0);
  return offsets;
}

}  // namespace

bool compile_glsl_stages(const std::vector<std::pair<Stage, std::string>>& stages, SpirvProgram* out,
                         std::string* error, ShaderInterface* iface, bool strict_fp64) {
  std::lock_guard<std::mutex> lock(glslang_mutex());
  const EShMessages messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  // Per stage: glslang's language, the name its log uses, and where its SPIR-V goes.
  struct StageInfo {
    EShLanguage language;
    const char* name;
    std::vector<uint32_t> SpirvProgram::*words;
  };
  auto info = [](Stage s) -> StageInfo {
    switch (s) {
      case Stage::Vertex: return {EShLangVertex, "job.vert", &SpirvProgram::words};
      case Stage::Fragment: return {EShLangFragment, "job.frag", &SpirvProgram::fragment_words};
      case Stage::Geometry: return {EShLangGeometry, "job.geom", &SpirvProgram::geometry_words};
      case Stage::TessControl: return {EShLangTessControl, "job.tesc", &SpirvProgram::tess_control_words};
      case Stage::TessEvaluation: return {EShLangTessEvaluation, "job.tese", &SpirvProgram::tess_evaluation_words};
      default: return {EShLangCompute, "job.comp", &SpirvProgram::words};
    }
  };

  std::vector<std::unique_ptr<glslang::TShader>> shaders;
  glslang::TProgram program;
  for (const auto& [stage, glsl] : stages) {
    const EShLanguage lang = info(stage).language;
    auto shader = std::make_unique<glslang::TShader>(lang);
    const char* text = glsl.c_str();
    const char* name = info(stage).name;
    shader->setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
    shader->setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    // Relaxed rules accept GL-style text (loose uniforms, no explicit bindings), which is what the
    // compiler under test emits; loose uniforms go to one block we fill from reflection.
    shader->setEnvInputVulkanRulesRelaxed();
    shader->setAutoMapBindings(true);
    shader->setAutoMapLocations(true);
    shader->setGlobalUniformBlockName(kGlobalBlockName);
    shader->setGlobalUniformSet(kUniformSet);
    shader->setGlobalUniformBinding(kUniformBinding);
    if (!shader->parse(GetDefaultResources(), 100, false, messages)) {
      *error = std::string("GLSL compile failed (glslang, ") + name + "):\n" + shader->getInfoLog() +
               shader->getInfoDebugLog();
      return false;
    }
    program.addShader(shader.get());
    shaders.push_back(std::move(shader));
  }
  if (!program.link(messages) || !program.mapIO()) {
    *error = std::string("GLSL link failed (glslang):\n") + program.getInfoLog() + program.getInfoDebugLog();
    return false;
  }
  // SeparateBuffers: SSBOs are listed as buffer blocks, not mixed into the uniform blocks.
  if (!program.buildReflection(EShReflectionSeparateBuffers)) {
    *error = "glslang reflection failed";
    return false;
  }

  SpirvProgram result;
  if (iface) reflect(program, iface);
  int global_block = -1;
  for (int i = 0; i < program.getNumUniformBlocks(); ++i) {
    const glslang::TObjectReflection& block = program.getUniformBlock(i);
    if (block.name == kGlobalBlockName) {
      global_block = i;
      result.uniform_block_size = static_cast<uint32_t>(block.size);
      continue;
    }
    if (block.size < 0 || block.getBinding() < 0 || (block.getType() && block.getType()->isArray())) {
      *error = "unsupported: uniform block '" + block.name + "' (arrays of blocks are not fed by the runner)";
      return false;
    }
    result.uniform_blocks.push_back({block.name, descriptor_set_of(block), static_cast<uint32_t>(block.getBinding()),
                                     static_cast<uint32_t>(block.size), TextureKind::Tex2D});
  }
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    if (u.index < 0) {
      TextureKind kind;
      if (!sampler_kind(u.glDefineType, &kind) || u.size != 1 || u.getBinding() < 0) {
        *error = "unsupported: opaque uniform '" + u.name +
                 "' (the runner binds its test texture to sampler2D, sampler3D and samplerCube only, not arrays)";
        return false;
      }
      result.samplers.push_back({u.name, descriptor_set_of(u), static_cast<uint32_t>(u.getBinding()), 0, kind});
      continue;
    }
    if (u.index != global_block) continue;  // a member of a named block: the job gives the block's bytes
    UniformSlot slot{static_cast<uint32_t>(u.offset), u.glDefineType == kGlFloat && u.size == 1};
    uniform_shape(u.glDefineType, u.size, &slot.scalar, &slot.components, &slot.columns);
    slot.is_double = slot.scalar == 'd';
    result.uniforms[u.name] = slot;
  }
  for (int i = 0; i < program.getNumBufferBlocks(); ++i) result.ssbo_bindings.push_back(program.getBufferBlock(i).getBinding());

  glslang::SpvOptions options;
  options.disableOptimizer = true;  // the driver's optimizer is what we want to observe, not spirv-opt's
  options.validate = false;         // validated below with a readable message
  for (size_t i = 0; i < stages.size(); ++i) {
    const StageInfo stage = info(stages[i].first);
    std::vector<uint32_t>& words = result.*stage.words;
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(stage.language), words, &logger, &options);
    if (words.empty()) {
      *error = "glslang produced no SPIR-V: " + logger.getAllMessages();
      return false;
    }
    if (strict_fp64) decorate_fp64_no_contraction(words);
    if (std::string v = validate_spirv(words); !v.empty()) {
      *error = "invalid SPIR-V: " + v;
      return false;
    }
  }
  for (const std::vector<uint32_t>* words : {&result.words, &result.fragment_words, &result.geometry_words,
                                             &result.tess_control_words, &result.tess_evaluation_words}) {
    const std::map<std::string, uint32_t> offsets = block_member_offsets(*words, kGlobalBlockName);
    if (offsets.empty()) continue;
    for (auto& [name, slot] : result.uniforms)
      if (auto it = offsets.find(name); it != offsets.end()) slot.offset = it->second;
    // The block ends after its last member; 128 bytes cover any scalar, vector or matrix (dmat4).
    for (const auto& [name, offset] : offsets)
      result.uniform_block_size = std::max(result.uniform_block_size, offset + 128);
    break;
  }
  *out = std::move(result);
  return true;
}

bool spirv_uses_float64(const std::vector<uint32_t>& words) {
  constexpr uint32_t kOpCapability = 17, kCapabilityFloat64 = 10;
  for (size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, opcode = words[i] & 0xffff;
    if (count == 0) break;  // malformed; the validator reports it
    if (opcode == kOpCapability && i + 1 < words.size() && words[i + 1] == kCapabilityFloat64) return true;
    i += count;
  }
  return false;
}

}  // namespace detail

std::string validate_spirv(const std::vector<uint32_t>& spirv) {
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  std::ostringstream messages;
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
    messages << "word " << pos.index << ": " << msg << "\n";
  });
  if (tools.Validate(spirv)) return {};
  std::string text = messages.str();
  return text.empty() ? "validator rejected the module without a message" : text;
}

bool reflect_compute(const std::string& glsl, ShaderInterface* out, std::string* error) {
  detail::SpirvProgram program;
  *out = ShaderInterface{};
  return detail::compile_glsl(glsl, &program, error, out);
}

bool compile_compute_to_spirv(const std::string& glsl, std::vector<uint32_t>* spirv, std::string* error) {
  detail::SpirvProgram program;
  if (!detail::compile_glsl(glsl, &program, error)) return false;
  *spirv = std::move(program.words);
  return true;
}

}  // namespace doublet::runner
