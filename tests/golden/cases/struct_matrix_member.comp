// targets: es310 es320 glsl450
#version 450
// User structs with a dmat2 member, built by constructors (constant and run-time) and in an
// array constructor: the struct takes the lowered df_dmat2 whole.
layout(local_size_x = 1) in;
struct Frame { double scale; dmat2 rotation; };
layout(std430, binding = 0) buffer Io { double x; double c; double out_x; };

void main() {
  Frame identity = Frame(1.0lf, dmat2(1.0lf));
  Frame f = Frame(x, dmat2(c, 0.0lf, 0.0lf, c));
  Frame frames[2] = Frame[2](identity, f);
  out_x = (frames[1].rotation * dvec2(x, 1.0lf)).x * frames[0].scale;
}
