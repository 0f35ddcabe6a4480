// targets: es310 wgsl
#version 450
// Both out-argument rewrites in one function: a double vector's component (out-argument-temporaries,
// before lowering) and, for wgsl, a buffer element (wgsl-out-arguments, after): their temporaries
// must not share a name (the differential tester's seed 77113: 'df_out1' : redefinition).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double s[]; };
void scale(inout double x) { x *= 2.0lf; }
void main() {
  dvec2 w = dvec2(s[0], s[1]);
  scale(w.y);
  scale(s[2]);
  s[3] = w.x + w.y;
}
