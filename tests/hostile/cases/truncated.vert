#version 300 es
void main() {
  double x = 1.0lf
