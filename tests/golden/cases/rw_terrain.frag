// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450 core
// The fragment side of rw_terrain.vert: the matching input block under another instance name, a
// lighting uniform block, textures, a global initialiser from a double uniform, local consts.
in TerrainData {
  flat dvec3 world;
  vec3 normal;
  vec2 uv;
  float fog;
} fin;
layout(std140, binding = 1) uniform Lighting {
  vec4 sun_direction;
  vec4 sun_color;
  double exposure;
};
uniform sampler2D albedo;
uniform samplerCube sky;
uniform double sea_level;
layout(location = 0) out vec4 frag_color;

float sea_mask = 0.0;
double altitude_scale = 1.0lf / max(sea_level, 1.0lf);

void main() {
  const double altitude = length(fin.world) - sea_level;
  const float shade = max(dot(normalize(fin.normal), sun_direction.xyz), 0.0);
  vec3 base = texture(albedo, fin.uv).rgb;
  if (altitude < 0.0lf) {
    sea_mask = 1.0;
    base = mix(base, texture(sky, reflect(-sun_direction.xyz, fin.normal)).rgb, 0.5);
  }
  float exposed = float(exposure * altitude_scale * (altitude + sea_level));
  frag_color = vec4(mix(base * sun_color.rgb * shade * exposed, vec3(0.6, 0.7, 0.8), fin.fog), 1.0 - sea_mask * 0.2);
}
