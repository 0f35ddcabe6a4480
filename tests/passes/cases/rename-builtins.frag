// target: es300
#version 450
out vec4 color;
float dot(float a, float b, float c, float d) { return a * b + c * d; }
void main() { color = vec4(dot(1.0, 2.0, 3.0, 4.0)); }
