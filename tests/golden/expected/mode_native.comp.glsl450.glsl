#version 450 core
precision highp float;
precision highp int;
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

layout(std430, binding = 0) buffer Data {
  double x[];
};
uniform double scale;


void main()
{
  uint i = gl_GlobalInvocationID.x;
  double a = x[2u * i];
  x[2u * i + 1u] = sqrt(a) * scale + 0.10000000000000001lf;
}
