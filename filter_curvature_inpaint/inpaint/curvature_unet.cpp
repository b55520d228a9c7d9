#include "curvature_unet.h"

#include <Eigen/Core>

#include <algorithm>
#include <cstring>

namespace curvature_inpaint {

namespace {

constexpr int32_t kVersion = 1;

class Reader {
public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  int32_t Int() {
    int32_t v = 0;
    Take(&v, sizeof v);
    return v;
  }
  void Floats(std::vector<float>* out, size_t n) {
    out->resize(n);
    Take(out->data(), n * sizeof(float));
  }
  bool AtEnd() const { return at_ == bytes_.size(); }

private:
  void Take(void* to, size_t n) {
    if (bytes_.size() - at_ < n) throw NetworkFileError("the network's weights end early");
    std::memcpy(to, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::string& bytes_;
  size_t at_ = 0;
};

Planes AveragePool2(const Planes& x) {
  Planes y{x.channels, x.height / 2, x.width / 2, {}};
  y.data.resize(size_t(y.channels) * y.height * y.width);
  for (int c = 0; c < y.channels; ++c)
    for (int r = 0; r < y.height; ++r)
      for (int q = 0; q < y.width; ++q) {
        const float* a = &x.data[(size_t(c) * x.height + 2 * r) * x.width + 2 * q];
        y.data[(size_t(c) * y.height + r) * y.width + q] =
            0.25f * (a[0] + a[1] + a[x.width] + a[x.width + 1]);
      }
  return y;
}

/// `low` doubled by nearest neighbour, then `skip`'s channels after it.
Planes UpAndAppend(const Planes& low, const Planes& skip) {
  Planes y{low.channels + skip.channels, skip.height, skip.width, {}};
  y.data.resize(size_t(y.channels) * y.height * y.width);
  for (int c = 0; c < low.channels; ++c)
    for (int r = 0; r < y.height; ++r)
      for (int q = 0; q < y.width; ++q)
        y.data[(size_t(c) * y.height + r) * y.width + q] =
            low.data[(size_t(c) * low.height + r / 2) * low.width + q / 2];
  std::copy(skip.data.begin(), skip.data.end(),
            y.data.begin() + size_t(low.channels) * y.height * y.width);
  return y;
}

} // namespace

CurvatureUNet::CurvatureUNet(const std::string& bytes) {
  if (bytes.compare(0, 4, "CIUN") != 0)
    throw NetworkFileError("not a curvature network's weights (no CIUN header)");
  Reader r(bytes);
  r.Int(); // the header
  if (r.Int() != kVersion) throw NetworkFileError("the network's weights are of another version");
  levels_ = r.Int();
  if (levels_ < 1 || levels_ > 8) throw NetworkFileError("the network's level count is wrong");
  // Two per level down, two at the bottom, two per level up, one out.
  const int count = 4 * levels_ + 3;
  for (int i = 0; i < count; ++i) {
    Conv c;
    c.out = r.Int(), c.in = r.Int(), c.kernel = r.Int();
    if (c.out < 1 || c.in < 1 || c.out > 4096 || c.in > 4096 || (c.kernel != 1 && c.kernel != 3))
      throw NetworkFileError("a layer of the network has an impossible shape");
    if (i > 0 && c.in != InputOf(i))
      throw NetworkFileError("the network's layers do not follow on");
    r.Floats(&c.weights, size_t(c.out) * c.in * c.kernel * c.kernel);
    r.Floats(&c.bias, size_t(c.out));
    layers_.push_back(std::move(c));
  }
  if (!r.AtEnd()) throw NetworkFileError("the network's weights go on past its last layer");
  if (layers_.back().kernel != 1 || layers_.back().out != 1)
    throw NetworkFileError("the network's last layer is not one 1x1 output");
}

int CurvatureUNet::InputOf(int i) const {
  const int up = i - (2 * levels_ + 2); // the up path's layers from 0
  // Going up, a level's first convolution takes the level below and the level's skip.
  if (up >= 0 && up % 2 == 0 && up < 2 * levels_)
    return layers_[i - 1].out + layers_[2 * (levels_ - 1 - up / 2) + 1].out;
  return layers_[i - 1].out;
}

Planes CurvatureUNet::Apply(const Conv& conv, const Planes& x, bool relu) const {
  const int h = x.height, w = x.width, k = conv.kernel, pad = k / 2;
  const Eigen::Index pixels = Eigen::Index(h) * w;
  // The input unrolled: one row per (channel, kernel tap), zero outside the image.
  Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> columns(
      Eigen::Index(conv.in) * k * k, pixels);
  for (int c = 0; c < conv.in; ++c)
    for (int dy = 0; dy < k; ++dy)
      for (int dx = 0; dx < k; ++dx) {
        float* row = columns.row((Eigen::Index(c) * k + dy) * k + dx).data();
        for (int y = 0; y < h; ++y) {
          const int sy = y + dy - pad;
          for (int q = 0; q < w; ++q) {
            const int sx = q + dx - pad;
            row[size_t(y) * w + q] = sy < 0 || sy >= h || sx < 0 || sx >= w
                                         ? 0.0f
                                         : x.data[(size_t(c) * h + sy) * w + sx];
          }
        }
      }
  const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
      weights(conv.weights.data(), conv.out, Eigen::Index(conv.in) * k * k);
  Planes y{conv.out, h, w, std::vector<float>(size_t(conv.out) * pixels)};
  Eigen::Map<Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> out(
      y.data.data(), conv.out, pixels);
  out.noalias() = weights * columns;
  for (int c = 0; c < conv.out; ++c) {
    out.row(c).array() += conv.bias[c];
    if (relu) out.row(c) = out.row(c).cwiseMax(0.0f);
  }
  return y;
}

Planes CurvatureUNet::Forward(const Planes& input) const {
  std::vector<Planes> skips;
  Planes x = input;
  size_t layer = 0;
  for (int l = 0; l < levels_; ++l) {
    x = Apply(layers_[layer++], x, true);
    x = Apply(layers_[layer++], x, true);
    skips.push_back(x);
    x = AveragePool2(x);
  }
  x = Apply(layers_[layer++], x, true);
  x = Apply(layers_[layer++], x, true);
  for (int l = levels_ - 1; l >= 0; --l) {
    x = UpAndAppend(x, skips[l]);
    x = Apply(layers_[layer++], x, true);
    x = Apply(layers_[layer++], x, true);
  }
  return Apply(layers_[layer], x, false);
}

} // namespace curvature_inpaint
