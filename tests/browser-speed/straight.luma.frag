#version 300 es
// straight.frag by hand on luma.gl's fp64 module (@luma.gl/shadertools, tools/peers), each double a
// vec2 (hi, lo): the peer of issue 23's speed benchmark (tools/browser/speed-suite.mjs). The transform
// is the library's own mat4_vec4_mul_fp64, as deck.gl's 64-bit projection uses it.
precision highp float;
precision highp int;
// luma.gl fp64 library: inserted here by speed-suite.mjs
uniform sampler2D words;  // as straight.frag
uniform vec2 eye64[3];    // (hi, lo) per component
uniform vec2 mvp64[16];   // (hi, lo) per entry, row after row (mat4_vec4_mul_fp64's order)
layout(location = 0) out vec4 xy;
layout(location = 1) out vec4 zw;
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  vec2 d[4];
  d[0] = sub_fp64(a.xy, eye64[0]);
  d[1] = sub_fp64(a.zw, eye64[1]);
  d[2] = sub_fp64(b.xy, eye64[2]);
  d[3] = vec2(1.0, 0.0);
  vec2 clip[4];
  mat4_vec4_mul_fp64(mvp64, d, clip);
  xy = vec4(clip[0].x, clip[1].x, clip[0].y, clip[1].y);
  zw = vec4(clip[2].x, clip[3].x, clip[2].y, clip[3].y);
}
