#version 450
// Kernel written with global state, as ported CPU code often is: a global accumulator with an
// initialiser and named local constants (a Kahan-style compensated running sum per invocation).
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Samples { double samples[]; };
layout(std430, binding = 1) writeonly buffer Sums { double sums[]; };

double running_sum = 0.0lf;
double compensation = 0.0lf;

void accumulate(double x) {
  double y = x - compensation;
  double t = running_sum + y;
  compensation = (t - running_sum) - y;
  running_sum = t;
}

void main() {
  const double weight = 0.125lf;
  const int terms = 8;
  uint base = gl_GlobalInvocationID.x * uint(terms);
  for (int k = 0; k < terms; ++k) accumulate(samples[base + uint(k)] * weight);
  sums[gl_GlobalInvocationID.x] = running_sum;
}
