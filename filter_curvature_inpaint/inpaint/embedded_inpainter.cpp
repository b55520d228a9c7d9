// The embedded inpainter: offline, deterministic for a seed, no new dependency.
//
// 1. Read the curvature value back from every known pixel (the colour map's exact inverse).
// 2. Continue it into the hole with a biharmonic solve (Eigen sparse), at most 256 pixels per
//    side and upsampled: the curvature field is smooth at that scale, and a biharmonic
//    continuation keeps its level and its slope across the hole's border (on a synthetic
//    field the design notes measured RMS 0.018 against 0.10 for OpenCV's Telea). On real
//    curvature a membrane term and a weak pull towards flat keep it from overshooting, and
//    where the hole still shows the coarse fill's curvature, a pull towards that.
// 3. Add detail: a random field, one per seed, with the correlation length of a few of the
//    patch's vertex spacings (the finest detail the deformed mesh can carry and its curvature
//    fits can see) and the spread of the known region's own detail at that scale, times the
//    detail amplitude. Each seed gives another variation.
#include "inpainter.h"

#include "curvature_reading.h"

#include <vcg_ext/exemplar_inpainting.h>

#include <vcg_ext/curvature_colormap.h>

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <random>

namespace curvature_inpaint {

namespace {

// The energy of the continuation, on the <= 256-pixel grid: thin plate (squared Laplacian),
// plus a membrane term (squared gradient) that keeps a steep border from overshooting, plus a
// weak pull towards flat (value 0.5), the safest guess far from any border. The two weights
// were chosen on the public cases of the inpainting benchmark (bench/run_inpaint_bench.py);
// there the pure thin plate overshoots on the Igea nose and the falcon's base.
constexpr double kMembrane = 0.3;
constexpr double kScreening = 1e-4;
// Where the hole's pixels carry the coarse fill's curvature, a pull towards it. On the same
// benchmark that curvature is closer to the truth than any continuation from the border
// (bench/run_inpaint_bench.py, last column), so the continuation only bends it near the
// border; the weight was chosen with bench/run_fill_bench.py (0.01-0.1 all beat CGAL there).
constexpr double kCoarsePrior = 0.03;
// Colour distance (0-441) under which a pixel counts as painted with the colour map.
constexpr double kOnColormap = 24;

struct Field {
  int w = 0, h = 0;
  std::vector<double> v;
  std::vector<char> known;
  std::vector<double> prior;        ///< hole pixels: the value they carry (the coarse fill's)
  std::vector<double> prior_weight; ///< its weight: 0 where the pixel is off the colour map
  double& at(int x, int y) { return v[size_t(y) * w + x]; }
  double at(int x, int y) const { return v[size_t(y) * w + x]; }
  bool is_known(int x, int y) const { return known[size_t(y) * w + x]; }
};

Field ReadField(const QImage& image, const QImage& mask) {
  const CurvatureReading r = ReadCurvatureImage(image, mask);
  Field f;
  f.w = r.width;
  f.h = r.height;
  f.v.assign(r.t.size(), 0.5);
  f.known.assign(r.t.size(), 0);
  f.prior.assign(r.t.size(), 0.5);
  f.prior_weight.assign(r.t.size(), 0.0);
  for (size_t i = 0; i < r.t.size(); ++i) {
    if (r.hole[i]) {
      // A hole pixel still painted with the colour map carries the coarse fill's curvature.
      if (r.distance[i] < kOnColormap) f.prior[i] = r.t[i], f.prior_weight[i] = kCoarsePrior;
      continue;
    }
    f.v[i] = r.t[i];
    f.known[i] = 1;
  }
  return f;
}

/// Minimises that energy over the unknown pixels with the known ones fixed. Exact for
/// harmonic fields, up to the weak pull towards flat.
bool SolveBiharmonic(Field& f) {
  std::vector<int> index(f.v.size(), -1);
  int n = 0;
  for (size_t i = 0; i < f.v.size(); ++i)
    if (!f.known[i]) index[i] = n++;
  if (n == 0) return true;
  std::vector<Eigen::Triplet<double>> a;
  // At most 34 entries per unknown pixel (it lies in at most five stencils of at most five
  // unknowns: 25 products; one screening entry; at most eight membrane entries), about as many
  // as a compact hole takes: reserved once, the 256² solves spend no time growing the list.
  a.reserve(size_t(n) * 34);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  const int dx[5] = {0, 1, -1, 0, 0}, dy[5] = {0, 0, 0, 1, -1};
  const double c[5] = {-4, 1, 1, 1, 1};
  for (int y = 1; y + 1 < f.h; ++y)
    for (int x = 1; x + 1 < f.w; ++x) {
      int ids[5];
      bool touches = false;
      double fixed = 0;
      for (int k = 0; k < 5; ++k) {
        ids[k] = index[size_t(y + dy[k]) * f.w + x + dx[k]];
        if (ids[k] >= 0)
          touches = true;
        else
          fixed += c[k] * f.at(x + dx[k], y + dy[k]);
      }
      if (!touches) continue;
      for (int i = 0; i < 5; ++i) {
        if (ids[i] < 0) continue;
        b[ids[i]] -= c[i] * fixed;
        for (int j = 0; j < 5; ++j)
          if (ids[j] >= 0) a.emplace_back(ids[i], ids[j], c[i] * c[j]);
      }
    }
  // Unknown pixels no stencil reaches (an image-wide hole's corners) stay put.
  for (size_t i = 0; i < f.v.size(); ++i) {
    if (index[i] < 0) continue;
    a.emplace_back(index[i], index[i], 1e-9 + kScreening + f.prior_weight[i]);
    b[index[i]] += kScreening * 0.5 + f.prior_weight[i] * f.prior[i];
  }
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const int i = index[size_t(y) * f.w + x];
      if (i < 0) continue;
      for (int k = 1; k < 5; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= f.w || ny >= f.h) continue;
        const int j = index[size_t(ny) * f.w + nx];
        a.emplace_back(i, i, kMembrane);
        if (j >= 0)
          a.emplace_back(i, j, -kMembrane);
        else
          b[i] += kMembrane * f.at(nx, ny);
      }
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(a.begin(), a.end());
  Eigen::VectorXd x;
  // A pull towards the coarse curvature on (nearly) every unknown pixel bounds the smallest
  // eigenvalue away from zero: preconditioned conjugate gradients then converge in under a
  // hundred iterations, a third of the time a factorization takes at 256². A hole continued
  // from its border alone is badly conditioned and gets the factorization.
  const auto pulled =
      std::count_if(f.prior_weight.begin(), f.prior_weight.end(), [](double w) { return w > 0; });
  bool solved = false;
  if (pulled >= 0.9 * n) {
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                             Eigen::IncompleteCholesky<double>>
        cg(A);
    // A relative residual of 1e-7 is far below the 8-bit colour step (1/255) of the result.
    cg.setTolerance(1e-7);
    cg.setMaxIterations(1000);
    // Started from the prior (the coarse fill's curvature where the hole carries it, flat
    // elsewhere) rather than from zero: a quarter fewer iterations to the same tolerance.
    Eigen::VectorXd start(n);
    for (size_t i = 0; i < f.v.size(); ++i)
      if (index[i] >= 0) start[index[i]] = f.prior[i];
    x = cg.solveWithGuess(b, start);
    solved = cg.info() == Eigen::Success && x.allFinite();
  }
  if (!solved) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
    if (ldlt.info() != Eigen::Success) return false;
    x = ldlt.solve(b);
  }
  if (!x.allFinite()) return false;
  for (size_t i = 0; i < f.v.size(); ++i)
    if (index[i] >= 0) f.v[i] = x[index[i]];
  return true;
}

