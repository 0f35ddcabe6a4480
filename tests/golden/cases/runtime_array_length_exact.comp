// targets: es310
// options: --mode exact
#version 450
// .length() of a runtime-sized array of doubles in mode exact: the length of its word array.
layout(local_size_x = 64) in;
layout(std430, binding = 1) buffer Values { double total; dvec3 points[]; };
void main() {
  double s = 0.0lf;
  for (int i = 0; i < points.length(); ++i) s += points[i].x;
  total = s;
}
