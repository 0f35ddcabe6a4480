// Generates the WebGL2 programs of a vertex or fragment job (webgl2.hpp): the user's text as
// graphics_wrapper.cpp rewrites it (in/out declarations as plain globals, `main` renamed), under
// `#version 300 es`, followed by a main() that loads the inputs from the RGBA32UI input texture and
// stores the outputs' bits in uvec4 slots (transform feedback varyings or colour attachments).
#include <algorithm>
#include <cstring>
#include <regex>

#include "runner/graphics_wrapper.hpp"
#include "runner/internal.hpp"
#include "runner/webgl2.hpp"

namespace doublet::runner::detail {
namespace {

const char* kComponents[] = {".x", ".y", ".z", ".w"};

// `name` or `name.x`...: the expression of component c of a variable.
std::string component(const StageVariable& v, int c) {
  const std::string name = v.name == "gl_FragColor" ? "doublet_FragColor"
                           : v.name.rfind("gl_FragData[", 0) == 0 ? "doublet_FragData" + v.name.substr(11)
                                                                  : v.name;
  return v.components == 1 ? name : name + kComponents[c];
}

// Words of each variable, one per component, one variable after the other; the total rounded up to
// whole uvec4s.
uint32_t assign_words(const std::vector<StageVariable>& vars, std::vector<uint32_t>* first) {
  uint32_t word = 0;
  for (const StageVariable& v : vars) {
    first->push_back(word);
    word += static_cast<uint32_t>(v.components);
  }
  return (word + 3) / 4 * 4;
}

// The input texture read, then the variables assigned from their words.
std::string load_inputs(const WebGl2Program& p) {
  std::string s;
  for (size_t i = 0; i < p.iface.inputs.size(); ++i) {
    const StageVariable& v = p.iface.inputs[i];
    const char* type = v.scalar == 'f' ? "float" : v.scalar == 'i' ? "int" : "uint";
    const char* from_bits = v.scalar == 'f' ? "uintBitsToFloat" : v.scalar == 'i' ? "int" : "";
    std::string vector_type = v.components == 1 ? type
                              : std::string(v.scalar == 'f' ? "vec" : v.scalar == 'i' ? "ivec" : "uvec") +
                                    std::to_string(v.components);
    s += "  " + v.name + " = " + vector_type + "(";
    for (int c = 0; c < v.components; ++c)
      s += std::string(c ? ", " : "") + from_bits + "(doublet_word(doublet_i, " + std::to_string(p.input_word[i] + c) + "))";
    s += ");\n";
  }
  return s;
}

// Output word w's expression (its bits as a uint), "0u" for the padding after the last one.
std::string output_word_expression(const WebGl2Program& p, uint32_t w) {
  for (size_t i = 0; i < p.iface.outputs.size(); ++i) {
    const StageVariable& v = p.iface.outputs[i];
    if (w < p.output_word[i] || w >= p.output_word[i] + static_cast<uint32_t>(v.components)) continue;
    const std::string e = component(v, static_cast<int>(w - p.output_word[i]));
    return v.scalar == 'f' ? "floatBitsToUint(" + e + ")" : v.scalar == 'i' ? "uint(" + e + ")" : e;
  }
  return "0u";
}

// The generated tail of pass `pass`: declarations of the transport and the new main().
std::string generated_main(const WebGl2Program& p, const WebGl2Pass& pass) {
  const bool vertex = p.stage == GraphicsStage::Vertex;
  std::string w = "#undef main\nprecision highp float;\nprecision highp int;\n";
  if (p.input_words > 0) {
    const std::string texels = std::to_string(p.input_words / 4);
    w += "uniform highp usampler2D doublet_inputs;\n"
         "uint doublet_word(int i, int k) {\n"
         "  uvec4 t = texelFetch(doublet_inputs, ivec2((i % " + std::to_string(kWebGl2GridWidth) + ") * " + texels +
         " + k / 4, i / " + std::to_string(kWebGl2GridWidth) + "), 0);\n"
         "  int c = k % 4;\n"
         "  return c == 0 ? t.x : c == 1 ? t.y : c == 2 ? t.z : t.w;\n"
         "}\n";
  }
  for (uint32_t k = 0; k < pass.slots; ++k)
    w += (vertex ? "flat out highp uvec4 doublet_o" : "layout(location = " + std::to_string(k) + ") out highp uvec4 doublet_o") +
         std::to_string(k) + ";\n";
  w += "void main() {\n  int doublet_i = ";
  w += vertex ? "gl_VertexID;\n" : "int(gl_FragCoord.y) * " + std::to_string(kWebGl2GridWidth) + " + int(gl_FragCoord.x);\n";
  w += load_inputs(p);
  w += "  doublet_user_main();\n";
  for (uint32_t k = 0; k < pass.slots; ++k) {
    const uint32_t first = (pass.first_slot + k) * 4;
    w += "  doublet_o" + std::to_string(k) + " = uvec4(";
    for (uint32_t c = 0; c < 4; ++c) w += (c ? ", " : "") + output_word_expression(p, first + c);
    w += ");\n";
  }
  return w + "}\n";
}

constexpr const char* kCoverVertexShader =
    "#version 300 es\n"
    "// One triangle over the whole framebuffer: every pixel runs the fragment stage once.\n"
    "void main() {\n"
    "  gl_Position = vec4(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0, 0.0, 1.0);\n"
    "}\n";
constexpr const char* kEmptyFragmentShader = "#version 300 es\nvoid main() {}\n";  // rasterizer discard

}  // namespace

std::string wrap_webgl2(GraphicsStage stage, const std::string& glsl, WebGl2Program* out) {
  *out = WebGl2Program{};
  out->stage = stage;
  static const std::regex version_re(R"((?:^|\n)[ \t]*#[ \t]*version[ \t]+(\d+)[ \t]*(es)?)");
  std::smatch m;
  if (!std::regex_search(glsl, m, version_re)) return "the shader has no #version line";
  const std::string version = m[1].str() + (m[2].matched ? " es" : "");
  if (version != "100" && version != "300 es")
    return "WebGL2 runs GLSL ES 1.00 and 3.00 only; the shader is '#version " + version + "'";
  WrappedProgram wrapped;
  if (std::string e = wrap_graphics(stage, glsl, &wrapped); !e.empty()) return e;
  for (const auto* vars : {&wrapped.iface.inputs, &wrapped.iface.outputs})
    for (const StageVariable& v : *vars)
      if (v.scalar == 'd') return "'" + v.name + "' is a double: WebGL2 has no doubles";
  out->iface = wrapped.iface;
  out->input_words = assign_words(out->iface.inputs, &out->input_word);
  out->output_words = assign_words(out->iface.outputs, &out->output_word);
  // The user's text under the WebGL2 version line (wrap_graphics wrote #version 310 es for the
  // storage buffers this transport does not use).
  std::string user = wrapped.user_text;
  user.replace(0, user.find('\n'), "#version 300 es");
  // The lines the wrapper added after #version (the main rename, renamed fragment outputs) would
  // shift the browser's line numbers: a #line puts the rest back on the lowered text's numbering.
  const std::string rename = "#define main doublet_user_main\n";
  if (size_t at = user.find(rename); at != std::string::npos) {
    at += rename.size();
    const std::string legacy_output = "highp vec4 doublet_Frag";  // graphics_wrapper.cpp's declarations
    while (user.compare(at, legacy_output.size(), legacy_output) == 0) at = user.find('\n', at) + 1;
    const long version_line = 1 + std::count(glsl.begin(), glsl.begin() + m.position(1), '\n');
    user.insert(at, "#line " + std::to_string(version_line + 1) + "\n");
  }

  const uint32_t slots = out->output_words / 4;
  const uint32_t per_pass = stage == GraphicsStage::Vertex ? kWebGl2VertexSlots : kWebGl2FragmentSlots;
  for (uint32_t first = 0; first < slots; first += per_pass) {
    WebGl2Pass pass;
    pass.first_slot = first;
    pass.slots = std::min(per_pass, slots - first);
    const std::string text = user + generated_main(*out, pass);
    if (stage == GraphicsStage::Vertex) {
      pass.vertex = text;
      pass.fragment = kEmptyFragmentShader;
      for (uint32_t k = 0; k < pass.slots; ++k) pass.varyings.push_back("doublet_o" + std::to_string(k));
    } else {
      pass.vertex = kCoverVertexShader;
      pass.fragment = text;
    }
    out->passes.push_back(std::move(pass));
  }
  return {};
}

std::string webgl2_pack_inputs(const WebGl2Program& p, const GraphicsJob& job, std::vector<uint32_t>* words) {
  words->assign(size_t{job.count} * p.input_words, 0);
  for (const auto& [name, values] : job.inputs) {
    size_t i = 0;
    while (i < p.iface.inputs.size() && p.iface.inputs[i].name != name) ++i;
    if (i == p.iface.inputs.size()) continue;  // as for uniforms: a name the shader lacks is ignored
    const StageVariable& v = p.iface.inputs[i];
    const size_t comps = static_cast<size_t>(v.components), n = size_t{job.count} * comps;
    if (values.size() != n)
      return "input '" + name + "' needs " + std::to_string(n) + " values (count × components), job gives " +
             std::to_string(values.size());
    for (size_t k = 0; k < n; ++k) {
      uint8_t bytes[4];
      store_scalar(bytes, v.scalar, values[k]);
      std::memcpy(&(*words)[(k / comps) * p.input_words + p.input_word[i] + k % comps], bytes, 4);
    }
  }
  return {};
}

void webgl2_unpack_outputs(const WebGl2Program& p, uint32_t count, const std::vector<uint32_t>& words,
                           GraphicsResult* out) {
  for (size_t i = 0; i < p.iface.outputs.size(); ++i) {
    const StageVariable& v = p.iface.outputs[i];
    const size_t comps = static_cast<size_t>(v.components);
    std::vector<double>& values = out->outputs[v.name];
    values.resize(size_t{count} * comps);
    for (size_t k = 0; k < values.size(); ++k) {
      const uint32_t word = words[(k / comps) * p.output_words + p.output_word[i] + k % comps];
      if (v.scalar == 'f') {
        float f;
        std::memcpy(&f, &word, 4);
        values[k] = f;
      } else {
        values[k] = v.scalar == 'i' ? static_cast<double>(static_cast<int32_t>(word)) : static_cast<double>(word);
      }
    }
  }
}

}  // namespace doublet::runner::detail
