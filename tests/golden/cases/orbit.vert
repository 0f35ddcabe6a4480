// targets: wgsl
#version 450
// A vertex shader with a double uniform and attributes split into hi/lo (relative to eye).
layout(location = 0) in vec3 position_hi;
layout(location = 1) in vec3 position_lo;
uniform dvec3 eye;
uniform mat4 view_projection;
out vec3 color;
void main() {
  dvec3 p = dvec3(position_hi) + dvec3(position_lo) - eye;
  color = vec3(abs(p));
  gl_Position = view_projection * vec4(vec3(p), 1.0);
}
