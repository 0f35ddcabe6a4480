// targets: es310 glsl450
// options: --mode exact
#version 450
// Mode exact's storage blocks keep the original std430/std140 bytes: words in place of doubles,
// padding members where a dvec3/dvec4 aligned to 32, a twin P_words for a struct of doubles;
// reads load, writes store, an inout argument goes through a temporary.
layout(local_size_x = 64) in;
struct P { dvec3 pos; float w; double m; dvec4 q[2]; };
layout(std430, binding = 0) buffer In { float f; dvec3 v3; double d[]; } inb;
layout(std140, binding = 1) buffer Consts { float s; dvec4 v4; double k; dvec2 v2[2]; dvec3 v3s[2]; };
layout(std430, binding = 2) buffer Ps { int n; P p[]; };
void bump(inout double x) { x += 1.0; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  inb.d[i] = inb.d[i] * k + v4.y;
  bump(inb.d[i]);
  P q = p[i];
  q.pos += q.q[1].xyz + v3s[i & 1u];
  p[i] = q;
  p[i].q[0].w = double(n) + q.m;
  if (i == 0u) v4.w = k * s;
}
