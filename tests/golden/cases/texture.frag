// targets: wgsl
#version 450
// Textures are refused with a position (WGSL separates textures and samplers).
uniform sampler2D image;
uniform double gain;
layout(location = 0) out vec4 color;
void main() {
  color = texture(image, vec2(0.5)) * float(gain);
}
