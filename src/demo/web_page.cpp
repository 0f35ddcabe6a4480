// The web page of `doublet demo --web` (see web_page.hpp): lowers the two demo shaders per mode
// and writes them, the scene and the page's script (web_page.js) into one HTML file.
#include "demo/web_page.hpp"

#include <filesystem>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "demo/jitter.hpp"
#include "demo/jitter_scene.hpp"
#include "demo/web_page_script.hpp"
#include "frontend/demote.hpp"

namespace doublet::demo {

const char* const kMandelbrotFragmentShader = R"(#version 300 es
// Deep-zoom Mandelbrot, one fragment per pixel (the compute shader of `doublet demo mandelbrot`).
// Below ~1e-7 units per pixel neighbouring pixels share float coordinates; in double the view
// holds to ~1e-13.
precision highp float;
precision highp int;
uniform dvec2 center;      // complex-plane centre of the view
uniform double scale;      // complex-plane units per pixel
uniform vec2 resolution;   // pixels
uniform int max_iterations;
out highp uint iterations;

void main() {
  dvec2 c = center + dvec2(gl_FragCoord.xy - 0.5 * resolution) * scale;
  dvec2 z = dvec2(0.0lf);
  int n = 0;
  while (n < max_iterations && z.x * z.x + z.y * z.y < 4.0lf) {
    z = dvec2(z.x * z.x - z.y * z.y, 2.0lf * z.x * z.y) + c;
    ++n;
  }
  iterations = uint(n);
}
)";

namespace {

using json = nlohmann::json;

// WebGL2 is GLSL ES 3.00 with WebGL's extra rules: the webgl2 target follows them (no ternary on
// structs, FLT_MAX spelled without ANGLE's "Float overflow" warning; docs/web.md).
constexpr Target kWebTarget = Target::Webgl2;

const char* const kJitterFragmentShader = R"(#version 300 es
precision highp float;
in vec3 v_color;
out vec4 frag_color;
void main() { frag_color = vec4(v_color, 1.0); }
)";

// A panel's caption and the page's one-line description of a mode.
std::string label_of(doublet::Mode mode) {
  switch (mode) {
    case doublet::Mode::Fp32: return "fp32: doubles demoted to float";
    case doublet::Mode::Df64: return "df64: doublet float-float";
    default: return std::string(to_string(mode)) + ": doublet --mode " + std::string(to_string(mode));
  }
}

std::string description_of(doublet::Mode mode) {
  const std::string name = "<b>" + std::string(to_string(mode)) + "</b> ";
  switch (mode) {
    case doublet::Mode::Fp32: return name + "demotes every double to float (what WebGL gives you)";
    case doublet::Mode::Df64:
      return name + "is doublet's float-float lowering (a double as a pair of floats, about 48 bits)";
    default: return name + "is <code>doublet lower --mode " + std::string(to_string(mode)) + "</code> (docs/modes.md)";
  }
}

// One shader of one mode: its text, and for each double input the names it was split into.
bool shader_json(doublet::Mode mode, const char* source, Stage stage, WebSabotage sabotage, const char* text_key,
                 json* out, std::string* error) {
  json split = json::object();
  if (mode == doublet::Mode::Fp32) {
    (*out)[text_key] = frontend::demote_doubles(source);
  } else {
    Options o;
    o.stage = stage;
    o.target = kWebTarget;
    o.mode = mode;
    o.file_name = stage == Stage::Vertex ? "<web jitter.vert>" : "<web mandelbrot.frag>";
    if (sabotage == WebSabotage::NoGuard) o.guard = GuardKind::None;
    const Result r = lower(source, o);
    if (!r.ok) {
      for (const Diagnostic& d : r.diagnostics) *error += format_diagnostic(d) + "\n";
      return false;
    }
    (*out)[text_key] = r.output;
    for (const InterfaceVariable& v : r.manifest.variables)
      if (v.split) split[v.name] = v.lowered_names;
  }
  (*out)["split"] = split;
  return true;
}

json jitter_json(const WebPageOptions& o) {
  const JitterGeometry g = jitter_geometry();
  const JitterOrbit orbit = jitter_orbit();
  return {{"positions", g.positions}, {"colors", g.colors}, {"centre", orbit.centre},
          {"radial", orbit.radial}, {"along_track", orbit.along_track}, {"north", orbit.north},
          {"frames", o.jitter_frames}, {"width", o.jitter_width}, {"height", o.jitter_height}};
}

// JSON inside <script>: '<' occurs only in strings there, and as \u003c it cannot end the element.
std::string script_safe(const std::string& json_text) {
  std::string out;
  for (char c : json_text) out += c == '<' ? std::string("\\u003c") : std::string(1, c);
  return out;
}

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

