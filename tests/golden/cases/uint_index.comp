// targets: es310 es320 glsl450
#version 310 es
// A double vector indexed by a uint loop variable, read as a function argument
// and written, plain and compound (the component helpers take an int index).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { vec2 v[]; };
vec2 f(double d) { return vec2(float(d)); }
void main() {
  dvec3 p = dvec3(v[0].x);
  for (uint i = 0u; i < 3u; ++i) {
    v[i] = f(p[i]);
    p[i] = double(v[i].y);
    p[i] += 1.0lf;
  }
  v[3] = vec2(p.xy);
}
