#version 450
// A user struct with a dmat2 member built by its constructor (issue 12: once refused as "building
// a scalar or vector from the components of a double matrix"): values equal to native fp64.
layout(local_size_x = 1) in;
struct Frame { double scale; dmat2 rotation; };
layout(std430, binding = 0) buffer Io { double x; double y; double c; double s; double out_x; double out_y; };

void main() {
  Frame identity = Frame(1.0lf, dmat2(1.0lf));
  Frame f = Frame(x, dmat2(c, 0.0lf, 0.0lf, s) * identity.scale);  // products only: no cancellation
  Frame frames[2] = Frame[2](identity, f);
  dvec2 p = frames[1].rotation * dvec2(x, y) * frames[1].scale * frames[0].rotation[1].y;
  out_x = p.x;
  out_y = p.y;
}
