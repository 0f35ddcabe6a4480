#version 450 compatibility
// gl_FragData with two slots, lowered for es100.
uniform double gain;
flat in vec2 v;
void main() {
  double r = double(v.x) * gain + double(v.y);
  gl_FragData[0] = vec4(float(r), float(r - double(float(r))), 0.0, 1.0);
  gl_FragData[1] = vec4(v, float(gain), 1.0);
}
