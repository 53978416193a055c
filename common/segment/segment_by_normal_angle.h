// segment_by_normal_angle.h: the paper's automatic segmentation (Yang, Oh, Choi, section 2.1).
//
// Input:  a vcg triangle mesh, optionally its FaceAdjacency (built here otherwise), and parameters:
//         angle_deg            two adjacent faces join when the angle between their smoothed normals is below it;
//         smoothing_iterations passes of smooth_face_normals against scan noise. Averaging skips neighbours
//                              beyond a crease angle of min(2 * angle_deg, 80) degrees, so that smoothing never
//                              blurs a sharp edge into a ramp of small steps the flood fill would walk across;
//         min_segment_faces    segments with fewer faces are absorbed by the neighbouring segment with which
//                              they share the longest border (repeatedly, smallest first, until none is left
//                              or a small segment has no neighbour at all).
// Output: segment_of_face (indexed by vcg::tri::Index): dense ids 0..K-1, -1 for deleted faces. Returns K.
//         Faces without a defined normal (zero area, NaN coordinates) join no neighbour in the flood fill; they
//         start as single-face segments and are absorbed like any small segment. An adjacency whose size does
//         not match the mesh gives 0 and every face -1.
// Complexity: O(F) for adjacency, smoothing and the iterative (explicit stack) flood fill; the absorption runs
//         in rounds, each linear in the faces of the still-small segments, with at least half of them merged
//         per round. No per-face heap allocation, no maps.
#ifndef PRIMITIVE_EDIT_SEGMENT_BY_NORMAL_ANGLE_H
#define PRIMITIVE_EDIT_SEGMENT_BY_NORMAL_ANGLE_H

#include "common/base/constants.h"
#include "common/base/progress.h"
#include "common/mesh/compact_segment_ids.h"
#include "common/mesh/face_adjacency.h"
#include "common/mesh/smooth_face_normals.h"

#include <Eigen/Core>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace primitive_edit {

struct SegmentByNormalAngleParams
{
  double angle_deg = 20.0;
  int smoothing_iterations = 2;
  int min_segment_faces = 30;
};

namespace detail {

inline int find_root(std::vector<int>& parent, int s)
{
  int root = s;
  while (parent[std::size_t(root)] != root)
    root = parent[std::size_t(root)];
  while (parent[std::size_t(s)] != root) {
    const int up = parent[std::size_t(s)];
    parent[std::size_t(s)] = root;
    s = up;
  }
  return root;
}

// Length of the edge faces f and g share (0 when it is not finite); fv holds 3 vertex indices per face.
template <class MeshType>
double shared_edge_length(const MeshType& m, const std::vector<int>& fv, int f, int g)
{
  const int* a = &fv[3 * std::size_t(f)];
  const int* b = &fv[3 * std::size_t(g)];
  for (int k = 0; k < 3; ++k) {
    const int u = a[k];
    const int v = a[(k + 1) % 3];
    if (u == v || (b[0] != u && b[1] != u && b[2] != u) || (b[0] != v && b[1] != v && b[2] != v))
      continue;
    const auto d = m.vert[std::size_t(u)].cP() - m.vert[std::size_t(v)].cP();
    const double length = std::sqrt(double(d[0]) * double(d[0]) + double(d[1]) * double(d[1]) +
                                     double(d[2]) * double(d[2]));
    return std::isfinite(length) ? length : 0.0;
  }
  return 0.0;
}

// Absorbs segments smaller than min_faces into the neighbour segment with the longest shared border.
// segment_of_face holds ids 0..K-1 (or -1); ids are left uncompacted.
template <class MeshType>
void absorb_small_segments(const MeshType& m, const FaceAdjacency& adj, int min_faces,
                           std::vector<int>& segment_of_face, int segment_count)
{
  const std::size_t K = std::size_t(segment_count);
  std::vector<int> size(K, 0);
  for (int s : segment_of_face)
    if (s >= 0)
      ++size[std::size_t(s)];
  std::vector<int> parent(K);
  for (std::size_t s = 0; s < K; ++s)
    parent[s] = int(s);
  std::vector<char> isolated(K, 0);

  const std::vector<int> fv = face_vertex_indices(m);
  // Faces that may still belong to a small segment; segments only grow, so the list only shrinks.
  std::vector<int> candidates;
  for (std::size_t f = 0; f < segment_of_face.size(); ++f) {
    const int s = segment_of_face[f];
    if (s >= 0 && size[std::size_t(s)] < min_faces)
      candidates.push_back(int(f));
  }

  std::vector<int> small_roots, slot(K, -1), face_offset, faces, touched;
  std::vector<double> border(K, 0.0);
  std::vector<int> border_edges(K, 0);
  for (;;) {
    // Group the candidate faces by their current (small, not isolated) root.
    small_roots.clear();
    std::size_t kept = 0;
    for (int f : candidates) {
      const int r = find_root(parent, segment_of_face[std::size_t(f)]);
      if (size[std::size_t(r)] >= min_faces || isolated[std::size_t(r)])
        continue;
      candidates[kept++] = f;
      if (slot[std::size_t(r)] < 0) {
        slot[std::size_t(r)] = int(small_roots.size());
        small_roots.push_back(r);
      }
    }
    candidates.resize(kept);
    if (small_roots.empty())
      break;
    face_offset.assign(small_roots.size() + 1, 0);
    for (int f : candidates)
      ++face_offset[std::size_t(slot[std::size_t(find_root(parent, segment_of_face[std::size_t(f)]))]) + 1];
    for (std::size_t i = 0; i < small_roots.size(); ++i)
      face_offset[i + 1] += face_offset[i];
    faces.resize(candidates.size());
    {
      std::vector<int> cursor(face_offset.begin(), face_offset.end() - 1);
      for (int f : candidates)
        faces[std::size_t(cursor[std::size_t(slot[std::size_t(find_root(parent, segment_of_face[std::size_t(f)]))])]++)] = f;
    }
    std::vector<int> order(small_roots.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = int(i);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const int ra = small_roots[std::size_t(a)], rb = small_roots[std::size_t(b)];
      return size[std::size_t(ra)] != size[std::size_t(rb)] ? size[std::size_t(ra)] < size[std::size_t(rb)] : ra < rb;
    });

    bool merged = false;
    for (int i : order) {
      const int r = small_roots[std::size_t(i)];
      if (parent[std::size_t(r)] != r || size[std::size_t(r)] >= min_faces)
        continue; // absorbed by, or grown through, an earlier merge of this round
      touched.clear();
      for (int j = face_offset[std::size_t(i)]; j < face_offset[std::size_t(i) + 1]; ++j) {
        const int f = faces[std::size_t(j)];
        for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
          const int g = adj.neighbour[std::size_t(k)];
          const int sg = segment_of_face[std::size_t(g)];
          if (sg < 0)
            continue;
          const int s = find_root(parent, sg);
          if (s == r)
            continue;
          if (border_edges[std::size_t(s)] == 0)
            touched.push_back(s);
          border[std::size_t(s)] += shared_edge_length(m, fv, f, g);
          ++border_edges[std::size_t(s)];
        }
      }
      int best = -1;
      for (int s : touched) {
        if (best < 0 || border[std::size_t(s)] > border[std::size_t(best)] ||
            (border[std::size_t(s)] == border[std::size_t(best)] &&
             border_edges[std::size_t(s)] > border_edges[std::size_t(best)]))
          best = s;
      }
      for (int s : touched) {
        border[std::size_t(s)] = 0.0;
        border_edges[std::size_t(s)] = 0;
      }
      if (best < 0) {
        // Adjacency is symmetric, so a segment nobody borders now is a whole component: it stays.
        isolated[std::size_t(r)] = 1;
        continue;
      }
      parent[std::size_t(r)] = best;
      size[std::size_t(best)] += size[std::size_t(r)];
      merged = true;
    }
    for (int r : small_roots)
      slot[std::size_t(r)] = -1;
    if (!merged)
      break;
  }
  for (int& s : segment_of_face)
    if (s >= 0)
      s = find_root(parent, s);
}

} // namespace detail

