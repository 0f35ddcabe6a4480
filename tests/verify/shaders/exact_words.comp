#version 450
// verify --mode exact: double inputs and outputs in storage buffers (the lowered shader reads and
// writes the same bytes as binary64 words), a dvec3 result, + * / sqrt and a conversion.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In { dvec2 xy[]; };
layout(std430, binding = 1) writeonly buffer Sums { double r[]; };
layout(std430, binding = 2) writeonly buffer Vecs { dvec3 q[]; };
layout(std430, binding = 3) writeonly buffer Floats { float f[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  double x = xy[i].x, y = xy[i].y;
  r[i] = x + y;
  q[i] = dvec3(x * y, x / y, sqrt(abs(x)) - y);
  f[i] = float(x - y);
}
