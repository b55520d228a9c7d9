// Reading a curvature image back into values (inpaint/curvature_reading.h).
#include "hole_fill_fixtures.h"

namespace {

using namespace fixtures;

TEST(CurvatureReading, EveryPixelsValueAndHoleWhateverTheImagesFormat) {
  // Not square, the hole transparent (as in hole_<k>_rgba.png), one pixel off the colour map,
  // the mask in grey levels: the reading must not depend on any of it.
  const int w = 7, h = 5;
  QImage image(w, h, QImage::Format_ARGB32);
  QImage mask(w, h, QImage::Format_Grayscale8);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8((y * w + x) / double(w * h));
      const bool hole = x >= 2 && x < 5 && y >= 1 && y < 4;
      image.setPixel(x, y, qRgba(c.r, c.g, c.b, hole ? 0 : 255));
      mask.setPixel(x, y, hole ? qRgb(200, 200, 200) : qRgb(100, 100, 100));
    }
  image.setPixel(6, 4, qRgb(128, 128, 128));
  const auto r = curvature_inpaint::ReadCurvatureImage(image, mask);
  ASSERT_EQ(r.width, w);
  ASSERT_EQ(r.height, h);
  ASSERT_EQ(r.t.size(), size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      EXPECT_EQ(bool(r.hole[i]), x >= 2 && x < 5 && y >= 1 && y < 4) << x << "," << y;
      if (x == 6 && y == 4) {
        EXPECT_GT(r.distance[i], 100) << "grey is far from the colour map";
        continue;
      }
      EXPECT_NEAR(r.t[i], i / double(w * h), 1.0 / 255) << x << "," << y;
      EXPECT_LT(r.distance[i], 1.0) << x << "," << y;
    }
}

} // namespace
