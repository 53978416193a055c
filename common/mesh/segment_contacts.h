// segment_contacts.h: which segments of a mesh touch, how long their common border is, and where it lies.
//
// Input:  a vcg triangle mesh, segment_of_face (indexed by vcg::tri::Index; -1 = none) and its FaceAdjacency
//         (face_adjacency.h).
// Output: one SegmentContact per pair of segments a < b that share at least one edge: the number of
//         face pairs across their border (about the border's length in edges) and a point of the border: of the
//         pairs' centroid midpoints, the one nearest to their mean (the middle of a straight border; some
//         point of a closed circular one, whose mean is its centre). Sorted by (a, b). Faces with non-finite
//         coordinates take no part.
// Cost:   O(F) plus O(B log B) for the B border face pairs.
#ifndef PRIMITIVE_EDIT_SEGMENT_CONTACTS_H
#define PRIMITIVE_EDIT_SEGMENT_CONTACTS_H

#include "common/mesh/face_adjacency.h"
#include "common/mesh/face_centroids_and_areas.h"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <tuple>
#include <vector>

namespace primitive_edit {

struct SegmentContact
{
  int a = -1, b = -1;  // a < b
  int pairs = 0;       // face pairs across the border
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

template <class MeshType>
std::vector<SegmentContact> segment_contacts(const MeshType& m, const std::vector<int>& segment_of_face,
                                             const FaceAdjacency& adj)
{
  std::vector<SegmentContact> out;
  const int face_count = adj.face_count();
  if (int(segment_of_face.size()) != face_count || int(m.face.size()) != face_count)
    return out;
  const FaceCentroidsAndAreas faces = face_centroids_and_areas(m);
  std::vector<std::tuple<int, int, int, int>> border;  // (a, b, f, h)
  for (int f = 0; f < face_count; ++f) {
    const int a = segment_of_face[std::size_t(f)];
    if (a < 0 || !faces.centroid[std::size_t(f)].allFinite())
      continue;
    for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
      const int h = adj.neighbour[std::size_t(k)];
      const int b = segment_of_face[std::size_t(h)];
      if (b > a && faces.centroid[std::size_t(h)].allFinite())
        border.emplace_back(a, b, f, h);
    }
  }
  std::sort(border.begin(), border.end());
  for (std::size_t i = 0; i < border.size();) {
    SegmentContact c;
    c.a = std::get<0>(border[i]);
    c.b = std::get<1>(border[i]);
    auto midpoint = [&](std::size_t j) {
      return Eigen::Vector3d(0.5 * (faces.centroid[std::size_t(std::get<2>(border[j]))] +
                                    faces.centroid[std::size_t(std::get<3>(border[j]))]));
    };
    const std::size_t first = i;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (; i < border.size() && std::get<0>(border[i]) == c.a && std::get<1>(border[i]) == c.b; ++i) {
      mean += midpoint(i);
      ++c.pairs;
    }
    mean /= double(c.pairs);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = first; j < i; ++j)
      if ((midpoint(j) - mean).squaredNorm() < best) {
        best = (midpoint(j) - mean).squaredNorm();
        c.point = midpoint(j);
      }
    out.push_back(c);
  }
  return out;
}

} // namespace primitive_edit

#endif
