#version 450
// issue 23's transcendental speed kernels (tools/browser/speed-suite.mjs --kernels exp,log,sin,cos,tan):
// per pixel one double function of four doubles, each read as hi/lo float words from a texture, so
// nothing folds. speed-suite.mjs puts the function's name (exp, log, sin, cos or tan, a doublet
// extension on doubles: docs/transcendentals.md) in place of FUNCTION before lowering.
uniform sampler2D words;           // texel (2x, y): x0_hi x0_lo x1_hi x1_lo; texel (2x + 1, y): x2, x3
layout(location = 0) out vec4 xy;  // f(x0), f(x1): hi.0 hi.1 lo.0 lo.1
layout(location = 1) out vec4 zw;  // f(x2), f(x3), the same way
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  dvec4 x = dvec4(double(a.x) + double(a.y), double(a.z) + double(a.w), double(b.x) + double(b.y), double(b.z) + double(b.w));
  dvec4 y = FUNCTION(x);
  xy = vec4(vec2(y.xy), vec2(y.xy - dvec2(vec2(y.xy))));
  zw = vec4(vec2(y.zw), vec2(y.zw - dvec2(vec2(y.zw))));
}
