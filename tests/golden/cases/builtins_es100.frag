// targets: es100 es300 glsl330 webgl2
#version 450
// Every fp64 built-in that GLSL ES 1.00 can host (frexp, ldexp, isnan, isinf, packDouble2x32 and
// unpackDouble2x32 need integer bit operations and are diagnosed there).
uniform double scale;
uniform dvec3 light;
in vec3 normal_in;
out vec4 color;
void main() {
  dvec3 n = normalize(dvec3(normal_in) * scale);
  double d = max(dot(n, normalize(light)), 0.0lf), ip;
  double t = smoothstep(0.0lf, 1.0lf, fract(d * 4.0lf)) + mod(d, 0.25lf) + step(0.5lf, d) + modf(d * 8.0lf, ip)
           + trunc(d) + round(d) + roundEven(d) + ceil(d) + min(d, scale) + fma(d, d, scale) + sqrt(d)
           + mix(d, scale, d < scale);
  dvec3 r = reflect(-light, n) + cross(n, light) * clamp(d, 0.0lf, 1.0lf) + mix(n, light, t)
          + faceforward(n, light, n) + refract(n, normalize(light), 0.75lf) + mix(n, light, bvec3(true, false, true));
  bool c = any(lessThan(n, r)) || all(lessThanEqual(n, r)) || any(greaterThan(n, r)) || any(greaterThanEqual(n, r))
         || all(equal(n, r)) || any(notEqual(n, r));
  color = vec4(vec3(abs(r) + floor(r) + sign(r)), float(length(r) + distance(n, light) + inversesqrt(d + 1.0lf) + ip))
        + (c ? 1.0 : 0.0);
}