/// The field at 1/factor resolution: a coarse pixel is known only when all its pixels are.
Field Downsample(const Field& f, int factor) {
  Field c;
  c.w = (f.w + factor - 1) / factor;
  c.h = (f.h + factor - 1) / factor;
  c.v.assign(size_t(c.w) * c.h, 0.5);
  c.known.assign(size_t(c.w) * c.h, 1);
  c.prior.assign(c.v.size(), 0.0);
  c.prior_weight.assign(c.v.size(), 0.0);
  std::vector<int> count(c.v.size(), 0);
  std::vector<double> sum(c.v.size(), 0.0);
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const size_t ci = size_t(y / factor) * c.w + x / factor;
      if (!f.is_known(x, y)) c.known[ci] = 0;
      sum[ci] += f.at(x, y);
      const size_t i = size_t(y) * f.w + x;
      c.prior[ci] += f.prior_weight[i] * f.prior[i];
      c.prior_weight[ci] += f.prior_weight[i];
      ++count[ci];
    }
  for (size_t i = 0; i < c.v.size(); ++i) {
    c.v[i] = count[i] ? sum[i] / count[i] : 0.5;
    c.prior[i] = c.prior_weight[i] > 0 ? c.prior[i] / c.prior_weight[i] : 0.5;
    if (count[i]) c.prior_weight[i] /= count[i];
  }
  return c;
}

double Bilinear(const Field& c, double x, double y) {
  x = std::max(0.0, std::min(c.w - 1.0, x));
  y = std::max(0.0, std::min(c.h - 1.0, y));
  const int x0 = std::min(int(x), c.w - 2 < 0 ? 0 : c.w - 2),
            y0 = std::min(int(y), c.h - 2 < 0 ? 0 : c.h - 2);
  const int x1 = std::min(x0 + 1, c.w - 1), y1 = std::min(y0 + 1, c.h - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * c.at(x0, y0) + fx * c.at(x1, y0)) +
         fy * ((1 - fx) * c.at(x0, y1) + fx * c.at(x1, y1));
}

