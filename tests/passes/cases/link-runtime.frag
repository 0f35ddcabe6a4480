// target: es300
#version 450
uniform double a;
out vec4 color;
void main() { color = vec4(float(a + a)); }
