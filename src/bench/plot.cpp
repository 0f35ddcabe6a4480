#include "bench/plot.hpp"

#include <cmath>
#include <cstdlib>

#include "demo/png_image.hpp"

namespace doublet::bench {
namespace {

constexpr int kWidth = 720, kHeight = 480, kMargin = 40;
constexpr double kMinBits = 20, kMaxBits = 56, kMinLog = -1, kMaxLog = 3;

int px(double bits) { return kMargin + static_cast<int>((bits - kMinBits) / (kMaxBits - kMinBits) * (kWidth - 2 * kMargin)); }
int py(double ratio) {
  const double l = std::log10(ratio);
  return kHeight - kMargin - static_cast<int>((l - kMinLog) / (kMaxLog - kMinLog) * (kHeight - 2 * kMargin));
}

void put(demo::Image& img, int x, int y, uint32_t abgr) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  uint8_t* p = img.at(x, y);
  p[0] = abgr & 0xff, p[1] = (abgr >> 8) & 0xff, p[2] = (abgr >> 16) & 0xff, p[3] = 0xff;
}

void hline(demo::Image& img, int y, uint32_t c, int thick) {
  for (int t = 0; t < thick; ++t)
    for (int x = kMargin; x <= kWidth - kMargin; ++x) put(img, x, y + t, c);
}
void vline(demo::Image& img, int x, uint32_t c, int thick) {
  for (int t = 0; t < thick; ++t)
    for (int y = kMargin; y <= kHeight - kMargin; ++y) put(img, x + t, y, c);
}

uint32_t colour(Mode m) {
  switch (m) {
    case Mode::Fp32: return 0xffcc6600u;      // blue
    case Mode::Rte: return 0xff0099ffu;       // orange
    case Mode::Df64Fast: return 0xffcc3399u;  // purple
    case Mode::Df64: return 0xff2222ddu;      // red
    case Mode::Df64Int: return 0xff222288u;   // dark red
    case Mode::Native: return 0xff22aa22u;    // green
    case Mode::Exact: return 0xff666666u;     // grey
  }
  return 0xff000000u;
}

}  // namespace

std::string write_cost_plot(const BenchReport& report, const std::string& path, int* points) {
  demo::Image img(kWidth, kHeight, 0xffffffffu);
  for (int b = 20; b <= 56; b += 4) vline(img, px(b), 0xffe0e0e0u, 1);
  for (double b : {24.0, 48.0, 53.0}) vline(img, px(b), 0xffa0a0a0u, 2);
  for (int d = -1; d <= 3; ++d) hline(img, py(std::pow(10.0, d)), d == 0 ? 0xff606060u : 0xffc0c0c0u, d == 0 ? 2 : 1);
  int drawn = 0;
  for (const Measurement& r : report.rows) {
    if (!r.ok || !r.time_vs_fp32) continue;
    if (r.bits < 0) continue;  // not measured (user shaders)
    const double bits = std::max(r.bits, kMinBits);  // below 20 bits (rte, fp32 chains): the left edge
    const double ratio = std::min(std::max(*r.time_vs_fp32, 0.1), 1000.0);
    const int cx = px(bits) + (r.backend == runner::Backend::Gles ? 3 : -3), cy = py(ratio);
    for (int dy = -3; dy <= 3; ++dy)
      for (int dx = -3; dx <= 3; ++dx)
        if (r.backend == runner::Backend::Vulkan || std::abs(dx) == 3 || std::abs(dy) == 3)
          put(img, cx + dx, cy + dy, colour(r.mode));
    ++drawn;
  }
  if (points) *points = drawn;
  return demo::write_png(path, img);
}

}  // namespace doublet::bench
