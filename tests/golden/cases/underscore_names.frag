#version 300 es
// Names ending in '_': split interface names and renamed shadowing locals never contain "__",
// which GLSL reserves (scale_ + _hi is scale_hi, a second s_ is s_1).
precision highp float;
uniform double scale_;
uniform dvec2 offset_;
out vec4 color;
void main() {
  double s_ = scale_ * offset_.x;
  { double s_ = 3.0lf * offset_.y; color = vec4(float(s_)); }
  color += vec4(float(s_));
}
