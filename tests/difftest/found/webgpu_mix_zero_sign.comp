#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer In0 { double in0[]; };
layout(std430, binding = 1) writeonly buffer Out0 { dvec2 r0[]; };
void main() {
  uint gid = gl_GlobalInvocationID.x;
  double a = in0[gid] * 0.0lf;
  double z = in0[gid] * 0.0lf;
  r0[gid] = dvec2(mix(0.0lf, -8.0lf, a), mix(z, -8.0lf, 0.0lf));
}