const char* const kStyle = R"(
body { font: 14px/1.4 system-ui, sans-serif; margin: 16px 20px; background: #fafafa; color: #222; max-width: 1240px; }
h1 { font-size: 22px; margin: 0 0 4px; } h2 { font-size: 17px; margin: 18px 0 4px; } h3 { font-size: 14px; margin: 8px 0 2px; }
p { margin: 4px 0; max-width: 1100px; }
.row { display: flex; gap: 12px; flex-wrap: nowrap; }
figure { margin: 0; } canvas { display: block; background: #000; }
figcaption { font-size: 12px; width: min-content; min-width: 256px; }
.caption { color: #444; }
.sabotage { background: #c00; color: #fff; padding: 4px 8px; font-weight: bold; }
table { border-collapse: collapse; } td, th { border: 1px solid #bbb; padding: 2px 8px; text-align: right; }
code { font-size: 13px; }
)";

}  // namespace

std::optional<WebSabotage> parse_web_sabotage(std::string_view name) {
  for (WebSabotage s : {WebSabotage::None, WebSabotage::NoGuard, WebSabotage::DropLo})
    if (to_string(s) == name) return s;
  return std::nullopt;
}

std::string_view to_string(WebSabotage s) {
  switch (s) {
    case WebSabotage::NoGuard: return "no-guard";
    case WebSabotage::DropLo: return "drop-lo";
    default: return "none";
  }
}

bool make_web_page(const WebPageOptions& o, std::string* html, std::string* error) {
  error->clear();
  if (o.modes.empty() || o.zooms.empty() || o.jitter_frames < 2 || o.mandelbrot_size < 8 || o.reference_stride < 1 ||
      o.timing_frames < 1 || o.max_iterations < 1) {
    *error = "the web page needs a mode, a zoom, 2 frames, 8x8 pixels, 1 iteration and 1 timed frame";
    return false;
  }
  json modes = json::array();
  for (doublet::Mode mode : o.modes) {
    if (mode == doublet::Mode::Native) {
      *error = "mode native cannot run in WebGL2 (no double in GLSL ES)";
      return false;
    }
    json m = {{"name", to_string(mode)}, {"label", label_of(mode)}};
    if (!shader_json(mode, kJitterVertexShader, Stage::Vertex, o.sabotage, "vertex", &m["jitter"], error) ||
        !shader_json(mode, kMandelbrotFragmentShader, Stage::Fragment, o.sabotage, "fragment", &m["mandelbrot"],
                     error))
      return false;
    modes.push_back(std::move(m));
  }
  json config = {
      {"modes", modes},
      {"sabotage", o.sabotage == WebSabotage::None ? json(nullptr) : json(to_string(o.sabotage))},
      {"jitter", jitter_json(o)},
      {"jitter_fragment", kJitterFragmentShader},
      {"mandelbrot",
       {{"center", {o.center_x, o.center_y}}, {"zooms", o.zooms}, {"width", o.mandelbrot_size},
        {"height", o.mandelbrot_size}, {"max_iterations", o.max_iterations}, {"reference_stride", o.reference_stride}}},
      {"timing_frames", o.timing_frames},
  };
  char view[160];
  std::snprintf(view, sizeof view, "centre (%.17g, %.17g), %dx%d pixels, at most %d iterations", o.center_x,
                o.center_y, o.mandelbrot_size, o.mandelbrot_size, o.max_iterations);
  std::string descriptions;
  for (size_t i = 0; i < o.modes.size(); ++i)
    descriptions += (i == 0 ? "" : i + 1 == o.modes.size() ? " and " : ", ") + description_of(o.modes[i]);
  std::string banner;
  if (o.sabotage != WebSabotage::None)
    banner = "<p class=\"sabotage\">SABOTAGED page (" + std::string(to_string(o.sabotage)) +
             "): a test of the tests, its float-float panels are meant to be wrong.</p>\n";
  *html = "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<title>doublet: double precision in WebGL2</title>\n<style>" + std::string(kStyle) + "</style>\n</head>\n<body>\n"
          "<h1>doublet: double precision in WebGL2</h1>\n" + banner +
          "<p>The same double-precision shaders, as an application would write them, in each mode: " +
          descriptions + ". The shaders were generated by "
          "<code>doublet demo --web</code>; every number below is computed now, in this browser, against the same "
          "computation in JavaScript doubles.</p>\n"
          "<p>Renderer: <span id=\"renderer\">...</span>. Status: <span id=\"status\">running...</span></p>\n"
          "<h2>Deep-zoom Mandelbrot (WebGL2 fragment shader)</h2>\n<p>" + html_escape(view) +
          ". Where neighbouring pixels are closer than a float can tell apart, fp32 draws blocks or stripes. "
          "The JS-double reference checks one pixel in every " + std::to_string(o.reference_stride) + "x" +
          std::to_string(o.reference_stride) + " block.</p>\n<div id=\"mandelbrot\"></div>\n"
          "<h2>Two satellites on a geostationary orbit (WebGL2 vertex shader)</h2>\n"
          "<p>Two 1.2 m boxes 2.75 m apart, 42,164 km from the Earth's centre, where neighbouring floats are 2-4 m "
          "apart; the camera moves from 10 to 50 m away. The vertex shader subtracts the eye from the Earth-centred "
          "positions in double (relative to eye). <i>Wobble</i>: the largest change from one frame to the next of a "
          "vertex's screen error against JavaScript doubles (gl_Position captured with transform feedback).</p>\n"
          "<div class=\"row\" id=\"jitter-row\"></div>\n"
          "<h2>Time per frame (ms)</h2>\n<table><thead><tr><th>mode</th><th>Mandelbrot, first zoom</th>"
          "<th>jitter scene</th></tr></thead><tbody id=\"timing\"></tbody></table>\n<p id=\"timing-note\"></p>\n"
          "<script type=\"application/json\" id=\"doublet-config\">" + script_safe(config.dump()) + "</script>\n"
          "<script>\n" + std::string(kWebPageScript) + "</script>\n</body>\n</html>\n";
  return true;
}

std::string write_web_page(const std::string& dir, const WebPageOptions& o) {
  namespace fs = std::filesystem;
  std::string html, error;
  if (!make_web_page(o, &html, &error)) return error;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) return "cannot create the directory " + dir + (ec ? ": " + ec.message() : "");
  const fs::path file = fs::path(dir) / "index.html";
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << html;
  out.close();
  if (!out) return "cannot write " + file.string();
  return {};
}

}  // namespace doublet::demo
