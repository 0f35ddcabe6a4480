#version 450
// Seed 6108 of the differential tester, reduced: a product of constants that doublet cannot fold
// (the comma hides it) but the driver can. Under the uniform guard (es310 without gpu_shader5) it
// kept 25.7 bits on lavapipe until every float-float constant read the guard (pass guard-constants,
// docs/accuracy.md, "Constants the driver folds"); the guard oracle checks it.
layout(local_size_x = 64) in;
layout(std430, binding = 1) writeonly buffer Out0 { dvec3 r0[]; };
double scratch;
const dvec2 C0 = dvec2(-1.6096658262102785lf);
void main() {
  uint gid = gl_GlobalInvocationID.x;
  r0[gid] = (clamp(C0.yxy, -1.5lf, 1.5lf) * (scratch = -2.5315213579651239lf, scratch * -0.13377862020845477lf));
}
