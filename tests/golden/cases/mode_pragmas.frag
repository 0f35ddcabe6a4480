// targets: es300 glsl450 webgl2
#version 300 es
precision highp float;
// '#pragma doublet mode(MODE)' sets the mode of the next declaration: a global's storage, a
// function's arithmetic (and the storage of its locals, parameters and return value), a
// local's storage. Mixed expressions convert where the precisions meet.
#pragma doublet mode(fp32)
uniform double gain;     // stored as a plain float
uniform double origin;   // df64 (the default): origin_hi, origin_lo
flat in double sample_;
out vec4 color;

#pragma doublet mode(rte)
float relative(double x) {
  return float(x - origin) * 2.0;   // exact difference, then float
}

#pragma doublet mode(fp32)
double cheap(double x) {
  #pragma doublet mode(df64)
  double kept = x * gain;           // float product, stored hi/lo (widened)
  return kept + 1.0lf;              // float arithmetic, float return value
}

void main() {
  double accurate = sample_ * gain;  // df64 arithmetic: the fp32 'gain' is widened
  color = vec4(relative(sample_), float(cheap(sample_)), float(accurate), 1.0);
}
