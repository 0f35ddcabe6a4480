// targets: es100 es300 glsl330 webgl2
#version 450
// The fp64 language on ES 1.00's terms: structs with double members (nested) as locals,
// parameters and uniforms; double arrays indexed by constants and loop indices; if/for with
// break/continue/return; double vertex inputs and outputs (varyings) split into hi/lo.
struct Frame { dvec3 origin; double scale; };
struct Camera { Frame frame; double weights[3]; };
uniform Camera camera;
in dvec3 position;
out dvec2 uv;
out vec4 tint;
dvec3 to_eye(Frame f, dvec3 p) { return (p - f.origin) * f.scale; }
double weigh(Camera c) {
  double sum = 0.0lf;
  for (int i = 0; i < 3; ++i) {
    if (c.weights[i] < 0.0lf) continue;
    if (sum > 10.0lf) break;
    sum += c.weights[i];
  }
  return sum;
}
void main() {
  dvec3 eye = to_eye(camera.frame, position);
  double w = weigh(camera);
  double history[2];
  history[0] = w;
  history[1] = history[0] * 0.5lf;
  uv = eye.xy * history[1];
  tint = vec4(float(w));
  if (w == 0.0lf) {
    gl_Position = vec4(0.0);
    return;
  }
  gl_Position = vec4(vec3(eye), 1.0);
}
