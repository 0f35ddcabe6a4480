// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// Global initialisers that are not constant expressions (issue 12): they read a double uniform,
// call a user function taking a double, and feed each other. They become assignments at the top
// of main, in declaration order, after the uniform's hi/lo join; constant ones stay in place.
uniform double farPlane;
const double kScale = 0.5lf;
double half_far = kScale * 2.0lf;
float k = 2.0 / log2(float(farPlane) + 1.0);
double scaled = farPlane * 2.0lf;
double twice(double x) { return x * 2.0lf; }
double t2 = twice(scaled);
varying vec2 uv;
void main() {
  gl_FragColor = vec4(k, float(scaled), float(t2 * half_far), uv.x);
}
