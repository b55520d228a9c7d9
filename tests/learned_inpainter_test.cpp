// The learned inpainter (inpaint/learned_inpainter.h) and its network (inpaint/curvature_unet.h).
#include "inpaint/learned_inpainter.h"

#include <vcg_ext/curvature_colormap.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

namespace {

using namespace curvature_inpaint;

/// train/unet.py's check_input().
Planes CheckInput() {
  Planes p{3, kLearnedSide, kLearnedSide, {}};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < kLearnedSide; ++r)
      for (int q = 0; q < kLearnedSide; ++q)
        p.data.push_back(c == 1 ? ((q - 64) * (q - 64) + (r - 64) * (r - 64) < 40 * 40 ? 1.f : 0.f)
                                : float(0.5 + 0.3 * std::sin(0.05 * (q + 1) * (c + 1) + 0.07 * r)));
  return p;
}

TEST(LearnedInpainter, TheShippedNetworkAnswersAsItDidInTraining) {
  // The outputs PyTorch gave when the weights were exported: the C++ layers are the model's.
  std::ifstream check(CI_LEARNED_DIR "/curvature_unet_check.txt");
  ASSERT_TRUE(check.good());
  const Planes out = ShippedUNet().Forward(CheckInput());
  ASSERT_EQ(out.channels, 1);
  ASSERT_EQ(out.height, kLearnedSide);
  int r, q, lines = 0;
  double expected;
  while (check >> r >> q >> expected) {
    EXPECT_NEAR(out.data[size_t(r) * kLearnedSide + q], expected, 1e-4) << r << "," << q;
    ++lines;
  }
  EXPECT_EQ(lines, 16);
}

TEST(LearnedInpainter, RefusesWeightsThatAreNotAWholeNetwork) {
  std::ifstream in(CI_LEARNED_DIR "/curvature_unet.bin", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 100u);
  EXPECT_NO_THROW(CurvatureUNet{bytes});
  EXPECT_THROW(CurvatureUNet{bytes.substr(0, bytes.size() - 4)}, NetworkFileError);
  EXPECT_THROW(CurvatureUNet{bytes + "xxxx"}, NetworkFileError);
  EXPECT_THROW(CurvatureUNet{"PNG" + bytes.substr(3)}, NetworkFileError);
  EXPECT_THROW(CurvatureUNet{std::string()}, NetworkFileError);
  // The first layer's kernel size (after the header, version, levels, out and in) made 2.
  std::string wrong = bytes;
  wrong[20] ^= 1;
  EXPECT_THROW(CurvatureUNet{wrong}, NetworkFileError);
}

TEST(LearnedInpainter, AveragesLargeImagesAndRepeatsSmallOnes) {
  std::vector<double> big(512 * 512);
  for (size_t i = 0; i < big.size(); ++i) big[i] = double(i % 512) + 512.0 * (i / 512);
  const std::vector<float> cells = ToLearnedSide(big, 512, 512);
  ASSERT_EQ(cells.size(), size_t(kLearnedSide * kLearnedSide));
  // Cell (1, 2) holds pixels x 8..11, y 4..7.
  EXPECT_NEAR(cells[1 * kLearnedSide + 2], 9.5 + 512 * 5.5, 1e-2);
  std::vector<double> small(64 * 64);
  for (size_t i = 0; i < small.size(); ++i) small[i] = double(i);
  const std::vector<float> repeated = ToLearnedSide(small, 64, 64);
  EXPECT_EQ(repeated[3 * kLearnedSide + 5], float(1 * 64 + 2));
}

TEST(LearnedInpainter, ChangesTheHolesPixelsOnly) {
  const int side = 160; // not the network's side: the correction is resampled
  QImage image(side, side, QImage::Format_RGB32), mask(side, side, QImage::Format_RGB32);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const bool hole = (x - 80) * (x - 80) + (y - 70) * (y - 70) < 35 * 35;
      const vcg_ext::Rgb8 c =
          vcg_ext::CurvatureColormap::Color8(0.5 + 0.2 * std::sin(0.06 * x) * std::cos(0.04 * y));
      image.setPixel(x, y, qRgb(c.r, c.g, c.b));
      mask.setPixel(x, y, hole ? qRgb(255, 255, 255) : qRgb(0, 0, 0));
    }
  InpaintParams params;
  const QImage out = InpaintLearned(image, mask, params);
  ASSERT_EQ(out.size(), image.size());
  const QImage continued = InpaintEmbeddedAmplitudes(image, mask, params, {0.0}).front();
  int changed = 0;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const bool hole = qGray(mask.pixel(x, y)) > 127;
      if (!hole) {
        ASSERT_EQ(out.pixel(x, y) & RGB_MASK, continued.pixel(x, y) & RGB_MASK) << x << "," << y;
        continue;
      }
      changed += (out.pixel(x, y) & RGB_MASK) != (continued.pixel(x, y) & RGB_MASK);
    }
  EXPECT_GT(changed, 100) << "the network corrects the continuation inside the hole";
  EXPECT_EQ(out, InpaintLearned(image, mask, params)) << "the same image, the same answer";
}

} // namespace
