// targets: wgsl
#version 450
// The numeric kernel of the WebGPU accuracy tests: element i applies operation op = i / per_op
// (0 add, 1 sub, 2 mul, 3 div, 4 sqrt, 5 (x+y)-x, 6 (x*y+x)/y) to doubles stored as float pairs.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 xy[]; };  // x.hi, x.lo, y.hi, y.lo
layout(std430, binding = 1) buffer Outputs { vec2 r[]; };          // hi, lo
uniform uint per_op;
uniform uint count;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  int op = int(i / per_op);
  double x = double(xy[i].x) + double(xy[i].y);
  double y = double(xy[i].z) + double(xy[i].w);
  double z;
  switch (op) {
    case 0: z = x + y; break;
    case 1: z = x - y; break;
    case 2: z = x * y; break;
    case 3: z = x / y; break;
    case 4: z = sqrt(x); break;
    case 5: z = (x + y) - x; break;
    default: z = (x * y + x) / y; break;
  }
  float hi = float(z);
  r[i] = vec2(hi, float(z - double(hi)));
}
