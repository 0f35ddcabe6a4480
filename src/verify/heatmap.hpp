// Writes a grid of correct bits as a PNG heatmap (libpng): dark red 0 bits → yellow ~24 → green
// at the bound → white at 60; NaN cells (no sample) grey.
#pragma once

#include <string>
#include <vector>

namespace doublet::verify {

// cells[row * width + col]; row 0 is drawn at the top. Each cell becomes scale × scale pixels.
// Empty on success, else why not.
std::string write_heatmap_png(const std::string& path, const std::vector<double>& cells, int width, int height,
                              int scale);

}  // namespace doublet::verify
