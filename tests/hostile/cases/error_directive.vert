#version 300 es
#error this shader is not finished
void main() { }
