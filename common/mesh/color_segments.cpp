#include "common/mesh/color_segments.h"

namespace primitive_edit {

namespace detail {

vcg::Color4b segment_palette_color(int c)
{
  static const unsigned char palette[][3] = {
      {230, 25, 75},   {60, 180, 75},   {255, 225, 25}, {0, 130, 200},   {245, 130, 48},
      {145, 30, 180},  {70, 240, 240},  {240, 50, 230}, {210, 245, 60},  {250, 190, 212},
      {0, 128, 128},   {220, 190, 255}, {170, 110, 40}, {255, 250, 200}, {128, 0, 0},
      {170, 255, 195}, {128, 128, 0},   {255, 215, 180}, {0, 0, 128}};
  const int size = int(sizeof(palette) / sizeof(palette[0]));
  const int level = c / size;
  if (level > 4) {
    const std::uint32_t h = std::uint32_t(c) * 2654435761u;
    return vcg::Color4b((unsigned char)(h >> 24), (unsigned char)(h >> 16), (unsigned char)(h >> 8), 255);
  }
  static const double darken[5] = {1.0, 0.6, 1.0, 0.36, 1.0};
  static const double lighten[5] = {0.0, 0.0, 0.45, 0.0, 0.7};
  const unsigned char* base = palette[c % size];
  unsigned char rgb[3];
  for (int i = 0; i < 3; ++i) {
    const double x = double(base[i]) * darken[level];
    rgb[i] = (unsigned char)std::lround(x + (255.0 - x) * lighten[level]);
  }
  return vcg::Color4b(rgb[0], rgb[1], rgb[2], 255);
}

} // namespace detail
} // namespace primitive_edit
