#version 300 es
in dvec3 pos;
in vec3 pos_hi;
void main() { gl_Position = vec4(vec3(pos) + pos_hi, 1.0); }
