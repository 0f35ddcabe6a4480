// target: es310
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; float lo; };
void main() {
  y = x * x + x * 2.0lf;
  lo = float(x - double(float(x)));  // the low word: x.lo
}
