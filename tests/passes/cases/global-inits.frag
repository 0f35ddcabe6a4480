// target: es300
#version 450
uniform double base;
double twice = base * 2.0lf;
out vec4 color;
void main() { color = vec4(float(twice)); }
