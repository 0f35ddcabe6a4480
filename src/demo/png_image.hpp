// RGBA8 images for the demos, written with libpng.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace doublet::demo {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // row 0 is the top row
  Image() = default;
  Image(int w, int h, uint32_t fill = 0xff000000u);  // fill as 0xAABBGGRR
  uint8_t* at(int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
  const uint8_t* at(int x, int y) const { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; }
};

// Empty on success, else why the file could not be written.
std::string write_png(const std::string& path, const Image& image);

// The images left to right with `gap` pixels of `gap_color` between them (heights: the tallest).
Image side_by_side(const std::vector<Image>& images, int gap = 4, uint32_t gap_color = 0xffffffffu);

}  // namespace doublet::demo
