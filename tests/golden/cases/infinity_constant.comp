// targets: es310 glsl450
#version 450
// An infinity written as an expression (1.0 / 0.0, folded by glslang) is carried as (+-Inf, 0),
// which is what native fp64 computes (issue 24: it was refused as "overflows even double precision");
// a literal that overflows (1e+309) stays an error (tests/extremes, ExtremesConstants).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double lowest; double highest; double x; };
double positive_infinity() { return 1.0 / 0.0; }
void main() {
  lowest = -positive_infinity();
  highest = min(x, 1.0lf / 0.0lf);
}
