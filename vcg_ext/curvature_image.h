// Stage 7: the curvature image of a patch and the mask of its hole (paper, section 3.5).
//
// Each triangle is rasterized in UV with its vertices' curvature values interpolated
// barycentrically and coloured per pixel (crisper than a lookup in a vertex-coloured texture,
// and always on the palette, so the image inverts exactly). A pixel belongs to the hole when
// its centre lies in one of the hole's coarse-fill triangles.
#pragma once

#include "curvature_colormap.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace vcg_ext {

struct CurvatureImage {
  int size = 0;
  std::vector<uint8_t> rgb;  ///< size*size*3, row 0 at the top (v = 1)
  std::vector<uint8_t> hole; ///< size*size, 1 on the hole
  int HolePixels() const { return int(std::count(hole.begin(), hole.end(), 1)); }
};

/// Rasterizes the triangles (`uv` in [0,1]^2, per-vertex `t` in [0,1] for the colour map) into
/// a size x size image; `is_fill` marks the hole's triangles.
inline CurvatureImage RasterizeCurvature(const std::vector<Eigen::Vector2d>& uv,
                                         const std::vector<double>& t,
                                         const std::vector<std::array<int, 3>>& triangles,
                                         const std::vector<char>& is_fill, int size) {
  CurvatureImage img;
  img.size = size;
  img.rgb.assign(size_t(size) * size * 3, 0);
  img.hole.assign(size_t(size) * size, 0);
  // Context first, then the hole, so pixels on the hole's border go to the hole.
  for (int pass = 0; pass < 2; ++pass)
    for (size_t f = 0; f < triangles.size(); ++f) {
      if (bool(is_fill[f]) != (pass == 1)) continue;
      const auto& tri = triangles[f];
      double x[3], y[3];
      for (int k = 0; k < 3; ++k) {
        x[k] = uv[tri[k]].x() * size;
        y[k] = (1.0 - uv[tri[k]].y()) * size;
      }
      const double area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
      if (std::abs(area) < 1e-18) continue;
      const int x0 = std::max(0, int(std::floor(std::min({x[0], x[1], x[2]}) - 0.5)));
      const int x1 = std::min(size - 1, int(std::ceil(std::max({x[0], x[1], x[2]}))));
      const int y0 = std::max(0, int(std::floor(std::min({y[0], y[1], y[2]}) - 0.5)));
      const int y1 = std::min(size - 1, int(std::ceil(std::max({y[0], y[1], y[2]}))));
      const double eps = 1e-9;
      for (int py = y0; py <= y1; ++py)
        for (int px = x0; px <= x1; ++px) {
          const double cx = px + 0.5, cy = py + 0.5;
          const double w0 = ((x[1] - cx) * (y[2] - cy) - (x[2] - cx) * (y[1] - cy)) / area;
          const double w1 = ((x[2] - cx) * (y[0] - cy) - (x[0] - cx) * (y[2] - cy)) / area;
          const double w2 = 1.0 - w0 - w1;
          if (w0 < -eps || w1 < -eps || w2 < -eps) continue;
          const Rgb8 c =
              CurvatureColormap::Color8(w0 * t[tri[0]] + w1 * t[tri[1]] + w2 * t[tri[2]]);
          uint8_t* out = &img.rgb[(size_t(py) * size + px) * 3];
          out[0] = c.r, out[1] = c.g, out[2] = c.b;
          img.hole[size_t(py) * size + px] = uint8_t(pass);
        }
    }
  return img;
}

} // namespace vcg_ext
