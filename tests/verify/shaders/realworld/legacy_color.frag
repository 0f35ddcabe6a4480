#version 450 compatibility
// Compatibility-style output: gl_FragColor (ES 1.00 / compatibility), lowered for es100.
uniform double gain;
flat in vec2 v;
void main() {
  double r = double(v.x) * gain + double(v.y);
  gl_FragColor = vec4(float(r), float(r - double(float(r))), 0.0, 1.0);
}
