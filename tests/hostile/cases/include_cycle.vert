#version 300 es
#include "include_cycle_b.glsl"
void main() { gl_Position = vec4(0.0); }
