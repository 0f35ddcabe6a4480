// targets: wgsl
#version 450
// Vulkan GLSL's vertex and instance indices, which WGSL has (vertex_index, instance_index): a
// per-instance double offset read from a storage buffer, a per-vertex corner.
layout(std430, binding = 0) readonly buffer Offsets { dvec2 offsets[]; };
uniform dvec2 origin;
void main() {
  dvec2 p = offsets[gl_InstanceIndex] - origin;
  float corner = float(gl_VertexIndex & 1);
  gl_Position = vec4(vec2(p) + corner, 0.0, 1.0);
}
