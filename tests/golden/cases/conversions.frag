// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 300 es
precision highp float;
// Conversions between double and float/int/uint/bool, vector sizes,
// built-ins abs min max sqrt dot length.
flat in ivec2 cell;
flat in uvec2 id;
uniform dvec3 dir;
uniform double bias;
out vec4 color;
void main() {
  double x = double(cell.x) + double(id.y) + double(true);
  dvec2 d2 = dvec2(cell) + dvec2(id);
  dvec4 d4 = dvec4(d2, x, 1.0);
  int n = int(x) + ivec2(d2).y;
  uint u = uint(abs(x));
  bool nz = bool(x);
  double len = length(dir) + dot(dir, dvec3(d4)) + sqrt(abs(bias));
  double lo = min(x, bias), hi = max(dvec2(x), d2).y;
  color = vec4(float(len), float(lo + hi), float(n) + float(u), nz ? 1.0 : 0.0);
}
