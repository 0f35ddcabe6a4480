// targets: wgsl
#version 450
// isnan/isinf on a double (the runtime's df_isnan/df_isinf) and on a float (a bit-pattern helper,
// WGSL's isnan being gone) in one shader: WGSL has no overloading, so the two helpers need two
// names (they were both df_isnan, which Chromium's WebGPU rejected as a redeclaration; found by the
// differential tester, docs/robustness.md).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { double x[64]; float f[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  bool odd = isnan(x[i]) || isinf(x[i]);
  bool single = isnan(f[i]) || isinf(f[i]);
  x[i] = odd ? 0.0lf : x[i] + double(single);
}
