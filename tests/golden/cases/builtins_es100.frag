// targets: es100 es300 glsl330
#version 450
// The fp64 built-ins that GLSL ES 1.00 can host (no uint, no bit operations: frexp, ldexp,
// isnan, isinf, packDouble2x32 and unpackDouble2x32 are diagnosed there).
uniform double scale;
uniform dvec3 light;
in vec3 normal_in;
out vec4 color;
void main() {
  dvec3 n = normalize(dvec3(normal_in) * scale);
  double d = max(dot(n, normalize(light)), 0.0lf);
  double t = smoothstep(0.0lf, 1.0lf, fract(d * 4.0lf)) + mod(d, 0.25lf) + step(0.5lf, d);
  dvec3 r = reflect(-light, n) + cross(n, light) * clamp(d, 0.0lf, 1.0lf) + mix(n, light, t);
  color = vec4(vec3(abs(r) + floor(r) + sign(r)), float(length(r) + distance(n, light) + inversesqrt(d + 1.0lf)));
}
