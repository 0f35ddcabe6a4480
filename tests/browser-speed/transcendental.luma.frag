#version 300 es
// transcendental.frag by hand on luma.gl's fp64 module (@luma.gl/shadertools, tools/peers), each
// double a vec2 (hi, lo): the peer of issue 23's transcendental speed kernels
// (tools/browser/speed-suite.mjs puts exp, log, sin, cos or tan in place of FUNCTION).
precision highp float;
precision highp int;
// luma.gl fp64 library: inserted here by speed-suite.mjs
uniform sampler2D words;  // as transcendental.frag
layout(location = 0) out vec4 xy;
layout(location = 1) out vec4 zw;
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  vec2 y0 = FUNCTION_fp64(a.xy);
  vec2 y1 = FUNCTION_fp64(a.zw);
  vec2 y2 = FUNCTION_fp64(b.xy);
  vec2 y3 = FUNCTION_fp64(b.zw);
  xy = vec4(y0.x, y1.x, y0.y, y1.y);
  zw = vec4(y2.x, y3.x, y2.y, y3.y);
}
