// targets: es310 es320 glsl450 wgsl
#version 450
// .length() of runtime-sized buffer arrays, of floats and of doubles: passed through as .length()
// (issue 24: it was refused with "unsupported operation" in every mode and target).
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Samples { int count; float weights[]; };
layout(std430, binding = 1) buffer Values { double total; double values[]; };
void main() {
  count = weights.length();
  double s = 0.0lf;
  for (int i = 0; i < values.length(); ++i) s += values[i] * double(weights[i % weights.length()]);
  total = s;
}
