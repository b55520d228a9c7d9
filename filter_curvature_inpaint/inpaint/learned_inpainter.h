// The learned inpainter: the embedded backend's continuation of a curvature image, corrected
// inside the hole by a small network trained here on curvature images of public meshes
// (inpaint/learned/README.md: the training command, the meshes, the validation errors).
//
// The network sees the image at kLearnedSide² (the test cuts' size): the known curvature with
// the coarse fill's inside the hole, the hole's share of each pixel, and the continuation; it
// answers how much the truth differs from the continuation. Its answer is brought back to the
// image's size and added to the continuation on the hole's pixels only.
#pragma once

#include "inpaint/curvature_reading.h"
#include "inpaint/curvature_unet.h"
#include "inpaint/inpainter.h"

#include <QImage>

#include <vector>

namespace curvature_inpaint {

/// The side of the square the network sees.
constexpr int kLearnedSide = 128;

/// `values` (`width` x `height`, row by row) averaged onto kLearnedSide x kLearnedSide cells
/// (nearest where the image is smaller).
std::vector<float> ToLearnedSide(const std::vector<double>& values, int width, int height);

/// The network's three input planes for a hole: `image`'s curvature (the colour map's t),
/// its hole's share of each cell, and `continuation`'s curvature.
/// \pre both readings of one size.
Planes LearnedInput(const CurvatureReading& image, const CurvatureReading& continuation);

/// The network that ships with the product, read once from the build's resources. Throws
/// NetworkFileError where the build has none (or a broken one).
const CurvatureUNet& ShippedUNet();

/// Completes the hole of `image` (white pixels of `mask`): the embedded continuation at detail
/// 0, plus the network's correction on the hole's pixels. Same size as `image`. Throws
/// InpaintError where the continuation fails, NetworkFileError as ShippedUNet().
QImage InpaintLearned(const QImage& image, const QImage& mask, const InpaintParams& params);

/// The same from the continuation already made (`continued`: InpaintEmbeddedAmplitudes at
/// amplitude 0). \pre all three of one size.
QImage InpaintLearned(const QImage& image, const QImage& mask, const QImage& continued);

} // namespace curvature_inpaint
