#include "runner/graphics_wrapper.hpp"

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <vector>
#include <sstream>

namespace doublet::runner::detail {
namespace {

// A whole-line global declaration: [layout(...)] [interpolation/precision...] in|out [precision] TYPE names;
// (ES 1.00 spells them attribute and varying).
const std::regex& declaration() {
  static const std::regex re(
      R"(^\s*(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid|sample|invariant|precise|patch|highp|mediump|lowp)\s+)*)"
      R"((in|out|attribute|varying)\s+((?:highp|mediump|lowp)\s+)?([A-Za-z_]\w*)\s+([A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*)\s*)"
      R"((\[\s*(\d*)\s*\])?\s*;\s*(?://.*)?$)");
  return re;
}

// Anything that starts like an in/out declaration; what `declaration` does not take is unsupported.
const std::regex& looks_like_declaration() {
  static const std::regex re(
      R"(^\s*(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid|sample|invariant|precise|patch|highp|mediump|lowp)\s+)*(in|out|attribute|varying)\s+\w)");
  return re;
}

// Where the next line starts: inside a block comment or not, and at which depth of braces and
// parentheses. Only a line that starts at depth 0 outside a comment can be a global declaration;
// `out dvec3 p,` on its own line inside a parameter list is not.
struct Scope {
  int braces = 0, parens = 0;
  bool in_comment = false;
  bool global() const { return braces == 0 && parens == 0 && !in_comment; }
  void advance(const std::string& line) {
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i], next = i + 1 < line.size() ? line[i + 1] : '\0';
      if (in_comment) {
        if (c == '*' && next == '/') in_comment = false, ++i;
        continue;
      }
      if (c == '/' && next == '/') return;
      if (c == '/' && next == '*') in_comment = true, ++i;
      else if (c == '{') ++braces;
      else if (c == '}') --braces;
      else if (c == '(') ++parens;
      else if (c == ')') --parens;
    }
  }
};

using Renames = std::vector<std::pair<std::regex, const char*>>;

std::string apply_renames(const std::string& line, const Renames& renames) {
  std::string out = line;
  for (const auto& [re, replacement] : renames) out = std::regex_replace(out, re, replacement);
  return out;
}

// Built-ins the wrapped text cannot use as written: ES 1.00/compatibility fragment outputs become
// plain globals (stored like any output), ES 1.00 texture functions their ES 3.10 name.
std::string rename_legacy_builtins(const std::string& line) {
  static const Renames kRenames = {{std::regex(R"(\bgl_FragColor\b)"), "doublet_FragColor"},
                                   {std::regex(R"(\bgl_FragData\b)"), "doublet_FragData"},
                                   {std::regex(R"(\btexture2D\b)"), "texture"},
                                   {std::regex(R"(\btextureCube\b)"), "texture"}};
  return apply_renames(line, kRenames);
}

constexpr int kFragDataSlots = 4;  // gl_FragData[0..3]


// float/vecN, double/dvecN, int/ivecN, uint/uvecN → scalar letter and components.
bool parse_type(const std::string& type, char* scalar, int* components) {
  static const std::pair<const char*, char> kScalars[] = {{"float", 'f'}, {"double", 'd'}, {"int", 'i'}, {"uint", 'u'}};
  static const std::pair<const char*, char> kVectors[] = {{"vec", 'f'}, {"dvec", 'd'}, {"ivec", 'i'}, {"uvec", 'u'}};
  for (const auto& [name, s] : kScalars)
    if (type == name) {
      *scalar = s;
      *components = 1;
      return true;
    }
  for (const auto& [prefix, s] : kVectors) {
    const std::string p = prefix;
    if (type.size() == p.size() + 1 && type.compare(0, p.size(), p) == 0 && type.back() >= '2' && type.back() <= '4') {
      *scalar = s;
      *components = type.back() - '0';
      return true;
    }
  }
  return false;
}

