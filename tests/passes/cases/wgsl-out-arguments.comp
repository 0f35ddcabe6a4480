// target: wgsl
#version 450
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B { double v[]; };
layout(std430, binding = 1) buffer C { dvec2 w[]; };
double accumulate(inout double total, double x) { total += x; return total * 2.0lf; }
void scale(out double y, double x) { y = x * 3.0lf; }
void main() {
  double local = v[1];
  v[2] = accumulate(v[0], 1.5lf) + 1.0lf;  // a buffer element: a temporary, copied back
  scale(v[3], local);                      // the statement form
  uint k = uint(v.length());
  scale(v[k - 1u], local);                 // an index computed from locals: copied back to the same place
  scale(local, v[4]);                      // a whole local variable: passed as it is
  w[k].y = local;                          // a generated helper's inout parameter (df_assign_component_dvec2)
  w[k][0] = v[5] * 2.0lf;                  // its argument holds a call
  v[6] = modf(v[7], v[8]);                 // a rule's out parameter (df_modf's whole part)
}
