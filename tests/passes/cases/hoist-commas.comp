// target: wgsl
#version 450
// WGSL has no comma operator: the first comma moves before its statement; the second, under &&
// (evaluated only sometimes), is an if by then (wgsl-expression-effects) and moves inside it. The
// two calls of take() (a global as an inout argument: two commas) move in their order.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double x; double y; float f; bool ok; };
double t;
double take(inout double v) { double old = v; v = v / 3.0lf; return old; }
void main() {
  y = (t = x * 2.0lf, t * t) + x;
  ok = f > 0.0 && (f = 2.0, f > 1.0);
  x = take(t) - take(t);
}