// `[layout(...)] in|out Block {` opening an interface block on its own line.
const std::regex& block_start() {
  static const std::regex re(R"(^\s*(?:layout\s*\([^)]*\)\s*)?(in|out)\s+([A-Za-z_]\w*)\s*\{\s*(?://.*)?$)");
  return re;
}
// `} [instance];` closing it (an instance array is not supported).
const std::regex& block_end() {
  static const std::regex re(R"(^\s*\}\s*([A-Za-z_]\w*)?\s*;\s*(?://.*)?$)");
  return re;
}
// One member line: [interpolation/precision...] TYPE names;
const std::regex& block_member() {
  static const std::regex re(
      R"(^\s*(?:(?:flat|smooth|noperspective|centroid|sample|invariant|precise|highp|mediump|lowp)\s+)*)"
      R"(([A-Za-z_]\w*)\s+([A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*)\s*;\s*(?://.*)?$)");
  return re;
}

// An `in`/`out` interface block becomes a plain global struct (`out V { vec3 n; } v_out;` ->
// `struct doublet_block_V { vec3 n; }; doublet_block_V v_out;`, variables "v_out.n") or, without
// an instance name, plain globals; its members are captured like any in/out variable. `lines`
// holds the block from its opening line to its closing one. Empty on success, else why not.
std::string wrap_block(const std::vector<std::string>& lines, const std::string& block, std::string* text,
                       std::vector<StageVariable>* vars) {
  std::smatch end;
  if (!std::regex_match(lines.back(), end, block_end()))
    return "interface block '" + block + "' must end with '} instance;' on a line of its own";
  const std::string instance = end[1].matched ? end[1].str() : "";
  std::string members;
  for (size_t i = 1; i + 1 < lines.size(); ++i) {
    std::smatch m;
    if (lines[i].find_first_not_of(" \t") == std::string::npos) continue;
    StageVariable v;
    if (!std::regex_match(lines[i], m, block_member()) || !parse_type(m[1], &v.scalar, &v.components))
      return "interface block '" + block + "': unsupported member (one float/double/int/uint scalar or vector " +
             "declaration per line): " + lines[i];
    std::string names = m[2];
    std::replace(names.begin(), names.end(), ',', ' ');
    std::istringstream split(names);
    for (std::string name; split >> name;) {
      v.name = instance.empty() ? name : instance + "." + name;
      vars->push_back(v);
      members += " " + std::string(m[1]) + " " + name + ";";
    }
  }
  if (instance.empty()) *text += members.substr(1) + "  // was: block " + block + "\n";
  else *text += "struct doublet_block_" + block + " {" + members + " };\ndoublet_block_" + block + " " + instance + ";\n";
  return {};
}

std::string type_name(const StageVariable& v) {
  static const char* kScalar[] = {"float", "double", "int", "uint"};
  static const char* kVector[] = {"vec", "dvec", "ivec", "uvec"};
  const int k = v.scalar == 'f' ? 0 : v.scalar == 'd' ? 1 : v.scalar == 'i' ? 2 : 3;
  return v.components == 1 ? kScalar[k] : kVector[k] + std::to_string(v.components);
}

// std430 offsets of the variables as members of one struct; returns the struct's array stride.
uint32_t lay_out(std::vector<StageVariable>& vars) {
  uint32_t offset = 0, struct_align = 4;
  for (StageVariable& v : vars) {
    const uint32_t scalar = v.scalar == 'd' ? 8 : 4;
    const uint32_t align = scalar * (v.components == 1 ? 1 : v.components == 2 ? 2 : 4);
    offset = (offset + align - 1) / align * align;
    v.offset = offset;
    offset += scalar * static_cast<uint32_t>(v.components);
    struct_align = std::max(struct_align, align);
  }
  return (offset + struct_align - 1) / struct_align * struct_align;
}

std::string struct_decl(const char* name, const std::vector<StageVariable>& vars) {
  std::string s = std::string("struct ") + name + " {";
  for (size_t i = 0; i < vars.size(); ++i) s += " " + type_name(vars[i]) + " m" + std::to_string(i) + ";";
  return s + " };\n";
}

