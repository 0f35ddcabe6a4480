// targets: es300 glsl450 webgl2
// options: --mode exact
#version 450
// Mode exact's interface: every double crosses as binary64 words, low word first (a host double's
// bytes). double -> uvec2, dvec2 -> uvec4, dvec3/dvec4 -> NAME_xy + NAME_z/NAME_zw (locations
// kept), outputs flat; a std140 block keeps its offsets with padding members.
layout(location = 0) in double a;
layout(location = 1) in dvec2 b;
layout(location = 2) in dvec3 c;
layout(location = 4) in dvec4 d;
uniform double u[2];
uniform dvec3 e;
layout(std140, binding = 0) uniform Params { float s; dvec3 g; double h[2]; };
flat out dvec3 r;
flat out double t;
void main() {
  r = c + d.xyz * e + g;
  t = a - b.y * u[1] + h[1];
  gl_Position = vec4(float(t), float(s), 0.0, 1.0);
}
