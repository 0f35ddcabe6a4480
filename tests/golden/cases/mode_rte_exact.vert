// targets: es300 glsl450 webgl2
// options: --mode rte-exact
#version 450
// Mode rte-exact: doubles arrive and are stored as binary64 words (as in mode exact); the
// arithmetic is float, except the difference of two doubles, which is the exact difference
// rounded once to float (ex_sub_to_float), per component for the dvec3.
layout(location = 0) in dvec3 position;
uniform dvec3 eye;
uniform mat4 viewProj;
uniform double scale;
void main() {
  vec3 p = vec3(position - eye);
  float s = float(position.x - eye.x);
  gl_Position = viewProj * vec4(p * float(scale) + s, 1.0);
}
