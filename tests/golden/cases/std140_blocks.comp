// targets: wgsl
#version 450
// std140 blocks (docs/web.md, "std140 blocks in WGSL"): a uniform block and std140 storage blocks
// whose arrays of doubles and floats WGSL would pack tighter than std140 (elements padded through
// df_std140_* wrappers, read as a[i].v), a struct member aligned to 16 with @align/@size, a struct
// only std140 blocks hold (its members at std140's offsets) and a runtime-sized padded array.
layout(local_size_x = 16) in;
struct Body { double mass; float radius[2]; dvec3 position; };
layout(std140, binding = 0) uniform Scene { double scale[3]; double origin; Body sun; float weights[2]; };
layout(std140, binding = 1) readonly buffer Bodies { Body bodies[4]; double masses[]; };
layout(std140, binding = 2) buffer Results { double r[]; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  Body b = bodies[i % 4u];
  double m = masses[i] + b.mass * scale[i % 3u] + double(b.radius[1] * weights[0]);
  r[i] = m + length(b.position - sun.position) * sun.mass - origin + double(masses.length());
}
