// split_segments_by_plane.h: the paper's manual "split mesh segment": a cut by a plane (in the GUI, the plane
// through the line the user draws and the viewing direction).
//
// Input:  the mesh, its FaceAdjacency, segment_of_face, the ids of the segments to split, the plane as a
//         point and a normal (normalised here; a zero or non-finite plane leaves the segments as they are),
//         and SplitOptions: where the plane may cut (a per-face mask, for the stretch of the drawn stroke;
//         empty: everywhere) and the smallest piece to keep.
// Output: each face of a listed segment is classified by the side of its centroid (on the plane counts as the
//         positive side; a NaN centroid as the negative side); the segment is cut between neighbouring faces
//         on opposite sides when both may be cut, and every connected piece becomes its own segment. A piece
//         of fewer than min_piece_faces faces joins the neighbouring piece of the same former segment it
//         shares most edges with (slivers where the plane grazes the surface are not segments), and one still
//         that small the former segment's largest piece (stray faces of the segment stay in it). Other
//         segments are untouched. Ids are compacted to 0..K-1. Returns K.
// Complexity: O(F + adjacency size + L log L) for L listed ids; iterative flood fill.
#ifndef PRIMITIVE_EDIT_SPLIT_SEGMENTS_BY_PLANE_H
#define PRIMITIVE_EDIT_SPLIT_SEGMENTS_BY_PLANE_H

#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/face_adjacency.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace primitive_edit {

// The smallest piece a cut by hand leaves, in the edit tool and the filter alike: where the plane grazes the
// surface it cuts off slivers of a few faces, no segment to fit.
constexpr int kMinSplitPieceFaces = 10;

struct SplitOptions
{
  std::vector<char> cuttable;  // per face: the plane may cut next to it; empty: everywhere
  int min_piece_faces = 1;     // smaller pieces join a neighbouring piece of their former segment
};

namespace split_detail {

// Joins every piece (id >= first_piece) of fewer than min_faces faces to the neighbouring piece of the same
// former segment it shares most edges with; a piece still under min_faces then (without such a neighbour, or
// all of them small) joins its former segment's largest piece, so that every piece has min_faces faces or is
// all of its former segment. O(F + adjacency log F).
void absorb_small_pieces(const FaceAdjacency& adj, const std::vector<int>& former, int first_piece,
                         int min_faces, std::vector<int>& segment_of_face);

} // namespace split_detail

template <class MeshType>
int split_segments_by_plane(const MeshType& m, const FaceAdjacency& adj, std::vector<int>& segment_of_face,
                            const std::vector<int>& segments, const Eigen::Vector3d& point,
                            const Eigen::Vector3d& normal, const SplitOptions& options = {})
{
  const double length = normal.norm();
  if (segment_of_face.size() != m.face.size() || adj.face_count() != int(m.face.size()) || !point.allFinite() ||
      !std::isfinite(length) || length <= 0.0)
    return compact_segment_ids(segment_of_face);
  const Eigen::Vector3d unit = normal / length;

  std::vector<int> listed(segments);
  std::sort(listed.begin(), listed.end());
  listed.erase(std::unique(listed.begin(), listed.end()), listed.end());

  // side[f]: -1 not split, 0 negative side, 1 positive side. Split faces are taken out (-1) before compacting,
  // so the remaining ids are 0..K-1 and the pieces can be numbered from K.
  const std::size_t face_count = m.face.size();
  const std::vector<int> former(segment_of_face);
  std::vector<signed char> side(face_count, -1);
  for (std::size_t f = 0; f < face_count; ++f) {
    const int s = former[f];
    if (s < 0 || !std::binary_search(listed.begin(), listed.end(), s))
      continue;
    const auto& face = m.face[f];
    Eigen::Vector3d centroid = Eigen::Vector3d::Constant(std::nan(""));
    if (face.cV(0) != nullptr && face.cV(1) != nullptr && face.cV(2) != nullptr) {
      centroid.setZero();
      for (int k = 0; k < 3; ++k)
        centroid += Eigen::Vector3d(double(face.cP(k)[0]), double(face.cP(k)[1]), double(face.cP(k)[2]));
      centroid /= 3.0;
    }
    side[f] = (centroid - point).dot(unit) >= 0.0 ? 1 : 0;
    segment_of_face[f] = -1;
  }
  const int first_piece = compact_segment_ids(segment_of_face);
  int next = first_piece;
  const bool everywhere = options.cuttable.size() != face_count;
  auto joined = [&](std::size_t f, std::size_t g) {
    return side[g] == side[f] || (!everywhere && (!options.cuttable[f] || !options.cuttable[g]));
  };

  std::vector<int> stack;
  for (std::size_t seed = 0; seed < face_count; ++seed) {
    if (side[seed] < 0 || segment_of_face[seed] >= 0)
      continue;
    const int id = next++;
    segment_of_face[seed] = id;
    stack.push_back(int(seed));
    while (!stack.empty()) {
      const std::size_t f = std::size_t(stack.back());
      stack.pop_back();
      for (int k = adj.offset[f]; k < adj.offset[f + 1]; ++k) {
        const std::size_t g = std::size_t(adj.neighbour[std::size_t(k)]);
        if (side[g] >= 0 && joined(f, g) && former[g] == former[f] && segment_of_face[g] < 0) {
          segment_of_face[g] = id;
          stack.push_back(int(g));
        }
      }
    }
  }
  split_detail::absorb_small_pieces(adj, former, first_piece, options.min_piece_faces, segment_of_face);
  return compact_segment_ids(segment_of_face);
}

} // namespace primitive_edit

#endif
