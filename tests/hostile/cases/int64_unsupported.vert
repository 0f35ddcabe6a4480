#version 300 es
#extension GL_ARB_gpu_shader_int64 : require
uniform uint64_t big;
void main() { gl_Position = vec4(float(big)); }
