// segment_contacts.h: which segments of a mesh touch, how long their common border is, and where it lies.
//
// Input:  a vcg triangle mesh and segment_of_face (indexed by vcg::tri::Index; -1 = none).
// Output: one SegmentContact per pair of segments a < b that share at least one edge: the number of
//         face pairs across their border (about the border's length in edges) and a point of the border: of the
//         pairs' centroid midpoints, the one nearest to their mean (the middle of a straight border; some
//         point of a closed circular one, whose mean is its centre) and that mean (a straight border's mean
//         distance from a line is the mean's), and up to kContactPoints of those midpoints, evenly strided (a
//         border about an axis, whose mean lies on the axis, has its radius and height in their own means; see
//         meridian_section.h). Sorted by (a, b). Two faces are a pair
//         as in face_adjacency.h: they share an edge (a non-manifold edge pairs all of its faces, a pair
//         sharing two edges counts once; deleted faces, faces with an invalid vertex and an edge joining a
//         vertex to itself pair nothing). Faces with non-finite coordinates take no part.
// Method: no face adjacency of the whole mesh: a pass over the faces marks the vertices that faces of two
//         segments share; only edges with both ends marked can lie on a border, and those are sorted to
//         find the faces on each. Fit All needs nothing else of the adjacency once the roughness is kept on
//         the mesh, and at 1M faces building it took 0.08 s.
// Cost:   O(F + V) plus O(E log E) for the E edges with both ends on a border.
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

constexpr int kContactPoints = 128;

struct SegmentContact
{
  int a = -1, b = -1;  // a < b
  int pairs = 0;       // face pairs across the border
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();  // of the pairs' centroid midpoints
  std::vector<Eigen::Vector3d> points = {};        // up to kContactPoints of them, evenly strided
};

namespace contacts_detail {

// (a, b, f, h): face f of segment a and face h of segment b > a share an edge; sorted, each pair once.
template <class MeshType>
std::vector<std::tuple<int, int, int, int>> border_face_pairs(const MeshType& m,
                                                              const std::vector<int>& segment_of_face)
{
  constexpr int kUnseen = -1, kShared = -2;
  const std::size_t face_count = m.face.size();
  auto segment_and_corners = [&](std::size_t f, int c[3]) {
    const int s = segment_of_face[f];
    return s >= 0 && detail::face_corner_indices(m, f, c) ? s : -1;
  };
  std::vector<int> segment_at(m.vert.size(), kUnseen);  // the one segment around a vertex, or kShared
  for (std::size_t f = 0; f < face_count; ++f) {
    int c[3];
    const int s = segment_and_corners(f, c);
    if (s < 0)
      continue;
    for (const int v : c) {
      int& at = segment_at[std::size_t(v)];
      at = (at == kUnseen || at == s) ? s : kShared;
    }
  }
  std::vector<std::tuple<int, int, int>> edges;  // (low vertex, high vertex, face)
  for (std::size_t f = 0; f < face_count; ++f) {
    int c[3];
    if (segment_and_corners(f, c) < 0)
      continue;
    for (int k = 0; k < 3; ++k) {
      const int a = c[k], b = c[(k + 1) % 3];
      if (a != b && segment_at[std::size_t(a)] == kShared && segment_at[std::size_t(b)] == kShared)
        edges.emplace_back(std::min(a, b), std::max(a, b), int(f));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::tuple<int, int, int, int>> pairs;
  for (std::size_t i = 0, end = 0; i < edges.size(); i = end) {
    for (end = i; end < edges.size() && std::get<0>(edges[end]) == std::get<0>(edges[i]) &&
                  std::get<1>(edges[end]) == std::get<1>(edges[i]);
         ++end) {
    }
    for (std::size_t x = i; x < end; ++x)
      for (std::size_t y = x + 1; y < end; ++y) {
        int f = std::get<2>(edges[x]), h = std::get<2>(edges[y]);
        int a = segment_of_face[std::size_t(f)], b = segment_of_face[std::size_t(h)];
        if (a == b)
          continue;
        if (a > b)
          std::swap(a, b), std::swap(f, h);
        pairs.emplace_back(a, b, f, h);
      }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

} // namespace contacts_detail

template <class MeshType>
std::vector<SegmentContact> segment_contacts(const MeshType& m, const std::vector<int>& segment_of_face)
{
  std::vector<SegmentContact> out;
  if (segment_of_face.size() != m.face.size())
    return out;
  std::vector<std::tuple<int, int, Eigen::Vector3d>> border;  // (a, b, midpoint of the pair's centroids)
  for (const auto& [a, b, f, h] : contacts_detail::border_face_pairs(m, segment_of_face)) {
    Eigen::Vector3d cf, ch;
    double area;
    if (face_centroid_and_area(m.face[std::size_t(f)], cf, area) &&
        face_centroid_and_area(m.face[std::size_t(h)], ch, area))
      border.emplace_back(a, b, 0.5 * (cf + ch));
  }
  for (std::size_t i = 0; i < border.size();) {
    SegmentContact c;
    c.a = std::get<0>(border[i]);
    c.b = std::get<1>(border[i]);
    const std::size_t first = i;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (; i < border.size() && std::get<0>(border[i]) == c.a && std::get<1>(border[i]) == c.b; ++i) {
      mean += std::get<2>(border[i]);
      ++c.pairs;
    }
    mean /= double(c.pairs);
    c.mean = mean;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = first; j < i; ++j)
      if ((std::get<2>(border[j]) - mean).squaredNorm() < best) {
        best = (std::get<2>(border[j]) - mean).squaredNorm();
        c.point = std::get<2>(border[j]);
      }
    const std::size_t stride = (i - first + kContactPoints - 1) / kContactPoints;
    for (std::size_t j = first; j < i; j += stride)
      c.points.push_back(std::get<2>(border[j]));
    out.push_back(c);
  }
  return out;
}

} // namespace primitive_edit

#endif
