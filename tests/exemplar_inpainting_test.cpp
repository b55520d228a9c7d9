// The exemplar inpainter continues structures through a hole and keeps the known pixels.
#include <vcg_ext/exemplar_inpainting.h>

#include <gtest/gtest.h>

namespace {

/// Slanted stripes, 24 pixels apart and 8 wide, with a round hole of radius 40 in the middle.
vcg_ext::MaskedImage Stripes(int n) {
  vcg_ext::MaskedImage im;
  im.w = im.h = n;
  im.value.resize(size_t(n) * n);
  im.known.resize(size_t(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int u = (x + y / 2) % 24;
      im.value[im.At(x, y)] = u < 8 ? 0.8 : 0.3;
      im.known[im.At(x, y)] = std::hypot(x - n / 2.0, y - n / 2.0) > 40;
    }
  return im;
}

TEST(ExemplarInpainting, ContinuesAStripePatternAndKeepsTheKnownPixels) {
  const vcg_ext::MaskedImage truth = Stripes(256);
  vcg_ext::MaskedImage im = truth;
  for (size_t i = 0; i < im.value.size(); ++i)
    if (!im.known[i]) im.value[i] = 0;
  ASSERT_TRUE(vcg_ext::InpaintExemplar(im, vcg_ext::ExemplarParams()));
  int wrong = 0, hole = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      const size_t i = im.At(x, y);
      if (truth.known[i]) {
        ASSERT_EQ(im.value[i], truth.value[i]) << x << ", " << y;
        continue;
      }
      ++hole;
      // Right within 2 pixels of where the stripes' own continuation puts it.
      bool near = false;
      for (int d = -2; d <= 2 && !near; ++d)
        near = x + d >= 0 && x + d < 256 && im.value[i] == truth.value[truth.At(x + d, y)];
      wrong += !near;
    }
  EXPECT_EQ(wrong, 0) << "of " << hole << " hole pixels";
}

TEST(ExemplarInpainting, SeedsGiveDifferentCompletionsOfATexture) {
  vcg_ext::MaskedImage a;
  a.w = a.h = 96;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 96 * 96; ++i) a.value.push_back(u(rng));
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) a.known.push_back(std::hypot(x - 48, y - 48) > 16);
  vcg_ext::MaskedImage b = a;
  vcg_ext::ExemplarParams pa, pb;
  pb.seed = 2;
  ASSERT_TRUE(vcg_ext::InpaintExemplar(a, pa));
  ASSERT_TRUE(vcg_ext::InpaintExemplar(b, pb));
  EXPECT_NE(a.value, b.value);
}

TEST(ExemplarInpainting, RefusesWhenNoPatchIsKnown) {
  vcg_ext::MaskedImage im;
  im.w = im.h = 20;
  im.value.assign(400, 0.5);
  im.known.assign(400, 0);
  for (int x = 0; x < 20; ++x) im.known[im.At(x, 0)] = 1; // one row: no 9 x 9 patch
  const auto before = im.value;
  EXPECT_FALSE(vcg_ext::InpaintExemplar(im, vcg_ext::ExemplarParams()));
  EXPECT_EQ(im.value, before);
}

} // namespace
