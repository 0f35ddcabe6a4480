// target: wgsl
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; };
void main() { y = x + x; }
