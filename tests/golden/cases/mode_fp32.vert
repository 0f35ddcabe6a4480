// targets: es300 glsl450 webgl2
// options: --mode fp32
#version 300 es
// Mode fp32: every double is demoted to float: interfaces become plain float variables
// (no _hi/_lo), arithmetic, parameters and return values are float, constants are rounded.
in dvec3 position;
uniform dvec3 eye;
uniform dmat4 model;
uniform mat4 viewProj;
out float height;

double scaled(double x, int k) {
  return x * 0.5lf + double(k);
}

void main() {
  dvec3 world = (model * dvec4(position, 1.0lf)).xyz;
  dvec3 rel = world - eye;
  double h = scaled(length(world), 2);
  height = float(h - 6378137.0lf);
  gl_Position = viewProj * vec4(vec3(rel), 1.0);
}
