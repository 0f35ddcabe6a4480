#version 450
// issue 23's straight-line speed kernel (tools/browser/speed-suite.mjs): a relative-to-eye transform
// per pixel, a double position minus a double eye, times a dmat4 (3 subtractions, 16 products, 12
// sums; no loop, no branch). Each pixel reads its own position as hi/lo float words from a texture,
// so nothing folds.
uniform sampler2D words;  // texel (2x, y): x_hi x_lo y_hi y_lo; texel (2x + 1, y): z_hi z_lo - -
uniform dvec3 eye;
uniform dmat4 mvp;
layout(location = 0) out vec4 xy;  // clip.xy: hi.x hi.y lo.x lo.y
layout(location = 1) out vec4 zw;  // clip.zw, the same way
void main() {
  ivec2 at = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(words, ivec2(2 * at.x, at.y), 0);
  vec4 b = texelFetch(words, ivec2(2 * at.x + 1, at.y), 0);
  dvec3 position = dvec3(double(a.x) + double(a.y), double(a.z) + double(a.w), double(b.x) + double(b.y));
  dvec4 clip = mvp * dvec4(position - eye, 1.0);
  xy = vec4(vec2(clip.xy), vec2(clip.xy - dvec2(vec2(clip.xy))));
  zw = vec4(vec2(clip.zw), vec2(clip.zw - dvec2(vec2(clip.zw))));
}
