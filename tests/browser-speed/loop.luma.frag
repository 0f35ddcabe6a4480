#version 300 es
// loop.frag by hand on luma.gl's fp64 module (@luma.gl/shadertools, tools/peers), each double a
// vec2 (hi, lo): the peer of issue 23's speed benchmark (tools/browser/speed-suite.mjs). Same
// operations in the same order; 0.5 * dt and -mu are exact on a (hi, lo) pair.
precision highp float;
precision highp int;
// luma.gl fp64 library: inserted here by speed-suite.mjs
uniform sampler2D words;  // as loop.frag
uniform vec2 mu64;        // (hi, lo)
uniform vec2 dt64;        // (hi, lo)
layout(location = 0) out vec4 position;
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  vec2 px = a.xy, py = a.zw, vx = b.xy, vy = b.zw;
  for (int k = 0; k < 32; ++k) {
    vec2 r2 = sum_fp64(mul_fp64(px, px), mul_fp64(py, py));
    vec2 r = sqrt_fp64(r2);
    vec2 f = div_fp64(-mu64, mul_fp64(r2, r));
    vec2 h = mul_fp64(dt64 * 0.5, f);
    vx = sum_fp64(vx, mul_fp64(h, px));
    vy = sum_fp64(vy, mul_fp64(h, py));
    px = sum_fp64(px, mul_fp64(dt64, vx));
    py = sum_fp64(py, mul_fp64(dt64, vy));
    r2 = sum_fp64(mul_fp64(px, px), mul_fp64(py, py));
    r = sqrt_fp64(r2);
    f = div_fp64(-mu64, mul_fp64(r2, r));
    h = mul_fp64(dt64 * 0.5, f);
    vx = sum_fp64(vx, mul_fp64(h, px));
    vy = sum_fp64(vy, mul_fp64(h, py));
  }
  position = vec4(px.x, py.x, px.y, py.y);
}
