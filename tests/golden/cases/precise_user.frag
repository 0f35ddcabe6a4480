// targets: es100 es300 es310 es320 glsl330 glsl450 webgl2
#version 450
// The user's own 'precise' on a double and on a float (issue 12): kept on es320 and glsl450,
// dropped (with one warning) on targets that have no 'precise' qualifier.
uniform double u;
varying vec2 uv;
void main() {
  precise double a = u * 3.0lf;
  precise float b = float(a) * 2.0 + uv.x;
  gl_FragColor = vec4(float(a), b, 0.0, 1.0);
}
