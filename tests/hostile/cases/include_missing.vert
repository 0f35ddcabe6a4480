#version 300 es
#include "does_not_exist.glsl"
void main() { gl_Position = vec4(0.0); }
