// targets: es310 es320 glsl450
#version 310 es
// Every scalar/vector operator on doubles: arithmetic, unary minus, compound
// assignment, ++/--, comparisons, ?:, swizzle reads and writes, indexing.
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
uniform int k;
void main() {
  uint i = gl_GlobalInvocationID.x;
  dvec4 v = dvec4(values[i]);
  double a = v.x, b = v.y;
  a += b;
  a -= 0.5lf;
  a *= -b;
  a /= 3.0lf;
  double c = a++;
  --b;
  dvec3 w = v.xyz;
  w.xz = dvec2(a, b);
  w[1] = c;
  w[k] += 1.0lf;
  w.y *= 2.0lf;
  bool less = a < b, ge = a >= b;
  double m = less ? a : (ge ? b : c);
  v = -dvec4(w, m);
  if (v == dvec4(0.0lf)) v.w = v[k];
  values[i] = vec4(v);
}
