// targets: es310 es320 glsl450 wgsl
#version 310 es
// Sum of two dvec2 uniforms written to a float buffer.
layout(local_size_x = 1) in;
uniform dvec2 a;
uniform dvec2 b;
layout(std430, binding = 0) buffer Result { vec2 result; };
void main() {
  result = vec2(a + b);
}
