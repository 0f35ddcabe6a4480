// targets: es310 es320 glsl450
#version 460
// A desktop 4.60 shader: textures, images (with their format), explicit locations and bindings,
// a double view matrix and a flat double varying; nothing double survives.
layout(binding = 0) uniform sampler2D albedo;
layout(binding = 1, rgba32f) uniform readonly image2D heights;
uniform dmat4 view;
uniform dvec3 eye;
flat in dvec3 world;
in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
  dvec4 p = view * dvec4(world - eye, 1.0lf);
  vec4 h = imageLoad(heights, ivec2(uv * 16.0));
  double d = length(p.xyz) + double(h.x);
  color = texture(albedo, uv) * float(fract(d));
}
