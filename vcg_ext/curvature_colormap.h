// Stage 5: the rainbow colour map of the curvature images and its exact inverse.
//
// Blue is low (convex), green flat, red high (concave), as in the paper's figures. The map is
// one polyline of knots in RGB; the inverse is the nearest point on that polyline, so colours
// an inpainter returns slightly off the palette still read back as curvature, with their
// distance to the palette as a measure of how much to trust them.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vcg_ext {

struct Rgb8 {
  uint8_t r = 0, g = 0, b = 0;
};

class CurvatureColormap {
public:
  /// Knots at t = 0, 1/4, 1/2, 3/4, 1: blue, cyan, green, yellow, red.
  static const std::array<Eigen::Vector3d, 5>& Knots() {
    static const std::array<Eigen::Vector3d, 5> knots{
        {{0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}}};
    return knots;
  }

  /// The colour-map value of signed mean curvature h where `scale` maps to the map's ends:
  /// 0.5 + 0.5 h / scale, clamped to [0, 1] (convex, negative h, towards blue).
  static double Value(double h, double scale) {
    return std::max(0.0, std::min(1.0, 0.5 + 0.5 * h / scale));
  }

  /// The colour of t in [0, 1] (clamped), as exact RGB in [0, 255].
  static Eigen::Vector3d Color(double t) {
    const auto& k = Knots();
    t = std::max(0.0, std::min(1.0, std::isfinite(t) ? t : 0.5));
    const double s = t * (k.size() - 1);
    const int i = std::min(int(s), int(k.size()) - 2);
    return k[i] + (s - i) * (k[i + 1] - k[i]);
  }

  static Rgb8 Color8(double t) {
    const Eigen::Vector3d c = Color(t);
    return {uint8_t(std::lround(c.x())), uint8_t(std::lround(c.y())), uint8_t(std::lround(c.z()))};
  }

  struct Inverse {
    double t = 0.5;      ///< the value whose colour is nearest
    double distance = 0; ///< RGB distance (0-255 units) to the palette: 0 = on it
  };

  /// The nearest point of the palette to `rgb` (0-255 per channel).
  static Inverse Invert(const Eigen::Vector3d& rgb) {
    const auto& k = Knots();
    Inverse best;
    best.distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i + 1 < k.size(); ++i) {
      const Eigen::Vector3d d = k[i + 1] - k[i];
      const double u = std::max(0.0, std::min(1.0, (rgb - k[i]).dot(d) / d.squaredNorm()));
      const double dist = (k[i] + u * d - rgb).norm();
      if (dist < best.distance) best = {(i + u) / double(k.size() - 1), dist};
    }
    return best;
  }
  static Inverse Invert(const Rgb8& c) { return Invert(Eigen::Vector3d(c.r, c.g, c.b)); }
};

} // namespace vcg_ext
