// Exemplar-based inpainting of a scalar image (Criminisi, Perez and Toyama 2004), with the
// source patches searched PatchMatch's way (Barnes et al. 2009: random samples, propagation of
// the neighbours' matches, random search around the best). The hole is filled from its border
// inwards, first where the border is most trusted and where a structure (a ridge, a valley, a
// crease's line in a curvature image) runs into it, so structures continue through the hole
// instead of being smoothed away; known pixels are never changed.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace vcg_ext {

/// A w x h scalar image with a mask of the pixels that are known (row-major).
struct MaskedImage {
  int w = 0, h = 0;
  std::vector<double> value;
  std::vector<char> known;
  size_t At(int x, int y) const { return size_t(y) * size_t(w) + size_t(x); }
};

struct ExemplarParams {
  int patch = 9;              ///< side of the square patches, pixels (odd)
  int random_candidates = 64; ///< source patches drawn at random per target patch
  uint32_t seed = 1;          ///< each seed a different completion
};

/// Fills every unknown pixel of `image` with values copied from fully known patches of it.
/// Returns false (and leaves `image` as it was) when no patch of the given size is fully known.
inline bool InpaintExemplar(MaskedImage& image, const ExemplarParams& params) {
  const int w = image.w, h = image.h, r = std::max(1, params.patch / 2);
  if (w <= 2 * r || h <= 2 * r) return false;
  // Source centres: patches entirely inside the image and entirely known.
  std::vector<char> source(size_t(w) * size_t(h), 0);
  std::vector<int> sources;
  for (int y = r; y < h - r; ++y)
    for (int x = r; x < w - r; ++x) {
      bool all = true;
      for (int dy = -r; dy <= r && all; ++dy)
        for (int dx = -r; dx <= r && all; ++dx) all = image.known[image.At(x + dx, y + dy)];
      if (all) source[image.At(x, y)] = 1, sources.push_back(int(image.At(x, y)));
    }
  if (sources.empty()) return false;

  std::vector<char> filled = image.known;
  std::vector<double> confidence(filled.size());
  for (size_t i = 0; i < filled.size(); ++i) confidence[i] = filled[i] ? 1.0 : 0.0;
  std::vector<int> copied_from(filled.size(), -1); // for propagation: the source pixel
  std::mt19937 rng(params.seed);
  std::uniform_int_distribution<size_t> any_source(0, sources.size() - 1);
  auto filled_at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && filled[image.At(x, y)];
  };
  // Sum of squared differences over the target's filled pixels, cut short past `bound`.
  auto ssd = [&](int tx, int ty, int sx, int sy, double bound) {
    double e = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        if (!filled_at(tx + dx, ty + dy)) continue;
        const double d =
            image.value[image.At(tx + dx, ty + dy)] - image.value[image.At(sx + dx, sy + dy)];
        e += d * d;
        if (e >= bound) return e;
      }
    return e;
  };

  // The mean confidence of the patch around (x, y), over its pixels inside the image.
  auto patch_confidence = [&](int x, int y) {
    double c = 0;
    int n = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        if (x + dx >= 0 && y + dy >= 0 && x + dx < w && y + dy < h)
          c += confidence[image.At(x + dx, y + dy)], ++n;
    return c / n;
  };

  std::vector<int> front;
  for (;;) {
    // The fill front: unfilled pixels beside a filled one.
    front.clear();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (!filled[image.At(x, y)] && (filled_at(x - 1, y) || filled_at(x + 1, y) ||
                                        filled_at(x, y - 1) || filled_at(x, y + 1)))
          front.push_back(int(image.At(x, y)));
    if (front.empty()) break;
    // Priority: the confidence of the patch times the strength of the isophote (the level
    // line of the value) flowing into the hole across the front.
    double best_priority = -1;
    int target = front.front();
    for (int p : front) {
      const int x = p % w, y = p / w;
      const double c = patch_confidence(x, y);
      // The front's normal: towards the filled side; the image gradient from filled pixels
      // one and two steps out.
      double nx = double(filled_at(x + 1, y)) - double(filled_at(x - 1, y));
      double ny = double(filled_at(x, y + 1)) - double(filled_at(x, y - 1));
      const double nl = std::hypot(nx, ny);
      if (nl > 0) nx /= nl, ny /= nl;
      double gx = 0, gy = 0;
      auto diff = [&](int ax, int ay, int bx, int by) {
        return filled_at(ax, ay) && filled_at(bx, by)
                   ? image.value[image.At(ax, ay)] - image.value[image.At(bx, by)]
                   : 0.0;
      };
      for (int k = 1; k <= 2; ++k) {
        const int sx = x + int(std::lround(k * nx)), sy = y + int(std::lround(k * ny));
        gx += diff(sx + 1, sy, sx, sy) + diff(sx, sy, sx - 1, sy);
        gy += diff(sx, sy + 1, sx, sy) + diff(sx, sy, sx, sy - 1);
      }
      const double data = std::abs(-gy * nx + gx * ny); // isophote = gradient turned by 90
      const double priority = c * (data + 1e-3);
      if (priority > best_priority) best_priority = priority, target = p;
    }
    const int tx = target % w, ty = target / w;
    // The best source patch: random ones, the ones the target's filled neighbours point to,
    // then a random search around the best at halving radii.
    int best = sources[any_source(rng)];
    double best_e = ssd(tx, ty, best % w, best / w, std::numeric_limits<double>::max());
    auto consider = [&](int s) {
      if (s < 0 || !source[size_t(s)]) return;
      const double e = ssd(tx, ty, s % w, s / w, best_e);
      if (e < best_e) best_e = e, best = s;
    };
    for (int k = 1; k < params.random_candidates; ++k) consider(sources[any_source(rng)]);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        if (!filled_at(tx + dx, ty + dy)) continue;
        const int from = copied_from[image.At(tx + dx, ty + dy)];
        if (from < 0) continue;
        const int sx = from % w - dx, sy = from / w - dy;
        if (sx >= 0 && sy >= 0 && sx < w && sy < h) consider(int(image.At(sx, sy)));
      }
    for (int radius = std::max(w, h) / 2; radius >= 1; radius /= 2) {
      std::uniform_int_distribution<int> step(-radius, radius);
      const int sx = best % w + step(rng), sy = best / w + step(rng);
      if (sx >= 0 && sy >= 0 && sx < w && sy < h) consider(int(image.At(sx, sy)));
    }
    // Copy the source's pixels into the target's unfilled ones, at the target's confidence.
    const double copied_confidence = patch_confidence(tx, ty);
    const int bx = best % w, by = best / w;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int x = tx + dx, y = ty + dy;
        if (x < 0 || y < 0 || x >= w || y >= h || filled[image.At(x, y)]) continue;
        const size_t i = image.At(x, y);
        image.value[i] = image.value[image.At(bx + dx, by + dy)];
        filled[i] = 1;
        confidence[i] = copied_confidence;
        copied_from[i] = int(image.At(bx + dx, by + dy));
      }
  }
  return true;
}

} // namespace vcg_ext