/// Box blur of a w x h array in place, `radius` pixels, three passes each way ~ Gaussian.
void BoxBlur(std::vector<double>& a, int w, int h, int radius) {
  auto pass = [&](bool horizontal) {
    std::vector<double> out(a.size());
    const int len = horizontal ? w : h, lines = horizontal ? h : w;
    for (int l = 0; l < lines; ++l) {
      auto idx = [&](int i) { return horizontal ? size_t(l) * w + i : size_t(i) * w + l; };
      double acc = 0;
      for (int i = -radius; i <= radius; ++i) acc += a[idx(std::max(0, std::min(len - 1, i)))];
      for (int i = 0; i < len; ++i) {
        out[idx(i)] = acc / (2 * radius + 1);
        acc += a[idx(std::min(len - 1, i + radius + 1))] - a[idx(std::max(0, i - radius))];
      }
    }
    a.swap(out);
  };
  for (int k = 0; k < 3; ++k)
    for (bool hz : {true, false}) pass(hz);
}

/// Box blur of the known values only (normalized).
std::vector<double> BlurKnown(const Field& f, int radius) {
  std::vector<double> val(f.v.size()), wgt(f.v.size());
  for (size_t i = 0; i < f.v.size(); ++i) val[i] = f.known[i] ? f.v[i] : 0, wgt[i] = f.known[i];
  BoxBlur(val, f.w, f.h, radius);
  BoxBlur(wgt, f.w, f.h, radius);
  for (size_t i = 0; i < val.size(); ++i) val[i] = wgt[i] > 1e-6 ? val[i] / wgt[i] : 0.5;
  return val;
}

} // namespace

/// The field with a band of `width` known pixels around the hole made unknown.
Field WithoutBorderBand(const Field& f, int width) {
  Field g = f;
  for (int pass = 0; pass < width; ++pass) {
    std::vector<char> next = g.known;
    for (int y = 0; y < g.h; ++y)
      for (int x = 0; x < g.w; ++x)
        if (g.is_known(x, y))
          for (int k = 0; k < 4 && next[size_t(y) * g.w + x]; ++k) {
            const int nx = x + (k == 0) - (k == 1), ny = y + (k == 2) - (k == 3);
            if (nx >= 0 && ny >= 0 && nx < g.w && ny < g.h && !g.is_known(nx, ny))
              next[size_t(y) * g.w + x] = 0;
          }
    g.known.swap(next);
  }
  return g;
}

