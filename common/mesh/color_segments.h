// color_segments.h: one display colour per segment, neighbouring segments always in different colours.
//
// Input:  the mesh, its FaceAdjacency and segment_of_face with dense ids 0..K-1 (-1 for no segment).
// Output: K colours, indexed by segment id. Segments are coloured greedily over the segment adjacency graph
//         (most-connected first): each takes the first palette entry none of its coloured neighbours uses.
//         The palette holds 19 well distinguishable hues; beyond that the hues repeat darker and lighter, then
//         hashed colours follow; every colour number maps to a distinct RGB, so neighbours differ for any K. An empty vector when the
//         ids are not dense (some id above 2F + 1024) or sizes do not match.
// Complexity: O(F + E log E) for E face pairs across segment borders, plus O(C^2) for C colours used.
#ifndef PRIMITIVE_EDIT_COLOR_SEGMENTS_H
#define PRIMITIVE_EDIT_COLOR_SEGMENTS_H

#include "common/mesh/face_adjacency.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace primitive_edit {

namespace detail {

// Colour number c < 95: palette hue c % 19 at lightness level c / 19 (0 as is, 1 and 3 darker, 2 and 4
// lighter); further numbers are spread over the RGB cube by a multiplicative hash.
vcg::Color4b segment_palette_color(int c);

} // namespace detail

template <class MeshType>
std::vector<vcg::Color4b> color_segments(const MeshType& m, const FaceAdjacency& adj,
                                         const std::vector<int>& segment_of_face)
{
  const std::size_t face_count = segment_of_face.size();
  if (face_count != m.face.size() || adj.face_count() != int(face_count))
    return {};
  int max_id = -1;
  for (int s : segment_of_face)
    max_id = std::max(max_id, s);
  if (max_id < 0 || std::size_t(max_id) > 2 * face_count + 1024)
    return {};
  const std::size_t K = std::size_t(max_id) + 1;

  // Segment adjacency: every (smaller, larger) id pair meeting across an edge, sorted and unique.
  std::vector<std::uint64_t> pairs;
  for (std::size_t f = 0; f < face_count; ++f) {
    const int a = segment_of_face[f];
    if (a < 0)
      continue;
    for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
      const int b = segment_of_face[std::size_t(adj.neighbour[std::size_t(k)])];
      if (b > a)
        pairs.push_back((std::uint64_t(a) << 32) | std::uint64_t(b));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<int> offset(K + 1, 0);
  for (std::uint64_t p : pairs) {
    ++offset[std::size_t(p >> 32) + 1];
    ++offset[std::size_t(p & 0xFFFFFFFFu) + 1];
  }
  for (std::size_t s = 0; s < K; ++s)
    offset[s + 1] += offset[s];
  std::vector<int> neighbour(static_cast<std::size_t>(offset[K]));
  {
    std::vector<int> cursor(offset.begin(), offset.end() - 1);
    for (std::uint64_t p : pairs) {
      const int a = int(p >> 32), b = int(p & 0xFFFFFFFFu);
      neighbour[std::size_t(cursor[std::size_t(a)]++)] = b;
      neighbour[std::size_t(cursor[std::size_t(b)]++)] = a;
    }
  }

  // Welsh-Powell order: most neighbours first keeps the number of colours low.
  std::vector<int> order(K);
  for (std::size_t s = 0; s < K; ++s)
    order[s] = int(s);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const int da = offset[std::size_t(a) + 1] - offset[std::size_t(a)];
    const int db = offset[std::size_t(b) + 1] - offset[std::size_t(b)];
    return da != db ? da > db : a < b;
  });
  std::vector<int> colour(K, -1);
  std::vector<int> used_by(K + 1, -1); // used_by[c] == s: colour c is taken by a neighbour of s
  int colour_count = 0;
  for (int s : order) {
    for (int k = offset[std::size_t(s)]; k < offset[std::size_t(s) + 1]; ++k) {
      const int c = colour[std::size_t(neighbour[std::size_t(k)])];
      if (c >= 0)
        used_by[std::size_t(c)] = s;
    }
    int c = 0;
    while (used_by[std::size_t(c)] == s)
      ++c;
    colour[std::size_t(s)] = c;
    colour_count = std::max(colour_count, c + 1);
  }

  // Colour numbers to RGB; rounding could make two far-apart numbers equal, so nudge duplicates apart.
  std::vector<vcg::Color4b> table;
  table.reserve(std::size_t(colour_count));
  for (int c = 0; c < colour_count; ++c) {
    vcg::Color4b rgb = detail::segment_palette_color(c);
    // An odd step walks all 2^24 RGB values before repeating, so a free one is found.
    while (std::find(table.begin(), table.end(), rgb) != table.end()) {
      const std::uint32_t v = ((std::uint32_t(rgb[0]) << 16 | std::uint32_t(rgb[1]) << 8 | rgb[2]) + 0x9E3779u) & 0xFFFFFFu;
      rgb = vcg::Color4b((unsigned char)(v >> 16), (unsigned char)(v >> 8), (unsigned char)v, 255);
    }
    table.push_back(rgb);
  }
  std::vector<vcg::Color4b> result(K);
  for (std::size_t s = 0; s < K; ++s)
    result[s] = table[std::size_t(colour[s])];
  return result;
}

} // namespace primitive_edit

#endif
