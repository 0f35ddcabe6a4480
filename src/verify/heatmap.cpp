#include "verify/heatmap.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace doublet::verify {
namespace {

struct Rgb {
  unsigned char r, g, b;
};

Rgb colour(double bits) {
  if (std::isnan(bits)) return {128, 128, 128};
  const double t = std::clamp(bits / 60.0, 0.0, 1.0);
  // Piecewise: 0 → dark red, 0.4 (24 bits) → yellow, 0.75 (45 bits) → green, 1 → white.
  auto mix = [](double a, double b, double f) { return static_cast<unsigned char>(a + (b - a) * f); };
  if (t < 0.4) return {mix(96, 255, t / 0.4), mix(0, 220, t / 0.4), 0};
  if (t < 0.75) return {mix(255, 0, (t - 0.4) / 0.35), mix(220, 170, (t - 0.4) / 0.35), mix(0, 60, (t - 0.4) / 0.35)};
  return {mix(0, 255, (t - 0.75) / 0.25), mix(170, 255, (t - 0.75) / 0.25), mix(60, 255, (t - 0.75) / 0.25)};
}

}  // namespace

std::string write_heatmap_png(const std::string& path, const std::vector<double>& cells, int width, int height,
                              int scale) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return "cannot write " + path;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {  // libpng reports errors by longjmp
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return "libpng failed writing " + path;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width * scale), static_cast<png_uint_32>(height * scale), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  std::vector<unsigned char> row(static_cast<size_t>(width * scale) * 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Rgb c = colour(cells[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)]);
      for (int s = 0; s < scale; ++s) {
        unsigned char* p = &row[(static_cast<size_t>(x * scale + s)) * 3];
        p[0] = c.r;
        p[1] = c.g;
        p[2] = c.b;
      }
    }
    for (int s = 0; s < scale; ++s) png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(f) == 0 ? std::string() : "cannot finish " + path;
}

}  // namespace doublet::verify
