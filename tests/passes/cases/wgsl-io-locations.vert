// target: wgsl
#version 450
// WGSL gives every entry-point input and output a @location: those the shader leaves to the linker
// take the first free run in declaration order, after the hi/lo split and around explicit ones.
in float size;                         // not 0: normal holds it (a running counter gave both 0)
layout(location = 0) in vec3 normal;
in dvec3 position;
out vec3 shade;
layout(location = 0) out float depth;
uniform dvec3 eye;
void main() {
  dvec3 p = position - eye;
  shade = normal * size;
  depth = float(p.z);
  gl_Position = vec4(vec3(p), 1.0);
}
