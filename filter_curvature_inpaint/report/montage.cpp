#include "report/montage.h"

#include "io/output_files.h"
#include "report/bitmap_font.h"
#include "report/json_text.h"

#include <vcg_ext/curvature_colormap.h>

#include <QPainter>

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace curvature_inpaint {

namespace {

const int kCell = 224;  ///< a tile's side, pixels
const int kPad = 8;     ///< between tiles and rows
const int kScale = 2;   ///< the font's pixels per font pixel: 10 x 14 letters
const int kLine = 18;   ///< a line of text with its spacing
const int kLabel = 128; ///< the column of hole numbers
const QColor kBackground(40, 40, 48);
const QColor kText(230, 230, 230);
const QColor kDim(170, 170, 180);

/// One tile of a row: its picture, its caption, and the variation numbers it stands for.
struct Tile {
  QImage image;
  std::string caption;
  int first = 0, last = 0; ///< variations first..last (1-based); 0: not a variation
};

/// The variations of a hole as tiles, each run of identical pictures of one kind as one tile
/// ("1-4 continuation").
std::vector<Tile> VariationTiles(const HoleVariations& hv) {
  std::vector<Tile> tiles;
  for (const VariationRun& run : VariationRuns(hv)) {
    const int first = run.first + 1, last = run.last + 1;
    const std::string numbers =
        first == last ? std::to_string(first) : std::to_string(first) + "-" + std::to_string(last);
    tiles.push_back(
        {hv.variations[size_t(run.first)], numbers + " " + FillKindName(run.kind), first, last});
  }
  return tiles;
}

/// The legend above the rows: the colour map from convex to concave.
QImage Legend(int width) {
  QImage legend(std::max(width, 560), kLine + 3 * kPad + 16, QImage::Format_RGB32);
  legend.fill(kBackground);
  DrawText(legend, kPad, kPad + 4, "mean curvature:", kScale, kText);
  const int x0 = kPad + TextWidth("mean curvature: ", kScale), bar = 240, y = kPad;
  for (int x = 0; x < bar; ++x) {
    const vcg_ext::Rgb8 c = vcg_ext::CurvatureColormap::Color8(double(x) / (bar - 1));
    for (int dy = 0; dy < 16; ++dy) legend.setPixel(x0 + x, y + dy, qRgb(c.r, c.g, c.b));
  }
  const int ty = y + 16 + 4;
  DrawText(legend, x0, ty, "convex", kScale, kDim);
  DrawText(legend, x0 + (bar - TextWidth("flat", kScale)) / 2, ty, "flat", kScale, kDim);
  DrawText(legend, x0 + bar - TextWidth("concave", kScale), ty, "concave", kScale, kDim);
  return legend;
}

} // namespace

namespace {

/// Hole k's row of `tiles`, with tile `chosen` framed and `reason` beneath it (no frame where
/// `chosen` is past the tiles).
MontageRow BuildRow(const std::vector<Tile>& tiles, size_t k, int boundary_edges, size_t chosen,
                    const std::string& reason) {
  const int cells = int(tiles.size());
  auto x_of = [](int c) { return kLabel + c * (kCell + kPad); };
  const bool framed = chosen < tiles.size();
  const int top = kPad + kLine, height = top + kCell + kPad + (framed ? kLine + kPad : 0);
  const int width =
      std::max(x_of(cells), framed ? x_of(int(chosen)) + TextWidth(reason, kScale) + kPad : 0);
  QImage row(width, height, QImage::Format_RGB32);
  row.fill(kBackground);
  DrawText(row, kPad, top, "hole " + std::to_string(k + 1), kScale, kText);
  DrawText(row, kPad, top + kLine, std::to_string(boundary_edges) + " edges", kScale, kDim);
  QPainter painter(&row);
  if (framed)
    painter.fillRect(
        QRect(x_of(int(chosen)) - kPad / 2, top - kPad / 2, kCell + kPad, kCell + kPad),
        QColor(255, 255, 255));
  for (int c = 0; c < cells; ++c)
    painter.drawImage(QRect(x_of(c), top, kCell, kCell), tiles[size_t(c)].image);
  painter.end();
  MontageRow made{row, int(k) + 1, boundary_edges, {}, chosen, framed ? reason : ""};
  for (int c = 0; c < cells; ++c) {
    const Tile& t = tiles[size_t(c)];
    DrawText(row, x_of(c), kPad / 2, t.caption, kScale, kText);
    made.tiles.push_back({t.caption, t.first, t.last, x_of(c), top, kCell});
  }
  if (framed) DrawText(row, x_of(int(chosen)), top + kCell + kPad, reason, kScale, kText);
  made.image = row;
  return made;
}

/// `image` over a grey checkerboard, so that its transparent pixels show as such.
QImage OnCheckerboard(const QImage& image) {
  QImage board(image.size(), QImage::Format_RGB32);
  for (int j = 0; j < board.height(); ++j)
    for (int i = 0; i < board.width(); ++i)
      board.setPixel(i, j, ((i / 16 + j / 16) % 2) ? qRgb(200, 200, 200) : qRgb(150, 150, 150));
  QPainter painter(&board);
  painter.drawImage(0, 0, image);
  painter.end();
  return board;
}

} // namespace

MontageRow MakeMontageRow(const HoleVariations& hv, size_t k, int framed, const std::string& reason,
                          const QImage& final_image) {
  std::vector<Tile> tiles{{hv.image, "smooth fill"}, {hv.mask, "hole"}};
  for (Tile& t : VariationTiles(hv)) tiles.push_back(std::move(t));
  if (!final_image.isNull()) tiles.push_back({final_image, "result"});
  size_t chosen = 0; // the smooth fill's tile, unless a variation was applied
  for (size_t c = 2; c < tiles.size(); ++c)
    if (framed > 0 && tiles[c].first <= framed && framed <= tiles[c].last) chosen = c;
  return BuildRow(tiles, k, hv.boundary_edges, chosen, reason);
}

MontageRow MakeImagesRow(const HoleImage& hi, size_t k, int boundary_edges) {
  const std::vector<Tile> tiles{{ToQImage(hi.image, false), "curvature"},
                                {OnCheckerboard(ToQImage(hi.image, true)), "hole transparent"},
                                {MaskImage(hi.image), "mask"}};
  return BuildRow(tiles, k, boundary_edges, tiles.size(), "");
}

void SaveMontage(const std::vector<MontageRow>& rows, const std::string& path) {
  if (rows.empty()) return;
  int w = 0, h = 0;
  for (const auto& r : rows) w = std::max(w, r.image.width()), h += r.image.height();
  const QImage legend = Legend(w);
  w = std::max(w, legend.width());
  QImage montage(w, legend.height() + h, QImage::Format_RGB32);
  montage.fill(kBackground);
  QPainter painter(&montage);
  painter.drawImage(0, 0, legend);
  std::ostringstream json;
  json << "{\n  \"rows\": [";
  int y = legend.height();
  for (size_t i = 0; i < rows.size(); ++i) {
    const MontageRow& r = rows[i];
    painter.drawImage(0, y, r.image);
    json << (i ? "," : "") << "\n    {\"hole\": " << r.hole
         << ", \"boundary_edges\": " << r.boundary_edges << ", \"y\": " << y
         << ", \"framed_tile\": " << r.framed << ", \"reason\": " << JsonQuoted(r.reason)
         << ", \"tiles\": [";
    for (size_t t = 0; t < r.tiles.size(); ++t) {
      const MontageTile& tile = r.tiles[t];
      json << (t ? ", " : "") << "{\"caption\": " << JsonQuoted(tile.caption)
           << ", \"variations\": [" << tile.first << ", " << tile.last << "], \"x\": " << tile.x
           << ", \"y\": " << y + tile.y << ", \"size\": " << tile.size << "}";
    }
    json << "]}";
    y += r.image.height();
  }
  json << "\n  ]\n}\n";
  painter.end();
  SavePngAtomically(montage, path);
  WriteFileAtomically(path.substr(0, path.rfind('.')) + ".json", json.str());
}

} // namespace curvature_inpaint
