// targets: es310 es320 glsl450
#version 450
// Atomic counters and textures next to doubles (issue 12): float/int-only constructs pass
// through as written (binding and offset kept); es100/es300/glsl330 refuse atomic_uint.
layout(binding = 0, offset = 0) uniform atomic_uint fragments;
layout(binding = 0, offset = 4) uniform atomic_uint far_fragments;
uniform sampler2D albedo;
uniform double far_plane;
in vec2 uv;
flat in double depth;
out vec4 color;
void main() {
  uint n = atomicCounterIncrement(fragments);
  if (depth > far_plane * 0.5lf) atomicCounterIncrement(far_fragments);
  color = texture(albedo, uv) * float(depth / far_plane) + vec4(float(n & 1u));
}