// Geometry: vertices per input primitive, from `layout(triangles) in;` (0 when not declared).
uint32_t geometry_input_vertices(const std::string& glsl) {
  static const std::regex re(R"(layout\s*\(\s*(points|lines_adjacency|lines|triangles_adjacency|triangles)\b[^)]*\)\s*in\s*;)");
  std::smatch m;
  if (!std::regex_search(glsl, m, re)) return 0;
  static const std::pair<const char*, uint32_t> kVertices[] = {
      {"points", 1}, {"lines", 2}, {"lines_adjacency", 4}, {"triangles", 3}, {"triangles_adjacency", 6}};
  for (const auto& [name, n] : kVertices)
    if (m[1] == name) return n;
  return 0;
}

// Geometry: `max_vertices = N` of the output layout (0 when not declared).
uint32_t geometry_max_vertices(const std::string& glsl) {
  static const std::regex re(R"(max_vertices\s*=\s*(\d+))");
  std::smatch m;
  return std::regex_search(glsl, m, re) ? static_cast<uint32_t>(std::stoul(m[1])) : 0;
}

// Tessellation evaluation: the vertices of the domain (its per-vertex input array elements fed).
uint32_t tessellation_domain_vertices(const std::string& glsl) {
  static const std::regex re(R"(layout\s*\(\s*(triangles|quads|isolines)\b[^)]*\)\s*in\s*;)");
  std::smatch m;
  if (!std::regex_search(glsl, m, re)) return 0;
  return m[1] == "triangles" ? 3 : m[1] == "quads" ? 4 : 2;
}

// Tessellation control: `layout(vertices = N) out;` (0 when not declared).
uint32_t tessellation_output_vertices(const std::string& glsl) {
  static const std::regex re(R"(layout\s*\(\s*vertices\s*=\s*(\d+)\s*\)\s*out\s*;)");
  std::smatch m;
  return std::regex_search(glsl, m, re) ? static_cast<uint32_t>(std::stoul(m[1])) : 0;
}

// Geometry and tessellation: the built-ins the wrapped text cannot use as written. gl_in (and a
// control shader's gl_out and tessellation levels) become global arrays, the inputs loaded from the
// input buffer; gl_TessCoord a global loaded from it. EmitVertex() stores the outputs
// (doublet_emit, in the wrapper's main part), EndPrimitive() and barrier() do nothing (no primitive
// is rasterized; a control shader's outputs are its own, see the wrapper's main).
std::string rename_primitive_builtins(const std::string& line) {
  static const Renames kRenames = {{std::regex(R"(\bgl_in\b)"), "doublet_gl_in"},
                                   {std::regex(R"(\bgl_out\b)"), "doublet_gl_out"},
                                   // members of the stand-in structs: GLES compilers refuse gl_ names there
                                   {std::regex(R"(\.\s*gl_Position\b)"), ".doublet_position"},
                                   {std::regex(R"(\.\s*gl_PointSize\b)"), ".doublet_point_size"},
                                   {std::regex(R"(\bgl_TessCoord\b)"), "doublet_tess_coord"},
                                   {std::regex(R"(\bgl_TessLevelOuter\b)"), "doublet_tess_level_outer"},
                                   {std::regex(R"(\bgl_TessLevelInner\b)"), "doublet_tess_level_inner"},
                                   {std::regex(R"(\bbarrier\s*\(\s*\))"), "doublet_barrier()"},
                                   {std::regex(R"(\bEmitVertex\s*\(\s*\))"), "doublet_emit()"},
                                   {std::regex(R"(\bEndPrimitive\s*\(\s*\))"), "doublet_end_primitive()"}};
  return apply_renames(line, kRenames);
}

// gl_VertexIndex under Vulkan (glslang defines VULKAN), gl_VertexID under GL.
constexpr const char* kVertexIndexMacro =
    "#ifdef VULKAN\n#define doublet_vertex_index gl_VertexIndex\n#else\n#define doublet_vertex_index gl_VertexID\n#endif\n";

}  // namespace

