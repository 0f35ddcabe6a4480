// targets: es310 es320 glsl450
#version 450
// Every fp64 built-in of GLSL 4.60 on scalars and vectors: common, geometric, comparison,
// classification, bit-level (frexp, ldexp, packDouble2x32, unpackDouble2x32).
layout(local_size_x = 8) in;
layout(std430, binding = 0) buffer Data { double xs[]; };
layout(std430, binding = 1) buffer Bits { uvec2 words[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double a = xs[i], b = xs[i + 1u], ip;
  dvec3 v = dvec3(a, b, -a), u = dvec3(b, 1.0lf, a), vi;
  int e;
  double s = sign(a) + floor(a) + ceil(a) + trunc(a) + round(a) + roundEven(a) + fract(a) + mod(a, b)
           + modf(a, ip) + min(a, b) + max(a, b) + clamp(a, 0.0lf, b) + mix(a, b, 0.25lf) + mix(a, b, a < b)
           + step(b, a) + smoothstep(0.0lf, b, a) + fma(a, b, 1.0lf) + frexp(a, e) + ldexp(a, e) + abs(a)
           + sqrt(abs(a)) + inversesqrt(abs(b)) + length(v) + distance(v, u) + dot(v, u);
  dvec3 g = cross(v, u) + normalize(v) + faceforward(v, u, v) + reflect(v, u) + refract(normalize(v), normalize(u), 0.5lf)
          + mod(v, 2.0lf) + modf(v, vi) + mix(v, u, bvec3(true, false, true)) + step(0.5lf, v) + ldexp(v, ivec3(e))
          + clamp(v, u, u + 1.0lf) + abs(v) + floor(v) + fract(v) + sign(u);
  bool c = any(lessThan(v, u)) || any(lessThanEqual(v, g)) || all(greaterThan(g, u)) || any(greaterThanEqual(u, v))
         || all(equal(v, g)) || any(notEqual(g, u));
  if (isnan(s) || isinf(s) || any(isnan(g)) || any(isinf(g)) || c) s = 0.0lf;
  words[i] = unpackDouble2x32(s + g.x);
  xs[i] = packDouble2x32(words[i + 1u]) + ip + vi.y;
}