template <class MeshType>
int segment_by_normal_angle(const MeshType& m, const FaceAdjacency& adj, const SegmentByNormalAngleParams& params,
                            std::vector<int>& segment_of_face, const Progress& progress = {})
{
  const int face_count = int(m.face.size());
  segment_of_face.assign(std::size_t(face_count), -1);
  if (adj.face_count() != face_count)
    return 0; // adjacency of another mesh: nothing sensible to do

  report_progress(progress, 0, "Smoothing face normals");
  const double crease = std::min(2.0 * params.angle_deg, 80.0);
  const std::vector<Eigen::Vector3d> normal =
      smooth_face_normals(m, adj, std::max(0, params.smoothing_iterations), crease);

  report_progress(progress, 30, "Growing segments");
  const double min_cos = std::cos(radians_from_degrees(params.angle_deg));
  std::vector<int> stack;
  int segment_count = 0;
  int visited = 0;
  for (int seed = 0; seed < face_count; ++seed) {
    if (m.face[std::size_t(seed)].IsD() || segment_of_face[std::size_t(seed)] >= 0)
      continue;
    const int id = segment_count++;
    segment_of_face[std::size_t(seed)] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      if ((++visited & 0xFFFF) == 0)
        report_progress(progress, 30 + int(40.0 * visited / face_count), "Growing segments");
      const Eigen::Vector3d& nf = normal[std::size_t(f)];
      if (nf.isZero(0.0))
        continue;
      for (int k = adj.offset[std::size_t(f)]; k < adj.offset[std::size_t(f) + 1]; ++k) {
        const int g = adj.neighbour[std::size_t(k)];
        if (segment_of_face[std::size_t(g)] >= 0)
          continue;
        const Eigen::Vector3d& ng = normal[std::size_t(g)];
        // Comparing the dot product with cos(angle) needs no acos; zero normals give 0 and never pass
        // for angles below 90 degrees, and are excluded explicitly above that.
        if (nf.dot(ng) > min_cos && !ng.isZero(0.0)) {
          segment_of_face[std::size_t(g)] = id;
          stack.push_back(g);
        }
      }
    }
  }

  if (params.min_segment_faces > 1 && segment_count > 1) {
    report_progress(progress, 70, "Absorbing small segments");
    detail::absorb_small_segments(m, adj, params.min_segment_faces, segment_of_face, segment_count);
  }
  const int K = compact_segment_ids(segment_of_face);
  report_progress(progress, 100, "Segmentation done");
  return K;
}

template <class MeshType>
int segment_by_normal_angle(const MeshType& m, const SegmentByNormalAngleParams& params,
                            std::vector<int>& segment_of_face, const Progress& progress = {})
{
  report_progress(progress, 0, "Building face adjacency");
  const FaceAdjacency adj = build_face_adjacency(m);
  return segment_by_normal_angle(m, adj, params, segment_of_face, progress);
}

} // namespace primitive_edit

#endif
