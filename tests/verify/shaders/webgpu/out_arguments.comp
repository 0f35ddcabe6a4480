#version 450
// Buffer elements as out/inout arguments, inside an expression and as a statement
// (tests/verify/webgpu_verify_test.cpp): WGSL's pointers point to function memory only, so they are
// copied through temporaries: the user's functions' parameters, the generated helpers' (a
// component assignment) and the rules' (modf's whole part; with --sabotage drop-lo, the float
// built-in's).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer B { double v[]; };
layout(std430, binding = 1) buffer R { double r[]; };
layout(std430, binding = 2) buffer S { double s[]; };
layout(std430, binding = 3) buffer W { dvec2 w[]; };
layout(std430, binding = 4) buffer T { double t[]; };
layout(std430, binding = 5) buffer M { double whole[]; };
double accumulate(inout double total, double x) { total += x; return total * 2.0lf; }
void scale(out double y, double x) { y = x * 3.0lf; }
double take(inout double x) { double old = x; x = x / 3.0lf; return old; }
void main() {
  uint i = gl_GlobalInvocationID.x;
  r[i] = accumulate(v[i], 1.5lf) + 1.0lf;
  scale(s[i], v[i]);
  w[i].x = r[i] * 0.375lf;                     // generated helpers with an inout parameter
  w[i][1] = w[i].x * v[i];
  t[i] = take(v[i]) - take(v[i]);             // two calls, left to right: v - v/3, not v/3 - v
  s[i] += modf(v[i] * 7.25lf, whole[i]);       // a rule's out parameter (df_modf's whole part)
}
