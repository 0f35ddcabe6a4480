#version 450
// Textured terrain tile: a height map and a sky cube map sampled at float coordinates, the
// elevation accumulated in double over a tile placed far from the origin.
#include "engine_common.glsl"

uniform sampler2D heightmap;
uniform samplerCube sky;
uniform dvec2 tile_origin;
uniform double tile_size;

flat in dvec2 local;          // position inside the tile, 0..1

out vec4 elevation;           // (elevation hi, lo, slope hi, lo)
out vec4 sky_color;

void main() {
  dvec2 world = tile_origin + local * tile_size;
  vec4 texel = texture(heightmap, vec2(local));
  double h = double(texel.r) * 100.0lf + double(texel.a);
  double slope = dot(world, dvec2(1.0e-3lf, 2.0e-3lf));
  elevation = vec4(hi_lo(h + slope), hi_lo(slope));
  sky_color = texture(sky, vec3(0.3, 1.0, 0.2));
}
