// A small U-Net on curvature images, run on the CPU with Eigen: the learned inpainter's
// network (train/train_unet.py trains it; inpaint/learned/README.md says on what).
//
// The layers are those of train/train_unet.py's model, in its order: per level two 3x3
// convolutions with ReLU, then a 2x2 average pool; two at the bottom; per level back up a
// nearest-neighbour doubling, the level's skip appended after it, two 3x3 convolutions with
// ReLU; last a 1x1 convolution to one channel. Zero padding, so the output has the input's size.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvature_inpaint {

/// A weights file that is not one this network reads: the sentence says what is wrong.
class NetworkFileError : public std::runtime_error {
public:
  explicit NetworkFileError(const std::string& what) : std::runtime_error(what) {}
};

/// Channels-first images: channel c, row y, column x at data[(c * height + y) * width + x].
struct Planes {
  int channels = 0, height = 0, width = 0;
  std::vector<float> data;
};

class CurvatureUNet {
public:
  /// Reads the weights as train/train_unet.py exports them: "CIUN", a version (1), the level
  /// count, then every convolution in the model's order as out, in and kernel size
  /// (little-endian int32) followed by its weights (out x in x k x k) and biases (out), float32.
  /// Throws NetworkFileError where the bytes do not make such a network.
  explicit CurvatureUNet(const std::string& bytes);

  /// The network's output (one channel) for `input`.
  /// \pre input.channels == InputChannels(), and height and width divisible by 2^Levels().
  Planes Forward(const Planes& input) const;

  int InputChannels() const { return layers_.front().in; }
  int Levels() const { return levels_; }

private:
  struct Conv {
    int out = 0, in = 0, kernel = 0;
    std::vector<float> weights; ///< out x (in * kernel * kernel), row-major
    std::vector<float> bias;
  };
  Planes Apply(const Conv& conv, const Planes& x, bool relu) const;
  /// The channels layer `i` must take, from the layers before it.
  int InputOf(int i) const;

  int levels_ = 0;
  std::vector<Conv> layers_;
};

} // namespace curvature_inpaint
