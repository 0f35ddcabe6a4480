// target: es310
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double v[]; };
#pragma doublet mode(exact)
double sum3(dvec3 a) {
  return a.x + a.y + a.z;
}
void main() {
  v[0] = sum3(dvec3(v[1], v[2], v[3])) * v[4];
}
