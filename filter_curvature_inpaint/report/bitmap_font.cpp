#include "report/bitmap_font.h"

#include <cctype>
#include <map>

namespace curvature_inpaint {

namespace {

/// Seven rows of five columns per character, '#' drawn.
using Glyph = const char* [7];

const std::map<char, const char* const*>& Glyphs() {
  static Glyph a{".....", ".....", ".###.", "....#", ".####", "#...#", ".####"};
  static Glyph b{"#....", "#....", "####.", "#...#", "#...#", "#...#", "####."};
  static Glyph c{".....", ".....", ".###.", "#....", "#....", "#...#", ".###."};
  static Glyph d{"....#", "....#", ".####", "#...#", "#...#", "#...#", ".####"};
  static Glyph e{".....", ".....", ".###.", "#...#", "#####", "#....", ".###."};
  static Glyph f{"..##.", ".#..#", ".#...", "###..", ".#...", ".#...", ".#..."};
  static Glyph g{".....", ".....", ".####", "#...#", ".####", "....#", ".###."};
  static Glyph h{"#....", "#....", "#.##.", "##..#", "#...#", "#...#", "#...#"};
  static Glyph i{"..#..", ".....", ".##..", "..#..", "..#..", "..#..", ".###."};
  static Glyph j{"...#.", ".....", "..##.", "...#.", "...#.", "#..#.", ".##.."};
  static Glyph k{"#....", "#....", "#..#.", "#.#..", "##...", "#.#..", "#..#."};
  static Glyph l{".##..", "..#..", "..#..", "..#..", "..#..", "..#..", ".###."};
  static Glyph m{".....", ".....", "##.#.", "#.#.#", "#.#.#", "#.#.#", "#.#.#"};
  static Glyph n{".....", ".....", "#.##.", "##..#", "#...#", "#...#", "#...#"};
  static Glyph o{".....", ".....", ".###.", "#...#", "#...#", "#...#", ".###."};
  static Glyph p{".....", ".....", "####.", "#...#", "####.", "#....", "#...."};
  static Glyph q{".....", ".....", ".####", "#...#", ".####", "....#", "....#"};
  static Glyph r{".....", ".....", "#.##.", "##..#", "#....", "#....", "#...."};
  static Glyph s{".....", ".....", ".####", "#....", ".###.", "....#", "####."};
  static Glyph t{".#...", ".#...", "###..", ".#...", ".#...", ".#..#", "..##."};
  static Glyph u{".....", ".....", "#...#", "#...#", "#...#", "#..##", ".##.#"};
  static Glyph v{".....", ".....", "#...#", "#...#", "#...#", ".#.#.", "..#.."};
  static Glyph w{".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."};
  static Glyph x{".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"};
  static Glyph y{".....", ".....", "#...#", "#...#", ".####", "....#", ".###."};
  static Glyph z{".....", ".....", "#####", "...#.", "..#..", ".#...", "#####"};
  static Glyph d0{".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."};
  static Glyph d1{"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."};
  static Glyph d2{".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"};
  static Glyph d3{"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."};
  static Glyph d4{"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."};
  static Glyph d5{"#####", "#....", "####.", "....#", "....#", "#...#", ".###."};
  static Glyph d6{"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."};
  static Glyph d7{"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."};
  static Glyph d8{".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."};
  static Glyph d9{".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."};
  static Glyph space{".....", ".....", ".....", ".....", ".....", ".....", "....."};
  static Glyph dot{".....", ".....", ".....", ".....", ".....", ".##..", ".##.."};
  static Glyph comma{".....", ".....", ".....", ".....", ".##..", "..#..", ".#..."};
  static Glyph colon{".....", ".##..", ".##..", ".....", ".##..", ".##..", "....."};
  static Glyph minus{".....", ".....", ".....", "#####", ".....", ".....", "....."};
  static Glyph plus{".....", "..#..", "..#..", "#####", "..#..", "..#..", "....."};
  static Glyph percent{"##...", "##..#", "...#.", "..#..", ".#...", "#..##", "...##"};
  static Glyph open{"...#.", "..#..", ".#...", ".#...", ".#...", "..#..", "...#."};
  static Glyph close{".#...", "..#..", "...#.", "...#.", "...#.", "..#..", ".#..."};
  static Glyph slash{".....", "....#", "...#.", "..#..", ".#...", "#....", "....."};
  static Glyph quote{"..#..", "..#..", ".#...", ".....", ".....", ".....", "....."};
  static Glyph equals{".....", ".....", "#####", ".....", "#####", ".....", "....."};
  static Glyph question{".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."};
  static Glyph underscore{".....", ".....", ".....", ".....", ".....", ".....", "#####"};
  static const std::map<char, const char* const*> glyphs{
      {'a', a},        {'b', b},         {'c', c},     {'d', d},     {'e', e},      {'f', f},
      {'g', g},        {'h', h},         {'i', i},     {'j', j},     {'k', k},      {'l', l},
      {'m', m},        {'n', n},         {'o', o},     {'p', p},     {'q', q},      {'r', r},
      {'s', s},        {'t', t},         {'u', u},     {'v', v},     {'w', w},      {'x', x},
      {'y', y},        {'z', z},         {'0', d0},    {'1', d1},    {'2', d2},     {'3', d3},
      {'4', d4},       {'5', d5},        {'6', d6},    {'7', d7},    {'8', d8},     {'9', d9},
      {' ', space},    {'.', dot},       {',', comma}, {':', colon}, {'-', minus},  {'+', plus},
      {'%', percent},  {'(', open},      {')', close}, {'/', slash}, {'\'', quote}, {'=', equals},
      {'?', question}, {'_', underscore}};
  return glyphs;
}

} // namespace

int TextWidth(const std::string& text, int scale) {
  return text.empty() ? 0 : int(text.size()) * 6 * scale - scale;
}

void DrawText(QImage& image, int x, int y, const std::string& text, int scale, QColor color) {
  const auto& glyphs = Glyphs();
  const QRgb rgb = color.rgb();
  for (char ch : text) {
    auto it = glyphs.find(char(std::tolower(static_cast<unsigned char>(ch))));
    if (it == glyphs.end()) it = glyphs.find('?');
    for (int row = 0; row < 7; ++row)
      for (int col = 0; col < 5; ++col) {
        if (it->second[row][col] != '#') continue;
        for (int dy = 0; dy < scale; ++dy)
          for (int dx = 0; dx < scale; ++dx) {
            const int px = x + col * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && py >= 0 && px < image.width() && py < image.height())
              image.setPixel(px, py, rgb);
          }
      }
    x += 6 * scale;
  }
}

} // namespace curvature_inpaint
