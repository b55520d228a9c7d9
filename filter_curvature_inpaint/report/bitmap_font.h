// Text for the pictures the product writes (the montage's labels), drawn from a 5 x 7 pixel
// font of its own: the same pixels on every machine, with or without fonts installed, and no
// Qt font database (which the command-line tool, without a QGuiApplication, does not have).
#pragma once

#include <QColor>
#include <QImage>

#include <string>

namespace curvature_inpaint {

/// Pixels a line of `text` takes at `scale` (each font pixel a scale x scale square).
int TextWidth(const std::string& text, int scale);
inline int TextHeight(int scale) {
  return 7 * scale;
}

/// Draws `text` with its top left corner at (x, y). Letters are drawn in lower case; a
/// character the font lacks is drawn as '?'.
void DrawText(QImage& image, int x, int y, const std::string& text, int scale, QColor color);

} // namespace curvature_inpaint
