// A double crosses a float-only interface (a buffer, a vec2 varying) as (hi, lo).
double load_pair(vec2 p) { return double(p.x) + double(p.y); }

vec2 store_pair(double d) {
  float hi = float(d);
  return vec2(hi, float(d - double(hi)));
}