namespace {

/// Variations 1..`variations` of the embedded backend, each at every amplitude of `amplitudes`
/// (variation-major), from one continuation.
std::vector<QImage> Complete(const QImage& image, const QImage& mask, const InpaintParams& p,
                             int variations, const std::vector<double>& amplitudes) {
  Field f = ReadField(image, mask);
  const int longest = std::max(f.w, f.h);
  const int factor = std::max(1, (longest + 255) / 256);
  // The pixels right at the hole's border carry the seam between the scan and its coarse fill
  // (the curvature fits there straddle both): the continuation starts a little way out.
  const Field solve = WithoutBorderBand(f, std::max(1, longest / 128));
  Field base = solve;
  if (factor == 1) {
    if (!SolveBiharmonic(base)) throw InpaintError("embedded: the biharmonic solve failed");
  } else {
    Field coarse = Downsample(solve, factor);
    if (!SolveBiharmonic(coarse)) throw InpaintError("embedded: the biharmonic solve failed");
    for (int y = 0; y < f.h; ++y)
      for (int x = 0; x < f.w; ++x)
        if (!solve.is_known(x, y))
          base.at(x, y) = Bilinear(coarse, (x + 0.5) / factor - 0.5, (y + 0.5) / factor - 0.5);
  }

  // The known region's detail: what a blur over four vertex spacings removes, and how much of
  // it there is. Finer detail than that is lost twice: between the vertices that sample the
  // image, and in the APSS fits (several rings wide) that measure curvature.
  const double spacing = p.detail_scale > 0 ? p.detail_scale : longest / 64.0;
  const int radius = std::max(2, int(std::lround(4 * spacing)));
  const std::vector<double> smooth = BlurKnown(solve, radius);
  double sum = 0, sq = 0;
  int known_count = 0;
  for (size_t i = 0; i < f.v.size(); ++i)
    if (solve.known[i]) {
      const double r = f.v[i] - smooth[i];
      sum += r, sq += r * r, ++known_count;
    }
  const double mean_residual = known_count ? sum / known_count : 0.0;
  const double amplitude =
      known_count > 1 ? std::sqrt(std::max(0.0, sq / known_count - mean_residual * mean_residual))
                      : 0.0;
  // Detail fades in from the hole's border, so the completion meets the known pixels.
  std::vector<double> inside(f.v.size());
  for (size_t i = 0; i < f.v.size(); ++i) inside[i] = f.known[i] ? 0.0 : 1.0;
  BoxBlur(inside, f.w, f.h, std::max(1, radius / 2));

  std::vector<QImage> out;
  const double largest = *std::max_element(amplitudes.begin(), amplitudes.end());
  // Without detail every variation at every amplitude is the continuation alone: one picture,
  // painted once and shared.
  const bool plain = !(largest > 0 && amplitude > 0);
  for (int variation = 0; variation < variations; ++variation) {
    // A random field with the detail's correlation length, one per seed, scaled to the known
    // region's spread over the hole.
    std::vector<double> noise(f.v.size(), 0.0);
    if (largest > 0 && amplitude > 0) {
      std::mt19937 rng(p.seed + 7919u * uint32_t(variation));
      std::normal_distribution<double> normal;
      for (double& x : noise) x = normal(rng);
      BoxBlur(noise, f.w, f.h, std::max(1, radius / 2));
      double nsum = 0, nsq = 0;
      int n = 0;
      for (size_t i = 0; i < f.v.size(); ++i)
        if (!f.known[i]) nsum += noise[i], nsq += noise[i] * noise[i], ++n;
      const double mean = n ? nsum / n : 0;
      const double sd = n > 1 ? std::sqrt(std::max(1e-300, nsq / n - mean * mean)) : 1;
      for (size_t i = 0; i < f.v.size(); ++i)
        noise[i] = f.known[i] ? 0.0
                              : (noise[i] - mean) / sd * amplitude *
                                    std::max(0.0, std::min(1.0, 2 * inside[i] - 1));
    }
    for (double a : amplitudes) {
      if (plain && !out.empty()) {
        out.push_back(out.front());
        continue;
      }
      QImage result(f.w, f.h, QImage::Format_RGB32);
      for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < f.w; ++x) {
          const size_t i = size_t(y) * f.w + x;
          double t = base.v[i];
          if (!f.known[i]) t += a * noise[i];
          const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(t);
          result.setPixel(x, y, qRgb(c.r, c.g, c.b));
        }
      out.push_back(result);
    }
  }
  return out;
}

} // namespace

std::vector<QImage> InpaintEmbedded(const QImage& image, const QImage& mask,
                                    const InpaintParams& p) {
  return Complete(image, mask, p, p.variations, {p.detail});
}

std::vector<QImage> InpaintEmbeddedAmplitudes(const QImage& image, const QImage& mask,
                                              const InpaintParams& p,
                                              const std::vector<double>& amplitudes) {
  if (amplitudes.empty()) return {};
  return Complete(image, mask, p, 1, amplitudes);
}

std::vector<QImage> InpaintExemplarVariations(const QImage& image, const QImage& mask,
                                              const InpaintParams& p, int count) {
  const Field f = ReadField(image, mask);
  // Patches of a few vertex spacings on a grid of at most 256 pixels: finer patches would
  // copy what the fill's vertices cannot carry, and cost more than the whole continuation.
  const int longest = std::max(f.w, f.h);
  const double spacing = p.detail_scale > 0 ? p.detail_scale : longest / 64.0;
  // At least 64 pixels, where a small hole's patches still fit beside it.
  const int factor = std::max({1, (longest + 255) / 256, std::min(int(spacing / 2), longest / 64)});
  // The border's seam, as for the continuation, is filled too.
  const Field band = WithoutBorderBand(f, std::max(1, longest / 128));
  const Field work = factor > 1 ? Downsample(band, factor) : band;
  std::vector<QImage> out;
  for (int k = 0; k < count; ++k) {
    vcg_ext::MaskedImage im;
    im.w = work.w;
    im.h = work.h;
    im.value = work.v;
    im.known = work.known;
    vcg_ext::ExemplarParams ep;
    ep.seed = p.seed + 7919u * uint32_t(k);
    if (!vcg_ext::InpaintExemplar(im, ep)) break; // no known patch: no exemplar to copy
    Field done = work;
    done.v = im.value;
    QImage result(f.w, f.h, QImage::Format_RGB32);
    for (int y = 0; y < f.h; ++y)
      for (int x = 0; x < f.w; ++x) {
        const double t = f.is_known(x, y) ? f.at(x, y)
                         : factor > 1
                             ? Bilinear(done, (x + 0.5) / factor - 0.5, (y + 0.5) / factor - 0.5)
                             : done.at(x, y);
        const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(t);
        result.setPixel(x, y, qRgb(c.r, c.g, c.b));
      }
    out.push_back(result);
  }
  return out;
}

} // namespace curvature_inpaint
