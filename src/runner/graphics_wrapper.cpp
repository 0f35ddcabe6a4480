#include "runner/graphics_wrapper.hpp"

#include <algorithm>
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
      R"(^\s*(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid|sample|invariant|precise|highp|mediump|lowp)\s+)*)"
      R"((in|out|attribute|varying)\s+((?:highp|mediump|lowp)\s+)?([A-Za-z_]\w*)\s+([A-Za-z_]\w*(?:\s*,\s*[A-Za-z_]\w*)*)\s*)"
      R"((\[\s*\d*\s*\])?\s*;\s*(?://.*)?$)");
  return re;
}

// Anything that starts like an in/out declaration; what `declaration` does not take is unsupported.
const std::regex& looks_like_declaration() {
  static const std::regex re(
      R"(^\s*(?:layout\s*\([^)]*\)\s*)?(?:(?:flat|smooth|noperspective|centroid|sample|invariant|precise|highp|mediump|lowp)\s+)*(in|out|attribute|varying)\s+\w)");
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

// Built-ins the wrapped text cannot use as written: ES 1.00/compatibility fragment outputs become
// plain globals (stored like any output), ES 1.00 texture functions their ES 3.10 name.
std::string rename_legacy_builtins(const std::string& line) {
  static const std::pair<std::regex, const char*> kRenames[] = {
      {std::regex(R"(\bgl_FragColor\b)"), "doublet_FragColor"},
      {std::regex(R"(\bgl_FragData\b)"), "doublet_FragData"},
      {std::regex(R"(\btexture2D\b)"), "texture"},
      {std::regex(R"(\btextureCube\b)"), "texture"}};
  std::string out = line;
  for (const auto& [re, replacement] : kRenames) out = std::regex_replace(out, re, replacement);
  return out;
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

// Geometry: the built-ins the wrapped text cannot use as written. gl_in becomes a global array
// loaded from the input buffer; EmitVertex() stores the outputs (doublet_emit, in the wrapper's
// main part) and EndPrimitive() does nothing (no primitive is rasterized).
std::string rename_geometry_builtins(const std::string& line) {
  static const std::pair<std::regex, const char*> kRenames[] = {
      {std::regex(R"(\bgl_in\b)"), "doublet_gl_in"},
      {std::regex(R"(\bEmitVertex\s*\(\s*\))"), "doublet_emit()"},
      {std::regex(R"(\bEndPrimitive\s*\(\s*\))"), "doublet_end_primitive()"}};
  std::string out = line;
  for (const auto& [re, replacement] : kRenames) out = std::regex_replace(out, re, replacement);
  return out;
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
  const bool geometry = stage == GraphicsStage::Geometry;
  static const std::regex reads_gl_in(R"(\bgl_in\b)");
  // Geometry: declarations the user's text needs, placed before its first line of code (after the
  // #version and #extension lines).
  std::string geometry_preamble;
  if (geometry) {
    out->iface.input_vertices = geometry_input_vertices(glsl);
    out->iface.records_per_sample = geometry_max_vertices(glsl);
    if (out->iface.input_vertices == 0 || out->iface.records_per_sample == 0)
      return "a geometry shader needs its input primitive (layout(triangles) in;) and max_vertices declared";
    geometry_preamble = "void doublet_emit();\nvoid doublet_end_primitive();\n";
    if (std::regex_search(glsl, reads_gl_in))
      geometry_preamble += "struct doublet_PerVertex { vec4 gl_Position; };\ndoublet_PerVertex doublet_gl_in[" +
                           std::to_string(out->iface.input_vertices) + "];\n";
  }
  while (std::getline(in, line)) {
    ++line_number;
    const bool global = scope.global();
    scope.advance(line);
    if (!geometry_preamble.empty() && !version.empty() && global) {
      const size_t first = line.find_first_not_of(" \t");
      if (first != std::string::npos && line[first] != '#' && line.compare(first, 2, "//") != 0) {
        body += geometry_preamble;
        geometry_preamble.clear();
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
      // A geometry shader's per-vertex inputs are arrays, one element per vertex of the primitive:
      // each element is an input of its own.
      const bool per_vertex = geometry && is_input && m[5].matched;
      if (m[5].matched && !per_vertex)
        return "line " + std::to_string(line_number) + ": unsupported in/out declaration (arrays only as a geometry "
               "shader's per-vertex inputs): " + line;
      if (per_vertex && names.find(',') != std::string::npos)
        return "line " + std::to_string(line_number) + ": one per-vertex input array per declaration: " + line;
      std::replace(names.begin(), names.end(), ',', ' ');
      std::istringstream split(names);
      for (std::string name; split >> name;) {
        for (uint32_t k = 0; k < (per_vertex ? out->iface.input_vertices : 1); ++k) {
          v.name = per_vertex ? name + "[" + std::to_string(k) + "]" : name;
          (is_input ? out->iface.inputs : out->iface.outputs).push_back(v);
        }
      }
      body += std::string(m[2]) + std::string(m[3]) + " " + std::string(m[4]) +
              (per_vertex ? "[" + std::to_string(out->iface.input_vertices) + "]" : "") + ";  // was: " + line + "\n";
      continue;
    }
    if (global && std::regex_search(line, looks_like_declaration()))
      return "line " + std::to_string(line_number) + ": unsupported in/out declaration (one per line, no arrays, " +
             "blocks or structs): " + line;
    body += (geometry ? rename_geometry_builtins(line) : rename_legacy_builtins(line)) + "\n";
  }
  if (!block_lines.empty()) return "an interface block does not end: " + block_lines.front();
  if (version.empty()) return "the shader has no #version line";
  if (stage == GraphicsStage::Vertex && glsl.find("gl_Position") != std::string::npos)
    out->iface.outputs.push_back(StageVariable{"gl_Position", 'f', 4});
  if (geometry) {
    static const std::regex writes_position(R"(\bgl_Position\s*=[^=])");
    if (std::regex_search(glsl, reads_gl_in))
      for (uint32_t k = 0; k < out->iface.input_vertices; ++k)
        out->iface.inputs.push_back(StageVariable{"gl_in[" + std::to_string(k) + "].gl_Position", 'f', 4});
    if (std::regex_search(glsl, writes_position)) out->iface.outputs.push_back(StageVariable{"gl_Position", 'f', 4});
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
  if (!out->iface.inputs.empty())
    w += struct_decl("doublet_In", out->iface.inputs) + "layout(std430, binding = " + std::to_string(kInputBinding) +
         ") readonly buffer doublet_Inputs { doublet_In doublet_in[]; };\n";
  w += struct_decl("doublet_Out", out->iface.outputs) + "layout(std430, binding = " + std::to_string(kOutputBinding) +
       ") writeonly buffer doublet_Outputs { doublet_Out doublet_out[]; };\n";
  std::string stores;  // the outputs into their record
  for (size_t i = 0; i < out->iface.outputs.size(); ++i)
    stores += "  doublet_out[doublet_record].m" + std::to_string(i) + " = " + rename_legacy_builtins(out->iface.outputs[i].name) + ";\n";
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
                                          : "doublet_i = int(gl_FragCoord.y) * " + std::to_string(kGridWidth) + " + int(gl_FragCoord.x);\n";
  for (size_t i = 0; i < out->iface.inputs.size(); ++i)
    w += "  " + (geometry ? rename_geometry_builtins(out->iface.inputs[i].name) : out->iface.inputs[i].name) +
         " = doublet_in[doublet_i].m" + std::to_string(i) + ";\n";
  w += "  doublet_user_main();\n";
  if (!geometry) w += "  int doublet_record = doublet_i;\n" + stores;
  w += "}\n";

  const std::string user = body + w;
  if (geometry) {
    out->geometry = user;
    out->vertex = version + "\nvoid main() { gl_Position = vec4(0.0); }\n";  // the inputs come from the buffer
    out->fragment = version + "\nvoid main() {}\n";  // never runs: rasterizer discard
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
