#version 450
// Struct constants folded by glslang (issue 12: once refused as "constant structures are not
// supported"): the lowered values must equal native fp64.
layout(local_size_x = 1) in;
struct Orbit { dvec2 z; int n; double r2; };
const Orbit kStart[2] = Orbit[2](Orbit(dvec2(0.1lf, 1.0lf / 3.0lf), 1, 2.0lf / 7.0lf),
                                 Orbit(dvec2(-0.7lf, 1e-9lf), 2, 1.0lf / 9.0lf));
layout(std430, binding = 0) buffer Io { double x; int pick; double y; double r; };

void main() {
  Orbit o = Orbit(dvec2(0.3lf, 1.0lf / 7.0lf), 3, 0.0lf);
  Orbit s = kStart[pick & 1];
  o.z = o.z * s.z * x;
  o.r2 = dot(o.z, o.z) + s.r2 * double(s.n + o.n);
  y = o.z.y;
  r = o.r2;
}
