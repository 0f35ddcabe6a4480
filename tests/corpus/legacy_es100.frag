#version 450 compatibility
// Compatibility-style fragment shader as WebGL-era engines write it: gl_FragColor, varyings,
// a double accumulation; lowered for es100 it stays in ES 1.00 style.
uniform double exposure;
uniform double offset;
flat in vec3 radiance;
void main() {
  double luminance = dot(dvec3(radiance), dvec3(0.2126lf, 0.7152lf, 0.0722lf)) * exposure + offset;
  float hi = float(luminance);
  gl_FragColor = vec4(hi, float(luminance - double(hi)), 0.0, 1.0);
}
