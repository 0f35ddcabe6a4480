#version 450
// Reads a texture (the runner binds its fixed test pattern to every sampler in both runs) and
// mixes the texel into double arithmetic; the double result leaves as a (hi, lo) pair.
uniform sampler2D albedo;
uniform sampler3D volume;
flat in dvec2 uv;
out vec4 color;
void main() {
  dvec2 t = uv * 3.0lf + 0.25lf;
  vec4 c = texture(albedo, vec2(fract(t)));
  vec4 v = texture(volume, vec3(0.3, 0.6, 0.8));
  double r = t.x * double(c.r) + t.y * double(c.a) + double(v.b);
  color = vec4(float(r), float(r - double(float(r))), c.g, v.r);
}