std::string wrap_graphics(GraphicsStage stage, const std::string& glsl, WrappedProgram* out) {
  *out = WrappedProgram{};
  std::istringstream in(glsl);
  std::string line, body, version;
  static const std::regex version_re(R"(^\s*#\s*version\s+(\d+)\s*(es)?\s*(?:core)?\s*(?://.*)?$)");
  int line_number = 0;
  Scope scope;
  std::string legacy_outputs;  // declarations of the renamed fragment outputs, after the #version line
  std::vector<std::string> block_lines;  // an interface block being read, from its opening line
  const bool geometry = stage == GraphicsStage::Geometry, control = stage == GraphicsStage::TessControl,
             evaluation = stage == GraphicsStage::TessEvaluation;
  const bool per_primitive = geometry || control || evaluation;  // a sample is a primitive or a patch
  static const std::regex reads_gl_in(R"(\bgl_in\b)"), reads_tess_coord(R"(\bgl_TessCoord\b)"),
      writes_gl_out(R"(\bgl_out\b)"), tess_outer(R"(\bgl_TessLevelOuter\b)"), tess_inner(R"(\bgl_TessLevelInner\b)");
  // Declarations the user's text needs, placed before its first line of code (after the #version
  // and #extension lines).
  std::string preamble;
  uint32_t elements = 1;  // elements of a per-vertex input array that are fed
  std::map<std::string, std::string> stored_as;  // an output stored other than by its name
  if (geometry) {
    out->iface.input_vertices = elements = geometry_input_vertices(glsl);
    out->iface.records_per_sample = geometry_max_vertices(glsl);
    if (out->iface.input_vertices == 0 || out->iface.records_per_sample == 0)
      return "a geometry shader needs its input primitive (layout(triangles) in;) and max_vertices declared";
    preamble = "void doublet_emit();\nvoid doublet_end_primitive();\n";
  } else if (evaluation) {
    // One patch of one control point per sample, tessellated at level 1: the corner the wrapper
    // stores from (main, below) evaluates the user's code at the sample's own gl_TessCoord.
    elements = tessellation_domain_vertices(glsl);
    if (elements == 0) return "a tessellation evaluation shader needs its domain declared (layout(triangles) in;)";
    if (std::regex_search(glsl, reads_tess_coord)) preamble += "vec3 doublet_tess_coord;\n";
  } else if (control) {
    out->iface.input_vertices = out->iface.records_per_sample = elements = tessellation_output_vertices(glsl);
    if (elements == 0) return "a tessellation control shader needs its output patch size declared (layout(vertices = 3) out;)";
    preamble = "void doublet_barrier() {}\nfloat doublet_tess_level_outer[4];\nfloat doublet_tess_level_inner[2];\n";
    if (std::regex_search(glsl, writes_gl_out))
      preamble += "struct doublet_PerVertexOut { vec4 doublet_position; float doublet_point_size; };\ndoublet_PerVertexOut doublet_gl_out[" +
                  std::to_string(elements) + "];\n";
  }
  if (per_primitive && std::regex_search(glsl, reads_gl_in))
    preamble += "struct doublet_PerVertex { vec4 doublet_position; };\ndoublet_PerVertex doublet_gl_in[" +
                std::to_string(elements) + "];\n";
  while (std::getline(in, line)) {
    ++line_number;
    const bool global = scope.global();
    scope.advance(line);
    if (!preamble.empty() && !version.empty() && global) {
      const size_t first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] != '#' && line.compare(first, 2, "//") != 0) {
        body += preamble;
        preamble.clear();
      }
    }
    std::smatch m;
    if (!block_lines.empty()) {
      block_lines.push_back(line);
      if (!scope.global()) continue;
      std::smatch start;
      std::regex_match(block_lines.front(), start, block_start());
      const bool is_input = start[1] == "in";
      if (std::string e = wrap_block(block_lines, start[2], &body, is_input ? &out->iface.inputs : &out->iface.outputs);
          !e.empty())
        return "line " + std::to_string(line_number) + ": " + e;
      block_lines.clear();
      continue;
    }
    if (global && std::regex_match(line, m, block_start())) {
      block_lines.push_back(line);
      continue;
    }
    if (version.empty() && std::regex_match(line, m, version_re)) {
      const std::string number = m[1];
      const bool es = m[2].matched || number == "100";
      // ES 1.00 and 3.00 run as 3.10 (the buffers need it), desktop 3.30 as 4.50: both supersets
      // once the wrapper has replaced the declarations and built-ins 3.10/4.50 lack.
      if (number == "100" || (es && (number == "300" || number == "310"))) version = "#version 310 es";
      else if (es && number == "320") version = "#version 320 es";
      else if (!es && (number == "450" || number == "330")) version = "#version 450";
      else return "unsupported '#version " + number + (es ? " es" : "") + "' for a vertex/fragment run (100, 300 es, 310 es, 320 es, 330, 450)";
      out->es = es;
      body += version + "\n#define main doublet_user_main\n";
      continue;
    }
    if (global && std::regex_match(line, m, declaration())) {
      StageVariable v;
      if (!parse_type(m[3], &v.scalar, &v.components))
        return "line " + std::to_string(line_number) + ": unsupported " + std::string(m[1]) + " type '" +
               std::string(m[3]) + "' (float/double/int/uint scalars and vectors)";
      const bool is_input = m[1] == "in" || m[1] == "attribute" || (m[1] == "varying" && stage == GraphicsStage::Fragment);
      std::string names = m[4];
      // Geometry and tessellation per-vertex inputs are arrays, one element per vertex: each element
      // is an input of its own. A control shader's per-vertex output is one output per record,
      // stored from the invocation's own element.
      const bool per_vertex = per_primitive && is_input && m[5].matched;
      const bool own_vertex = control && !is_input && m[5].matched;
      if (m[5].matched && !per_vertex && !own_vertex)
        return "line " + std::to_string(line_number) + ": unsupported in/out declaration (arrays only as the "
               "per-vertex inputs of geometry and tessellation shaders): " + line;
      if ((per_vertex || own_vertex) && names.find(',') != std::string::npos)
        return "line " + std::to_string(line_number) + ": one per-vertex array per declaration: " + line;
      // The declared size, else the vertices fed (a control shader's inputs are gl_MaxPatchVertices
      // long where the lowered text says so; only the first `elements` are fed).
      const std::string declared = m[6].matched ? m[6].str() : "";  // may be empty: `p[]`
      const std::string size = declared.empty() ? std::to_string(elements) : declared;
      std::replace(names.begin(), names.end(), ',', ' ');
      std::istringstream split(names);
      for (std::string name; split >> name;) {
        for (uint32_t k = 0; k < (per_vertex ? elements : 1); ++k) {
          v.name = per_vertex ? name + "[" + std::to_string(k) + "]" : name;
          (is_input ? out->iface.inputs : out->iface.outputs).push_back(v);
        }
        if (own_vertex) stored_as[name] = name + "[gl_InvocationID]";
      }
      body += std::string(m[2]) + std::string(m[3]) + " " + std::string(m[4]) +
              (per_vertex || own_vertex ? "[" + size + "]" : "") + ";  // was: " + line + "\n";
      continue;
    }
    if (global && std::regex_search(line, looks_like_declaration()))
      return "line " + std::to_string(line_number) + ": unsupported in/out declaration (one per line, no arrays, " +
             "blocks or structs): " + line;
    body += (per_primitive ? rename_primitive_builtins(line) : rename_legacy_builtins(line)) + "\n";
  }
  if (!block_lines.empty()) return "an interface block does not end: " + block_lines.front();
  if (version.empty()) return "the shader has no #version line";
  if (stage == GraphicsStage::Vertex && glsl.find("gl_Position") != std::string::npos)
    out->iface.outputs.push_back(StageVariable{"gl_Position", 'f', 4});
  if (per_primitive) {
    static const std::regex writes_position(R"((^|[^.\w])gl_Position\s*=[^=])");
    if (std::regex_search(glsl, reads_gl_in))
      for (uint32_t k = 0; k < elements; ++k)
        out->iface.inputs.push_back(StageVariable{"gl_in[" + std::to_string(k) + "].gl_Position", 'f', 4});
    if (evaluation && std::regex_search(glsl, reads_tess_coord))
      out->iface.inputs.push_back(StageVariable{"gl_TessCoord", 'f', 3});
    if (!control && std::regex_search(glsl, writes_position)) out->iface.outputs.push_back(StageVariable{"gl_Position", 'f', 4});
    if (control && std::regex_search(glsl, tess_outer)) {
      out->iface.outputs.push_back(StageVariable{"gl_TessLevelOuter", 'f', 4});
      stored_as["gl_TessLevelOuter"] = "vec4(doublet_tess_level_outer[0], doublet_tess_level_outer[1], "
                                       "doublet_tess_level_outer[2], doublet_tess_level_outer[3])";
    }
    if (control && std::regex_search(glsl, tess_inner)) {
      out->iface.outputs.push_back(StageVariable{"gl_TessLevelInner", 'f', 2});
      stored_as["gl_TessLevelInner"] = "vec2(doublet_tess_level_inner[0], doublet_tess_level_inner[1])";
    }
  }
  if (stage == GraphicsStage::Fragment) {
    if (std::regex_search(glsl, std::regex(R"(\bgl_FragColor\b)"))) {
      out->iface.outputs.push_back(StageVariable{"gl_FragColor", 'f', 4});
      legacy_outputs += "highp vec4 doublet_FragColor;\n";
    }
    // The gl_FragData slots the text names with a constant index, each an output.
    std::set<int> slots;
    static const std::regex frag_data(R"(\bgl_FragData\s*\[\s*(\d+)\s*\])");
    for (std::sregex_iterator it(glsl.begin(), glsl.end(), frag_data), end; it != end; ++it)
      if (const int k = std::stoi((*it)[1].str()); k < kFragDataSlots) slots.insert(k);
    for (int k : slots) out->iface.outputs.push_back(StageVariable{"gl_FragData[" + std::to_string(k) + "]", 'f', 4});
    if (std::regex_search(glsl, std::regex(R"(\bgl_FragData\b)")))
      legacy_outputs += "highp vec4 doublet_FragData[" + std::to_string(kFragDataSlots) + "];\n";
    // Inserted after "#define main ..." so that the user's text can use them.
    const std::string anchor = "#define main doublet_user_main\n";
    if (const size_t at = body.find(anchor); at != std::string::npos) body.insert(at + anchor.size(), legacy_outputs);
  }
  if (out->iface.outputs.empty()) return "the shader has no outputs to compare";
  out->iface.input_stride = lay_out(out->iface.inputs);
  out->iface.output_stride = lay_out(out->iface.outputs);

  out->user_text = body;
  std::string w = "#undef main\n";
  if (out->es) w += "precision highp float;\nprecision highp int;\n";
  if (stage == GraphicsStage::Vertex) w += kVertexIndexMacro;
  w += "#ifdef VULKAN\n#define doublet_wrapper_set set = " + std::to_string(kWrapperSet) +
       ",\n#else\n#define doublet_wrapper_set\n#endif\n";
  if (!out->iface.inputs.empty())
    w += struct_decl("doublet_In", out->iface.inputs) + "layout(std430, doublet_wrapper_set binding = " +
         std::to_string(kInputBinding) + ") readonly buffer doublet_Inputs { doublet_In doublet_in[]; };\n";
  w += struct_decl("doublet_Out", out->iface.outputs) + "layout(std430, doublet_wrapper_set binding = " +
       std::to_string(kOutputBinding) + ") writeonly buffer doublet_Outputs { doublet_Out doublet_out[]; };\n";
  std::string stores;  // the outputs into their record
  for (size_t i = 0; i < out->iface.outputs.size(); ++i) {
    const std::string& name = out->iface.outputs[i].name;
    const auto special = stored_as.find(name);
    stores += "  doublet_out[doublet_record].m" + std::to_string(i) + " = " +
              (special != stored_as.end() ? special->second : rename_legacy_builtins(name)) + ";\n";
  }
  if (geometry) {
    const std::string records = std::to_string(out->iface.records_per_sample);
    w += "int doublet_i;\nint doublet_emitted;\nvoid doublet_end_primitive() {}\n"
         "void doublet_emit() {\n  if (doublet_emitted >= " + records + ") return;\n"
         "  int doublet_record = doublet_i * " + records + " + doublet_emitted;\n" + stores +
         "  doublet_emitted += 1;\n}\n";
  }
  w += "void main() {\n  ";
  if (!geometry) w += "int ";
  w += stage == GraphicsStage::Vertex     ? "doublet_i = doublet_vertex_index;\n"
       : stage == GraphicsStage::Geometry ? "doublet_i = gl_PrimitiveIDIn;\n  doublet_emitted = 0;\n"
       : per_primitive                    ? "doublet_i = gl_PrimitiveID;\n"
                                          : "doublet_i = int(gl_FragCoord.y) * " + std::to_string(kGridWidth) + " + int(gl_FragCoord.x);\n";
  for (size_t i = 0; i < out->iface.inputs.size(); ++i)
    w += "  " + (per_primitive ? rename_primitive_builtins(out->iface.inputs[i].name) : out->iface.inputs[i].name) +
         " = doublet_in[doublet_i].m" + std::to_string(i) + ";\n";
  if (control)  // levels an invocation does not write read 0 in both runs
    w += "  for (int k = 0; k < 4; ++k) doublet_tess_level_outer[k] = 0.0;\n"
         "  for (int k = 0; k < 2; ++k) doublet_tess_level_inner[k] = 0.0;\n";
  w += "  doublet_user_main();\n";
  if (control) {
    w += "  int doublet_record = doublet_i * " + std::to_string(elements) + " + gl_InvocationID;\n" + stores;
  } else if (evaluation) {
    // Each corner of the patch runs the user's code on the sample's inputs; one of them stores.
    const char* corner = elements == 3 ? "gl_TessCoord.x > 0.5" : elements == 4 ? "gl_TessCoord.x < 0.5 && gl_TessCoord.y < 0.5"
                                                                                : "gl_TessCoord.x < 0.5";
    w += std::string("  if (") + corner + ") {\n    int doublet_record = doublet_i;\n" + stores + "  }\n";
  } else if (!geometry) {
    w += "  int doublet_record = doublet_i;\n" + stores;
  }
  w += "}\n";

  const std::string user = body + w;
  // ES 3.10 has tessellation through its extension (the user's text requires it itself).
  const std::string tessellation = version + (version == "#version 310 es" ? "\n#extension GL_EXT_tessellation_shader : require" : "");
  if (per_primitive) {
    out->vertex = version + "\nvoid main() { gl_Position = vec4(0.0); }\n";  // the inputs come from the buffer
    out->fragment = version + "\nvoid main() {}\n";  // never runs: rasterizer discard
  }
  if (geometry) {
    out->geometry = user;
  } else if (evaluation) {
    out->iface.input_vertices = 1;  // patches of one control point, tessellated at level 1
    out->tess_evaluation = user;
    out->tess_control = tessellation + "\nlayout(vertices = 1) out;\nvoid main() {\n"
                        "  for (int k = 0; k < 4; ++k) gl_TessLevelOuter[k] = 1.0;\n"
                        "  for (int k = 0; k < 2; ++k) gl_TessLevelInner[k] = 1.0;\n}\n";
  } else if (control) {
    out->tess_control = user;
    out->tess_evaluation = tessellation + "\nlayout(triangles) in;\nvoid main() { gl_Position = vec4(0.0); }\n";
  } else if (stage == GraphicsStage::Vertex) {
    out->vertex = user;
    out->fragment = version + "\nvoid main() {}\n";  // never runs: rasterizer discard
  } else {
    const std::string width = std::to_string(kGridWidth) + ".0", height = std::to_string(kGridHeight) + ".0";
    out->vertex = version + "\n" + kVertexIndexMacro +
                  "void main() {\n"
                  "  int i = doublet_vertex_index;\n"
                  "  vec2 pixel = vec2(float(i % " + std::to_string(kGridWidth) + "), float(i / " +
                  std::to_string(kGridWidth) + ")) + 0.5;\n"
                  "  gl_Position = vec4(pixel / vec2(" + width + ", " + height + ") * 2.0 - 1.0, 0.0, 1.0);\n"
                  "  gl_PointSize = 1.0;\n"
                  "}\n";
    out->fragment = user;
  }
  return {};
}

}  // namespace doublet::runner::detail
