// targets: es100 es300 es320 glsl450 webgl2
// options: --mode rte
#version 300 es
// Mode rte: positions stay hi/lo; the difference of two of them is the exact float-float
// subtraction, rounded to float once; everything after it is float. A float result stored
// back into a double variable is widened (lo = 0).
in dvec3 position;
uniform dvec3 eye;
uniform double scale;
uniform mat4 viewProj;
out float distanceToEye;

void main() {
  vec3 rel = vec3(position - eye);
  dvec3 offset = position - eye;
  double d = length(offset) * scale;
  distanceToEye = float(d);
  gl_Position = viewProj * vec4(rel, 1.0);
}
