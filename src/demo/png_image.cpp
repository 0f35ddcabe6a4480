// libpng encoder and strip composition for the demos' pictures.
#include "demo/png_image.hpp"

#include <png.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace doublet::demo {

Image::Image(int w, int h, uint32_t fill) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4) {
  for (size_t i = 0; i < rgba.size(); i += 4) std::memcpy(&rgba[i], &fill, 4);
}

std::string write_png(const std::string& path, const Image& image) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return "cannot write " + path;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::string error;
  if (!info) {
    error = "libpng: out of memory";
  } else if (setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
    error = "libpng failed writing " + path;
  } else {
    png_init_io(png, f);
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
                 PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_compression_level(png, 9);  // the pictures are committed: keep them small
    png_write_info(png, info);
    for (int y = 0; y < image.height; ++y) png_write_row(png, image.at(0, y));
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  if (std::fclose(f) != 0 && error.empty()) error = "cannot write " + path;
  return error;
}

Image side_by_side(const std::vector<Image>& images, int gap, uint32_t gap_color) {
  int w = 0, h = 0;
  for (const Image& im : images) {
    w += im.width + (w ? gap : 0);
    h = std::max(h, im.height);
  }
  Image out(w, h, gap_color);
  int x0 = 0;
  for (const Image& im : images) {
    for (int y = 0; y < im.height; ++y) std::memcpy(out.at(x0, y), im.at(0, y), static_cast<size_t>(im.width) * 4);
    x0 += im.width + gap;
  }
  return out;
}

}  // namespace doublet::demo
