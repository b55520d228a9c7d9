#include "inpaint/learned_inpainter.h"

#include <vcg_ext/curvature_colormap.h>

#include <QFile>

#include <algorithm>
#include <memory>
#include <mutex>

// The weights are a resource of the static pipeline library: naming its initializer here keeps
// the linker from dropping it from the plugin and the tool.
static bool LoadUNetResource() {
  Q_INIT_RESOURCE(curvature_unet);
  return true;
}

namespace curvature_inpaint {

namespace {

double Clamp(double v, double lo, double hi) {
  return std::max(lo, std::min(hi, v));
}

/// The pixels [first, last) of a side of `length` that fall in cell `cell` of kLearnedSide.
void CellRange(int cell, int length, int* first, int* last) {
  *first = int(int64_t(cell) * length / kLearnedSide);
  *last = std::max(*first + 1, int(int64_t(cell + 1) * length / kLearnedSide));
}

/// A kLearnedSide² plane read back at (x, y) of a `width` x `height` image, bilinearly between
/// the cells' centres.
float Upsampled(const float* plane, int width, int height, int x, int y) {
  const double fx = Clamp((x + 0.5) * kLearnedSide / width - 0.5, 0.0, kLearnedSide - 1.0);
  const double fy = Clamp((y + 0.5) * kLearnedSide / height - 0.5, 0.0, kLearnedSide - 1.0);
  const int x0 = std::min(int(fx), kLearnedSide - 2), y0 = std::min(int(fy), kLearnedSide - 2);
  const double ax = fx - x0, ay = fy - y0;
  const float* row0 = plane + size_t(y0) * kLearnedSide;
  const float* row1 = row0 + kLearnedSide;
  return float((1 - ay) * ((1 - ax) * row0[x0] + ax * row0[x0 + 1]) +
               ay * ((1 - ax) * row1[x0] + ax * row1[x0 + 1]));
}

} // namespace

std::vector<float> ToLearnedSide(const std::vector<double>& values, int width, int height) {
  std::vector<float> out(size_t(kLearnedSide) * kLearnedSide);
  for (int cy = 0; cy < kLearnedSide; ++cy) {
    int y0, y1;
    CellRange(cy, height, &y0, &y1);
    for (int cx = 0; cx < kLearnedSide; ++cx) {
      int x0, x1;
      CellRange(cx, width, &x0, &x1);
      double sum = 0;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += values[size_t(y) * width + x];
      out[size_t(cy) * kLearnedSide + cx] = float(sum / ((y1 - y0) * (x1 - x0)));
    }
  }
  return out;
}

Planes LearnedInput(const CurvatureReading& image, const CurvatureReading& continuation) {
  const int w = image.width, h = image.height;
  const std::vector<double> hole(image.hole.begin(), image.hole.end());
  Planes p{3, kLearnedSide, kLearnedSide, {}};
  for (const std::vector<double>* plane : {&image.t, &hole, &continuation.t}) {
    const std::vector<float> cells = ToLearnedSide(*plane, w, h);
    p.data.insert(p.data.end(), cells.begin(), cells.end());
  }
  return p;
}

const CurvatureUNet& ShippedUNet() {
  static std::once_flag once;
  static std::unique_ptr<CurvatureUNet> unet;
  static std::string problem;
  std::call_once(once, [] {
    LoadUNetResource();
    QFile file(":/curvature_inpaint/curvature_unet.bin");
    if (!file.open(QIODevice::ReadOnly)) {
      problem = "this build has no learned network";
      return;
    }
    const QByteArray bytes = file.readAll();
    try {
      unet = std::make_unique<CurvatureUNet>(std::string(bytes.constData(), size_t(bytes.size())));
    } catch (const NetworkFileError& e) {
      problem = e.what();
    }
  });
  if (!unet) throw NetworkFileError(problem);
  return *unet;
}

QImage InpaintLearned(const QImage& image, const QImage& mask, const InpaintParams& params) {
  ShippedUNet(); // before the continuation: a build without a network says so at once
  return InpaintLearned(image, mask, InpaintEmbeddedAmplitudes(image, mask, params, {0.0}).front());
}

QImage InpaintLearned(const QImage& image, const QImage& mask, const QImage& continued) {
  const CurvatureUNet& unet = ShippedUNet();
  const CurvatureReading known = ReadCurvatureImage(image, mask);
  const CurvatureReading base = ReadCurvatureImage(continued, mask);
  const Planes correction = unet.Forward(LearnedInput(known, base));
  QImage out = continued.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < out.height(); ++y) {
    QRgb* line = reinterpret_cast<QRgb*>(out.scanLine(y));
    for (int x = 0; x < out.width(); ++x) {
      const size_t i = size_t(y) * out.width() + x;
      if (!known.hole[i]) continue;
      const double t =
          base.t[i] + Upsampled(correction.data.data(), out.width(), out.height(), x, y);
      const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(Clamp(t, 0.0, 1.0));
      line[x] = qRgb(c.r, c.g, c.b);
    }
  }
  return out;
}

} // namespace curvature_inpaint
