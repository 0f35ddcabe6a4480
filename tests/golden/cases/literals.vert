// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 300 es
// Double literals are split exactly at compile time: lo is not zero.
in vec3 offset;
out vec4 v_info;
const double EARTH_RADIUS = 6378137.0lf;
const double GM = 3.986004418e14lf;
double tenth = 0.1lf;
void main() {
  double r = EARTH_RADIUS + double(offset.x);
  double g = GM / (r * r);
  dvec3 p = dvec3(offset) * tenth + dvec3(1.0lf / 3.0lf, -2.5lf, 1e-20lf);
  v_info = vec4(float(g), float(r - EARTH_RADIUS), vec2(p.xy));
  gl_Position = vec4(vec3(p), 1.0);
}
