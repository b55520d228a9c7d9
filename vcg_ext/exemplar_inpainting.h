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

namespace detail {

/// The state of one exemplar fill: which pixels are filled, how far each is trusted and where
/// it was copied from, and the sources (centres of fully known patches).
class ExemplarFill {
public:
  ExemplarFill(MaskedImage& image, const ExemplarParams& params)
      : image_(image), params_(params), w_(image.w), h_(image.h), r_(std::max(1, params.patch / 2)),
        source_(size_t(w_) * size_t(h_), 0), filled_(image.known), confidence_(filled_.size()),
        copied_from_(filled_.size(), -1), rng_(params.seed) {
    for (int y = r_; y < h_ - r_; ++y)
      for (int x = r_; x < w_ - r_; ++x) {
        bool all = true;
        for (int dy = -r_; dy <= r_ && all; ++dy)
          for (int dx = -r_; dx <= r_ && all; ++dx) all = image.known[image.At(x + dx, y + dy)];
        if (all) source_[image.At(x, y)] = 1, sources_.push_back(int(image.At(x, y)));
      }
    for (size_t i = 0; i < filled_.size(); ++i) confidence_[i] = filled_[i] ? 1.0 : 0.0;
  }

  bool HasSources() const { return !sources_.empty(); }

  /// The fill front: unfilled pixels beside a filled one.
  void Front(std::vector<int>& front) const {
    front.clear();
    for (int y = 0; y < h_; ++y)
      for (int x = 0; x < w_; ++x)
        if (!filled_[image_.At(x, y)] &&
            (FilledAt(x - 1, y) || FilledAt(x + 1, y) || FilledAt(x, y - 1) || FilledAt(x, y + 1)))
          front.push_back(int(image_.At(x, y)));
  }

  /// The front pixel to fill next: the highest confidence of the patch times the strength of
  /// the isophote (the level line of the value) flowing into the hole across the front.
  /// \pre `front` is not empty.
  int Target(const std::vector<int>& front) const {
    double best_priority = -1;
    int target = front.front();
    for (int p : front) {
      const double priority = PatchConfidence(p % w_, p / w_) * (Isophote(p % w_, p / w_) + 1e-3);
      if (priority > best_priority) best_priority = priority, target = p;
    }
    return target;
  }

  /// The best source patch for the target at (tx, ty): random ones, the ones the target's
  /// filled neighbours point to, then a random search around the best at halving radii.
  int BestSource(int tx, int ty) {
    std::uniform_int_distribution<size_t> any_source(0, sources_.size() - 1);
    int best = sources_[any_source(rng_)];
    double best_e = Ssd(tx, ty, best % w_, best / w_, std::numeric_limits<double>::max());
    auto consider = [&](int s) {
      if (s < 0 || !source_[size_t(s)]) return;
      const double e = Ssd(tx, ty, s % w_, s / w_, best_e);
      if (e < best_e) best_e = e, best = s;
    };
    for (int k = 1; k < params_.random_candidates; ++k) consider(sources_[any_source(rng_)]);
    for (int dy = -r_; dy <= r_; ++dy)
      for (int dx = -r_; dx <= r_; ++dx) {
        if (!FilledAt(tx + dx, ty + dy)) continue;
        const int from = copied_from_[image_.At(tx + dx, ty + dy)];
        if (from < 0) continue;
        const int sx = from % w_ - dx, sy = from / w_ - dy;
        if (sx >= 0 && sy >= 0 && sx < w_ && sy < h_) consider(int(image_.At(sx, sy)));
      }
    for (int radius = std::max(w_, h_) / 2; radius >= 1; radius /= 2) {
      std::uniform_int_distribution<int> step(-radius, radius);
      const int sx = best % w_ + step(rng_), sy = best / w_ + step(rng_);
      if (sx >= 0 && sy >= 0 && sx < w_ && sy < h_) consider(int(image_.At(sx, sy)));
    }
    return best;
  }

