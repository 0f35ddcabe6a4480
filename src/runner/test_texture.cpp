// The texture every sampler of a graphics job reads (runner.hpp, test_texture): a fixed pattern of
// exact floats, different in every channel and texel, so a shader that samples it computes with
// non-trivial values and a fetch from the wrong texel shows.
#include "runner/runner.hpp"

namespace doublet::runner {

std::vector<float> test_texture(TextureKind kind) {
  const uint32_t n = kTextureSize;
  const uint32_t layers = kind == TextureKind::Tex2D ? 1 : kind == TextureKind::Tex3D ? n : 6;
  std::vector<float> texels;
  texels.reserve(size_t{n} * n * layers * 4);
  for (uint32_t layer = 0; layer < layers; ++layer)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        // Multiples of 1/64 and 1/1024: exact in float, distinct per texel.
        texels.push_back(static_cast<float>(x + 1) / 16.0f + static_cast<float>(layer) / 64.0f);
        texels.push_back(static_cast<float>(y + 1) / 16.0f - static_cast<float>(layer) / 1024.0f);
        texels.push_back(static_cast<float>((x * 7 + y * 3 + layer * 5) % 16) / 4.0f - 1.5f);
        texels.push_back(1.0f + static_cast<float>(x * n + y) / 1024.0f);
      }
  return texels;
}

}  // namespace doublet::runner
