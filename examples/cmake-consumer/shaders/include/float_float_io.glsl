// Buffers cannot hold doubles in GLSL ES: a double crosses the interface as a vec2
// (hi, lo), the two floats doublet::split() makes on the host.
double load_pair(vec2 p) { return double(p.x) + double(p.y); }

vec2 store_pair(double d) {
  float hi = float(d);
  return vec2(hi, float(d - double(hi)));
}
