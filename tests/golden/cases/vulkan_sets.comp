// targets: wgsl
#version 450
// Vulkan GLSL's descriptor sets, which WGSL has as bind groups: layout(set = N) is @group(N), each
// group with its own bindings (a block without a binding takes its group's next free one).
layout(local_size_x = 64) in;
layout(set = 1, binding = 0) uniform Camera { dvec4 origin; double scale; } cam;
layout(set = 0, binding = 0) readonly buffer Points { dvec4 p[]; };
layout(set=2,binding=0) writeonly buffer Out { dvec4 o[]; };
layout(std430, set = 2)
  buffer Extra { double e[]; };
uniform double bias;
void main() {
  uint i = gl_GlobalInvocationID.x;
  o[i] = (p[i] - cam.origin) * cam.scale + bias;
  e[i] += 1.0lf;
}
