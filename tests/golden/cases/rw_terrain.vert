// targets: es300 es310 es320 glsl330 glsl450 webgl2
#version 450 core
// Real-world style (issue 12): a planet-scale terrain vertex shader as engines write it. Camera in
// a std140 uniform block with doubles, a height map read in the vertex stage, global state set
// from uniforms (global initialisers), an output interface block, helper functions.
layout(std140, binding = 0) uniform Camera {
  dmat4 view;
  dvec3 eye;
  mat4 projection;
  double planet_radius;
} camera;
uniform sampler2D height_map;
uniform dvec2 tile_origin;
uniform double tile_size;

layout(location = 0) in vec2 grid;  // 0..1 within the tile

out TerrainData {
  flat dvec3 world;
  vec3 normal;
  vec2 uv;
  float fog;
} vout;

const double kHeightScale = 8848.0lf;
double metres_per_texel = tile_size / 256.0lf;
float fog_density = float(1.0lf / camera.planet_radius) * 1000.0;

dvec3 sphere_point(dvec2 lonlat, double radius) {
  double c = cos(float(lonlat.y));
  return radius * dvec3(c * cos(float(lonlat.x)), c * sin(float(lonlat.x)), sin(float(lonlat.y)));
}

void main() {
  dvec2 lonlat = tile_origin + dvec2(grid) * tile_size;
  float h = textureLod(height_map, grid, 0.0).r;
  double radius = camera.planet_radius + double(h) * kHeightScale;
  dvec3 world = sphere_point(lonlat, radius);
  dvec3 relative = world - camera.eye;  // small: float is enough from here on
  vout.world = world;
  vout.normal = normalize(vec3(world));
  vout.uv = grid + vec2(float(metres_per_texel));
  vout.fog = 1.0 - exp(-fog_density * float(length(relative)));
  gl_Position = camera.projection * vec4(mat4(camera.view) * vec4(vec3(relative), 1.0));
}
