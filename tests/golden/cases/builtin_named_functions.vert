// targets: es100 es300 es310 es320 glsl330 glsl450
#version 450
// Desktop GLSL lets a shader overload built-in function names; GLSL ES does not (ES 3.00.6 §6.1).
// Lowered for ES, each user function named like a built-in becomes NAME_user, with its calls
// (mix_user2 below: mix_user is taken); desktop targets keep the names.
uniform double scale;
in vec4 position;
out float shade;
double mix_user;  // a global that already has the first choice of name
double exp(double x) { return 1.0lf + x + 0.5lf * x * x; }  // a user overload of a built-in name
float mix(float a, float b) { return 0.5 * (a + b); }        // a user float overload, same story
double distance2(double a, double b) { return (a - b) * (a - b); }
void main() {
  mix_user = scale;
  shade = mix(float(exp(scale)), float(distance2(mix_user, 1.0lf)));
  gl_Position = position;
}
