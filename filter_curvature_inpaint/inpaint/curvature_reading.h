// A curvature image read back: the value the colour map painted at every pixel, and which
// pixels the mask marks as the hole. The embedded inpainter starts from it and the variation
// score judges with it, so both read an image the same way.
#pragma once

#include <QImage>

#include <vector>

namespace curvature_inpaint {

struct CurvatureReading {
  int width = 0, height = 0;
  std::vector<double> t;        ///< vcg_ext::CurvatureColormap::Invert's t, row by row
  std::vector<double> distance; ///< the colour's distance from the map (0-441)
  std::vector<char> hole;       ///< 1 where the mask is light (grey above 127)
};

/// Reads `image` back through the colour map's inverse and `mask` (white on the hole), any
/// pixel formats; each distinct colour is inverted once, since a smooth image repeats its
/// colours. Precondition: both the same size.
CurvatureReading ReadCurvatureImage(const QImage& image, const QImage& mask);

} // namespace curvature_inpaint
