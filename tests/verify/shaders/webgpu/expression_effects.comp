#version 450
// Increments and assignments inside expressions (tests/verify/webgpu_verify_test.cpp): WGSL has
// them as statements only, so wgsl-expression-effects makes each (and an index with a call) a
// temporary and hoist-commas moves it before its statement, in GLSL's left-to-right order.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer B { double v[]; };
layout(std430, binding = 1) buffer R { dvec4 r[]; };
layout(std430, binding = 2) buffer S { double s[]; };
layout(std430, binding = 3) buffer U { double u[]; };
int next(inout int c) { c += 1; return c; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  double tmp[6];
  int n = 0;
  for (int k = 0; k < 2; ++k) tmp[n++] = v[i] * double(k + 2);  // tmp[0], tmp[1]
  double acc;
  tmp[n++] = (acc = v[i] * 3.0lf) + acc;                         // tmp[2] = 6 v
  int m = 1;
  tmp[n] = tmp[m++] - tmp[m++];                                  // tmp[3] = tmp[1] - tmp[2]
  tmp[++n] = double(m--) * v[i];                                 // tmp[4] = 3 v, m back to 2
  tmp[n++] += tmp[m];                                            // tmp[4] += tmp[2]; n = 5
  int c = 0;
  tmp[5] = v[i];
  tmp[next(c) + 4] *= 3.0lf;                                     // an index with a call: tmp[5] = 3 v
  // Effects evaluated only sometimes: if/else before the statement; a loop test in the body.
  int q = 0;
  double w = v[i] > 0.0lf ? tmp[q++] : tmp[++q];                // 2 v (q = 1) or 3 v (q = 1)
  bool more = q > 0 && tmp[q++] > 0.0lf;                         // q = 2; 3 v > 0
  int steps = 0;
  for (int k = 0; tmp[k++] > 0.0lf && k < 4;) steps++;           // 3 when v > 0, else 0
  u[i] = w * double(q * (more ? 3 : 5) + steps);                 // 18 v or 30 v
  r[i] = dvec4(tmp[0], tmp[1], tmp[2], tmp[3]);
  s[i] = tmp[4] * double(n) * tmp[5];                            // (3 v + 6 v) * 5 * 3 v
}
