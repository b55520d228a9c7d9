// The montage: every hole's pictures in one image a person can read at 100 %: a row per hole
// with its number and size, each tile captioned with its kind, identical variations drawn
// once, the fill chosen framed with the reason beneath it, and the colours' legend on top.
#pragma once

#include "pipeline/hole_fill.h"

#include <QImage>

#include <string>
#include <vector>

namespace curvature_inpaint {

/// One tile of a row: its caption, the variations it stands for and where it lies.
struct MontageTile {
  std::string caption;
  int first = 0, last = 0;    ///< variations first..last (1-based); 0: not a variation
  int x = 0, y = 0, size = 0; ///< in the row
};

/// One hole's row, and what it shows where (written as montage.json beside the picture).
struct MontageRow {
  QImage image;
  int hole = 0; ///< 1-based
  int boundary_edges = 0;
  std::vector<MontageTile> tiles;
  size_t framed = 0; ///< the tile of the fill chosen
  std::string reason;
};

/// Hole k's row: the curvature image with the smooth fill, the hole's mask, its variations
/// and, where there is one, the final image. `framed`: the variation chosen (1-based), 0 for
/// the smooth fill; `reason` is written beneath it.
MontageRow MakeMontageRow(const HoleVariations& hv, size_t k, int framed, const std::string& reason,
                          const QImage& final_image);

/// Hole k's row of the `images` command: its curvature image, the same with the hole
/// transparent, and its mask.
MontageRow MakeImagesRow(const HoleImage& hi, size_t k, int boundary_edges);

/// The rows stacked under the legend and written as a PNG to `path`, and beside it (the same
/// name ending in .json) where each hole's row and tiles lie, for scripts; nothing is written
/// where there are no rows. Throws std::runtime_error where a file cannot be written.
void SaveMontage(const std::vector<MontageRow>& rows, const std::string& path);

} // namespace curvature_inpaint
