#include "curvature_reading.h"

#include <vcg_ext/curvature_colormap.h>

#include <QColor>

#include <unordered_map>

namespace curvature_inpaint {

CurvatureReading ReadCurvatureImage(const QImage& image, const QImage& mask) {
  CurvatureReading r;
  r.width = image.width();
  r.height = image.height();
  const size_t n = size_t(r.width) * r.height;
  r.t.resize(n);
  r.distance.resize(n);
  r.hole.resize(n);
  // Scan lines of one known format: QImage::pixel converts every call.
  const QImage image32 = image.convertToFormat(QImage::Format_RGB32);
  const QImage mask32 = mask.convertToFormat(QImage::Format_ARGB32);
  std::unordered_map<QRgb, vcg_ext::CurvatureColormap::Inverse> inverse;
  for (int y = 0; y < r.height; ++y) {
    const QRgb* colours = reinterpret_cast<const QRgb*>(image32.constScanLine(y));
    const QRgb* marks = reinterpret_cast<const QRgb*>(mask32.constScanLine(y));
    for (int x = 0; x < r.width; ++x) {
      const QRgb c = colours[x] & RGB_MASK;
      auto it = inverse.find(c);
      if (it == inverse.end())
        it = inverse
                 .emplace(c, vcg_ext::CurvatureColormap::Invert(
                                 Eigen::Vector3d(qRed(c), qGreen(c), qBlue(c))))
                 .first;
      const size_t i = size_t(y) * r.width + x;
      r.t[i] = it->second.t;
      r.distance[i] = it->second.distance;
      r.hole[i] = qGray(marks[x]) > 127;
    }
  }
  return r;
}

} // namespace curvature_inpaint
