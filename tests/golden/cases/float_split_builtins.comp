// targets: es310 wgsl
#version 450
// modf and frexp on floats with out arguments in buffers: WGSL returns a struct, so a helper
// stores the second part through a pointer (a local temporary, copied back by wgsl-out-arguments).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer B { double v[]; };
layout(std430, binding = 1) buffer F { float whole[]; };
layout(std430, binding = 2) buffer E { int ex[]; };
layout(std430, binding = 3) buffer R { vec2 r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  float x = float(v[i]) * 7.25;
  float fr = modf(x, whole[i]);
  r[i] = vec2(fr + frexp(x * 3.0, ex[i]), float(v[i] * 2.0lf));
}
