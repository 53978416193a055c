// split_segments_by_plane.h: the paper's manual "split mesh segment": a cut by a plane (in the GUI, the plane
// through the line the user draws and the viewing direction).
//
// Input:  the mesh, its FaceAdjacency, segment_of_face, the ids of the segments to split, and the plane as a
//         point and a normal (normalised here; a zero or non-finite plane leaves the segments as they are).
// Output: each face of a listed segment is classified by the side of its centroid (on the plane counts as the
//         positive side; a NaN centroid as the negative side); every connected piece of faces of the same
//         former segment on the same side becomes its own segment. Other segments are untouched. Ids are
//         compacted to 0..K-1. Returns K.
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
#include <vector>

namespace primitive_edit {

template <class MeshType>
int split_segments_by_plane(const MeshType& m, const FaceAdjacency& adj, std::vector<int>& segment_of_face,
                            const std::vector<int>& segments, const Eigen::Vector3d& point,
                            const Eigen::Vector3d& normal)
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
  int next = compact_segment_ids(segment_of_face);

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
        if (side[g] == side[f] && former[g] == former[f] && segment_of_face[g] < 0) {
          segment_of_face[g] = id;
          stack.push_back(int(g));
        }
      }
    }
  }
  return compact_segment_ids(segment_of_face);
}

} // namespace primitive_edit

#endif
