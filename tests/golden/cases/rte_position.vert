// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 300 es
// Relative-to-eye: subtract two dvec3s, then narrow to float.
in dvec3 position;
uniform dvec3 eye;
uniform mat4 viewProj;
void main() {
  gl_Position = viewProj * vec4(vec3(position - eye), 1.0);
}
