// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Texture built-ins with no double pass through unchanged next to double code (issue 24).
uniform sampler2D tex;
uniform double scale;
in vec4 uv;
layout(location = 0) out vec4 o;
void main() {
  vec4 a = textureProjGradOffset(tex, uv.xyz, uv.xy, uv.zw, ivec2(1, -1));
  vec4 b = textureProjLodOffset(tex, uv.xyz, 0.0, ivec2(0, 1));
  o = (a + b) * float(scale * 2.0lf);
}