  /// Copies the source's pixels into the target's unfilled ones, at the target's confidence.
  void Copy(int tx, int ty, int best) {
    const double copied_confidence = PatchConfidence(tx, ty);
    const int bx = best % w_, by = best / w_;
    for (int dy = -r_; dy <= r_; ++dy)
      for (int dx = -r_; dx <= r_; ++dx) {
        const int x = tx + dx, y = ty + dy;
        if (x < 0 || y < 0 || x >= w_ || y >= h_ || filled_[image_.At(x, y)]) continue;
        const size_t i = image_.At(x, y);
        image_.value[i] = image_.value[image_.At(bx + dx, by + dy)];
        filled_[i] = 1;
        confidence_[i] = copied_confidence;
        copied_from_[i] = int(image_.At(bx + dx, by + dy));
      }
  }

private:
  bool FilledAt(int x, int y) const {
    return x >= 0 && y >= 0 && x < w_ && y < h_ && filled_[image_.At(x, y)];
  }

  /// Sum of squared differences over the target's filled pixels, cut short past `bound`.
  double Ssd(int tx, int ty, int sx, int sy, double bound) const {
    double e = 0;
    for (int dy = -r_; dy <= r_; ++dy)
      for (int dx = -r_; dx <= r_; ++dx) {
        if (!FilledAt(tx + dx, ty + dy)) continue;
        const double d =
            image_.value[image_.At(tx + dx, ty + dy)] - image_.value[image_.At(sx + dx, sy + dy)];
        e += d * d;
        if (e >= bound) return e;
      }
    return e;
  }

  /// The mean confidence of the patch around (x, y), over its pixels inside the image.
  double PatchConfidence(int x, int y) const {
    double c = 0;
    int n = 0;
    for (int dy = -r_; dy <= r_; ++dy)
      for (int dx = -r_; dx <= r_; ++dx)
        if (x + dx >= 0 && y + dy >= 0 && x + dx < w_ && y + dy < h_)
          c += confidence_[image_.At(x + dx, y + dy)], ++n;
    return c / n;
  }

  /// The strength of the isophote across the front at (x, y): the front's normal points to
  /// the filled side; the image gradient is read from filled pixels one and two steps out.
  double Isophote(int x, int y) const {
    double nx = double(FilledAt(x + 1, y)) - double(FilledAt(x - 1, y));
    double ny = double(FilledAt(x, y + 1)) - double(FilledAt(x, y - 1));
    const double nl = std::hypot(nx, ny);
    if (nl > 0) nx /= nl, ny /= nl;
    double gx = 0, gy = 0;
    auto diff = [&](int ax, int ay, int bx, int by) {
      return FilledAt(ax, ay) && FilledAt(bx, by)
                 ? image_.value[image_.At(ax, ay)] - image_.value[image_.At(bx, by)]
                 : 0.0;
    };
    for (int k = 1; k <= 2; ++k) {
      const int sx = x + int(std::lround(k * nx)), sy = y + int(std::lround(k * ny));
      gx += diff(sx + 1, sy, sx, sy) + diff(sx, sy, sx - 1, sy);
      gy += diff(sx, sy + 1, sx, sy) + diff(sx, sy, sx, sy - 1);
    }
    return std::abs(-gy * nx + gx * ny); // isophote = gradient turned by 90
  }

  MaskedImage& image_;
  const ExemplarParams& params_;
  const int w_, h_, r_;
  std::vector<char> source_;
  std::vector<int> sources_;
  std::vector<char> filled_;
  std::vector<double> confidence_;
  std::vector<int> copied_from_; ///< for propagation: the source pixel
  std::mt19937 rng_;
};

} // namespace detail

/// Fills every unknown pixel of `image` with values copied from fully known patches of it.
/// Returns false (and leaves `image` as it was) when no patch of the given size is fully known.
inline bool InpaintExemplar(MaskedImage& image, const ExemplarParams& params) {
  const int r = std::max(1, params.patch / 2);
  if (image.w <= 2 * r || image.h <= 2 * r) return false;
  detail::ExemplarFill fill(image, params);
  if (!fill.HasSources()) return false;
  std::vector<int> front;
  for (;;) {
    fill.Front(front);
    if (front.empty()) break;
    const int target = fill.Target(front);
    const int tx = target % image.w, ty = target / image.w;
    fill.Copy(tx, ty, fill.BestSource(tx, ty));
  }
  return true;
}

} // namespace vcg_ext
